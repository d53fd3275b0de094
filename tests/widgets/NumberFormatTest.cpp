// Numbers as people read them (widgets/NumberFormat.h, issue 20 #5): grouped counts, a short
// form for large ones, lengths and volumes with a unit between 1 and 1000, never an exponent.
#include <gtest/gtest.h>

#include <QLocale>

#include "widgets/NumberFormat.h"

namespace hlod::widgets {
namespace {

class NumberFormat : public ::testing::Test {
protected:
    void SetUp() override { QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates)); }
    void TearDown() override { QLocale::setDefault(QLocale::system()); }
};

TEST_F(NumberFormat, CountsAreGroupedAndLargeOnesShort) {
    EXPECT_EQ(formatCount(987), QStringLiteral("987"));
    EXPECT_EQ(formatCount(12345), QStringLiteral("12,345"));
    EXPECT_EQ(formatCount(123456), QStringLiteral("123 k"));
    EXPECT_EQ(formatCount(1234567), QStringLiteral("1.23 M"));
}

TEST_F(NumberFormat, VolumesTakeTheUnitThatKeepsThemReadable) {
    EXPECT_EQ(formatVolume(12345.6), QStringLiteral("12,346 m³"));
    EXPECT_EQ(formatVolume(1.5), QStringLiteral("1.5 m³"));
    EXPECT_EQ(formatVolume(0.0042), QStringLiteral("4.2 L"));
    EXPECT_EQ(formatVolume(3.5e-7), QStringLiteral("350 mm³")); // printed as 3.5e-07 before
    EXPECT_EQ(formatVolume(0.0), QStringLiteral("0 m³"));
}

TEST_F(NumberFormat, LengthsTakeTheUnitThatKeepsThemReadable) {
    EXPECT_EQ(formatLength(1234.0), QStringLiteral("1.23 km"));
    EXPECT_EQ(formatLength(80.25), QStringLiteral("80.3 m"));
    EXPECT_EQ(formatLength(0.12), QStringLiteral("12 cm"));
    EXPECT_EQ(formatLength(0.0008), QStringLiteral("0.8 mm"));
    EXPECT_EQ(formatMegabytes(3414000), QStringLiteral("3.41 MB"));
    EXPECT_EQ(formatMegabytes(812000000), QStringLiteral("812 MB"));
}

} // namespace
} // namespace hlod::widgets
