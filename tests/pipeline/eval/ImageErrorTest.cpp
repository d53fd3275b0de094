// Image error metrics of `hlod bench` (ImageError.h): the cap, a hand-computed PSNR, the
// differing-pixel threshold, and size checks.
#include <gtest/gtest.h>

#include <cmath>

#include "pipeline/core/Error.h"
#include "pipeline/eval/ImageError.h"

using namespace hlod;

TEST(ImageError, IdenticalImagesGiveTheCap) {
    RgbImage a(64, 32, Rgb(10, 200, 30));
    const ImageError e = compareImages(a, a);
    EXPECT_EQ(e.mse, 0.0);
    EXPECT_EQ(e.psnrDb, kPsnrCapDb);
    EXPECT_EQ(e.diffPixels, 0u);
    EXPECT_EQ(e.diffShare, 0.0);
}

TEST(ImageError, KnownDifferenceGivesHandComputedPsnr) {
    // 10x10 image, one pixel differs by 30 levels in every channel (> threshold 8), another by
    // 5 levels in red only (<= threshold). Sum of squares = 3*900 + 25 = 2725 over 300 values:
    // MSE = 9.0833..., PSNR = 10 log10(65025 / 9.0833) = 38.548 dB.
    RgbImage a(10, 10, Rgb(100));
    RgbImage b = a;
    b.set(3, 4, Rgb(130));
    b.set(7, 1, Rgb(105, 100, 100));
    const ImageError e = compareImages(a, b);
    EXPECT_NEAR(e.mse, 2725.0 / 300.0, 1e-12);
    EXPECT_NEAR(e.psnrDb, 10.0 * std::log10(65025.0 / (2725.0 / 300.0)), 1e-9);
    EXPECT_NEAR(e.psnrDb, 38.548, 1e-3);
    EXPECT_EQ(e.diffPixels, 1u);
    EXPECT_DOUBLE_EQ(e.diffShare, 0.01);
}

TEST(ImageError, BlackVersusWhiteIsZeroDb) {
    const ImageError e = compareImages(RgbImage(8, 8, Rgb(0)), RgbImage(8, 8, Rgb(255)));
    EXPECT_NEAR(e.psnrDb, 0.0, 1e-12);
    EXPECT_EQ(e.diffShare, 1.0);
}

TEST(ImageError, TinyDifferenceInABigImageIsCapped) {
    RgbImage a(640, 360, Rgb(50));
    RgbImage b = a;
    b.set(0, 0, Rgb(51, 50, 50)); // 106.5 dB uncapped
    EXPECT_EQ(compareImages(a, b).psnrDb, kPsnrCapDb);
    EXPECT_EQ(psnrFromMse(0.0), kPsnrCapDb);
}

TEST(ImageError, SizeMismatchThrows) {
    EXPECT_THROW(compareImages(RgbImage(4, 4), RgbImage(4, 5)), Error);
    EXPECT_THROW(compareImages(RgbImage(), RgbImage()), Error);
}
