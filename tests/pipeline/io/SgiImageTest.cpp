// SGI images (TORCS's .rgb textures): hand-written 4x4 files, verbatim and RLE, whose texels
// follow from the bytes written; corrupt files are refused with a reason, never a crash.
#include <gtest/gtest.h>

#include "SgiTestFiles.h"
#include "TestUtil.h"
#include "pipeline/io/ImageDecode.h"
#include "pipeline/io/SgiImage.h"

using namespace hlod;
using hlod::test::sgiHeader;
using hlod::test::sgiRle;

TEST(SgiImage, VerbatimRgbPlanesAreReadBottomRowFirst) {
    // 4x4, 3 channels, verbatim: red plane = 10 * row + column, green = 100, blue = 200 + row.
    std::vector<std::uint8_t> b = sgiHeader(0, 4, 4, 3);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            b.push_back(static_cast<std::uint8_t>(10 * y + x));
    b.insert(b.end(), 16, 100);
    for (int y = 0; y < 4; ++y)
        b.insert(b.end(), 4, static_cast<std::uint8_t>(200 + y));
    std::string why;
    const auto image = decodeSgi(b, why);
    ASSERT_TRUE(image) << why;
    EXPECT_EQ(image->width, 4);
    EXPECT_EQ(image->height, 4);
    // The file's row 0 is the bottom: it becomes the output's last row (top row first).
    EXPECT_EQ(image->at(0, 3), glm::u8vec4(0, 100, 200, 255));
    EXPECT_EQ(image->at(2, 0), glm::u8vec4(32, 100, 203, 255));
    EXPECT_EQ(image->at(3, 1), glm::u8vec4(23, 100, 202, 255));
}

TEST(SgiImage, RleRgbaRowsDecodeLiteralAndRepeatRuns) {
    // 4x4, 4 channels. Every row of every channel: a repeat run of 2 (value c*50 + y) and a
    // literal run of 2 (values 7, 9), then the terminating 0.
    std::vector<std::vector<std::vector<std::uint8_t>>> rows(4);
    for (int c = 0; c < 4; ++c)
        for (int y = 0; y < 4; ++y)
            rows[c].push_back({0x02, static_cast<std::uint8_t>(c * 50 + y), 0x82, 7, 9, 0x00});
    std::string why;
    const auto image = decodeSgi(sgiRle(4, 4, rows), why);
    ASSERT_TRUE(image) << why;
    // Top output row = file row 3: texels 0-1 repeat (3, 53, 103, 153), 2-3 are 7 and 9.
    EXPECT_EQ(image->at(0, 0), glm::u8vec4(3, 53, 103, 153));
    EXPECT_EQ(image->at(1, 0), glm::u8vec4(3, 53, 103, 153));
    EXPECT_EQ(image->at(2, 0), glm::u8vec4(7, 7, 7, 7));
    EXPECT_EQ(image->at(3, 3), glm::u8vec4(9, 9, 9, 9));
    EXPECT_EQ(image->at(0, 3), glm::u8vec4(0, 50, 100, 150));
    EXPECT_TRUE(image->hasTranslucentTexels());
}

TEST(SgiImage, OneChannelGreyIsReplicatedWithOpaqueAlpha) {
    std::vector<std::vector<std::vector<std::uint8_t>>> rows(1);
    for (int y = 0; y < 4; ++y)
        rows[0].push_back({0x04, static_cast<std::uint8_t>(60 * y), 0x00});
    std::string why;
    const auto image = decodeSgi(sgiRle(4, 4, rows), why);
    ASSERT_TRUE(image) << why;
    EXPECT_EQ(image->at(1, 0), glm::u8vec4(180, 180, 180, 255)); // file row 3
    EXPECT_EQ(image->at(2, 3), glm::u8vec4(0, 0, 0, 255));       // file row 0
}

TEST(SgiImage, RunPastTheRowEndIsRefusedWithItsRow) {
    std::vector<std::vector<std::vector<std::uint8_t>>> rows(1);
    for (int y = 0; y < 4; ++y)
        rows[0].push_back({0x04, 1, 0x00});
    rows[0][2] = {0x05, 1, 0x00}; // five texels in a row of four
    std::string why;
    EXPECT_FALSE(decodeSgi(sgiRle(4, 4, rows), why));
    EXPECT_EQ(why, "RLE row runs past its end (row 2 of channel 0)");
}

TEST(SgiImage, RowOffsetOutsideTheFileIsRefused) {
    std::vector<std::vector<std::vector<std::uint8_t>>> rows(1);
    for (int y = 0; y < 4; ++y)
        rows[0].push_back({0x04, 1, 0x00});
    std::vector<std::uint8_t> b = sgiRle(4, 4, rows);
    hlod::test::putBe32(b, 512, 1u << 30); // row 0 starts a gigabyte in
    std::string why;
    EXPECT_FALSE(decodeSgi(b, why));
    EXPECT_NE(why.find("RLE row outside the file"), std::string::npos) << why;
}

TEST(SgiImage, TruncatedVerbatimDataAndSixteenBitAreRefused) {
    std::vector<std::uint8_t> b = sgiHeader(0, 4, 4, 3);
    b.insert(b.end(), 20, 0); // 20 of 48 bytes
    std::string why;
    EXPECT_FALSE(decodeSgi(b, why));
    EXPECT_EQ(why, "verbatim SGI data truncated (20 of 48 bytes)");
    EXPECT_FALSE(decodeSgi(sgiHeader(0, 4, 4, 3, 2), why));
    EXPECT_EQ(why, "16-bit SGI images are not supported");
}

TEST(ImageDecode, CorruptTextureFileGivesAnErrorNamingTheFile) {
    hlod::test::TempDir dir;
    std::vector<std::uint8_t> b = sgiHeader(0, 4, 4, 3);
    const auto file = dir / "broken.rgb";
    hlod::test::writeFile(file, std::string(b.begin(), b.end()));
    const Texture t = loadTexture(file);
    EXPECT_EQ(t.image, nullptr);
    EXPECT_EQ(t.name, "broken.rgb");
    EXPECT_EQ(t.error, file.string() + ": verbatim SGI data truncated (0 of 48 bytes)");
    const Texture missing = loadTexture(dir / "nowhere.png");
    EXPECT_EQ(missing.error, (dir / "nowhere.png").string() + ": texture file missing or unreadable");
}
