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

// Issue 31 #6: one unit for every length, the scene's: no m/cm/km switching, so sizes and
// budgets of one scene read alike. Three significant digits, never an exponent.
TEST_F(NumberFormat, VolumesAreCubicSceneUnitsWithThreeDigits) {
    EXPECT_EQ(formatVolume(12345.6), QStringLiteral("12,346"));
    EXPECT_EQ(formatVolume(1.5), QStringLiteral("1.5"));
    EXPECT_EQ(formatVolume(0.0042), QStringLiteral("0.0042"));
    EXPECT_EQ(formatVolume(3.5e-7), QStringLiteral("0.00000035")); // printed as 3.5e-07 before
    EXPECT_EQ(formatVolume(0.0), QStringLiteral("0"));
}

TEST_F(NumberFormat, LengthsStayInSceneUnitsAndBytesInMegabytes) {
    EXPECT_EQ(formatLength(1234.0), QStringLiteral("1,234"));
    EXPECT_EQ(formatLength(80.25), QStringLiteral("80.3"));
    EXPECT_EQ(formatLength(0.12), QStringLiteral("0.12"));
    EXPECT_EQ(formatLength(0.12345), QStringLiteral("0.123"));
    EXPECT_EQ(formatLength(0.0008), QStringLiteral("0.0008"));
    EXPECT_EQ(lengthUnit(), QStringLiteral("scene units"));
    // MB = 10^6 bytes, the editor's one byte unit (Statistics, Compare, Export).
    EXPECT_EQ(formatMegabytes(3414000), QStringLiteral("3.41 MB"));
    EXPECT_EQ(formatMegabytes(812000000), QStringLiteral("812 MB"));
}

} // namespace
} // namespace hlod::widgets
