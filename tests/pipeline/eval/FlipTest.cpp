// LDR-FLIP (Flip.h) on small hand-made images. Expected values: closed forms where the
// images are uniform (no features, so FLIP is the redistributed colour difference), else the
// mean FLIP of NVIDIA's reference implementation (NVlabs/flip, src/cpp/FLIP.h at commit
// 1eb247c, LDR mode, the same images given as linear RGB of these 8-bit sRGB values), which
// agrees with ours to about 1e-5 (both are float; it sums its filters in another order).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "pipeline/core/Error.h"
#include "pipeline/eval/Flip.h"

using namespace hlod;

namespace {

// A 16x16 mid grey with a 4x4 white square at (6, 6) in the test image.
std::pair<RgbImage, RgbImage> whiteSquare() {
    RgbImage a(16, 16, Rgb(128));
    RgbImage b = a;
    b.fillRect(6, 6, 10, 10, Rgb(255));
    return {a, b};
}

// A 32x24 dark left half and light right half; the test image's edge is one pixel further right.
std::pair<RgbImage, RgbImage> edgeShift() {
    RgbImage a(32, 24, Rgb(40));
    RgbImage b = a;
    a.fillRect(16, 0, 32, 24, Rgb(220));
    b.fillRect(17, 0, 32, 24, Rgb(220));
    return {a, b};
}

// 64x48 pseudo-random colours (a 32-bit LCG, top byte), the test image continuing the sequence.
std::pair<RgbImage, RgbImage> noise() {
    RgbImage a(64, 48), b(64, 48);
    std::uint32_t s = 12345;
    auto next = [&] {
        s = s * 1664525u + 1013904223u;
        return static_cast<std::uint8_t>(s >> 24);
    };
    for (int y = 0; y < 48; ++y) {
        for (int x = 0; x < 64; ++x) {
            const std::uint8_t r = next(), g = next(), bl = next();
            a.set(x, y, Rgb(r, g, bl));
            const std::uint8_t r2 = next(), g2 = next(), b2 = next();
            b.set(x, y, Rgb(r2, g2, b2));
        }
    }
    return {a, b};
}

} // namespace

TEST(Flip, IdenticalImagesAreZeroEverywhere) {
    const auto [a, b] = noise();
    const FlipMap m = flipErrorMap(a, a, 5.44);
    EXPECT_EQ(m.mean, 0.0);
    EXPECT_EQ(m.max, 0.0f);
    ASSERT_EQ(m.values.size(), 64u * 48u);
}

TEST(Flip, UniformBlackAgainstWhiteIsTheRedistributedColourDifference) {
    // No edges or points in uniform images: FLIP = colour term. Black is L* = 0, white L* = 100
    // (a*, b* = 0 after the Hunt adjustment), HyAB = 100, 100^0.7 = 25.119. cmax = HyAB(green,
    // blue)^0.7 with the Hunt-adjusted green (87.74, -75.61, 72.98) and blue (32.30, 25.58,
    // -34.84): (55.44 + 147.85)^0.7 = 41.21; above pc cmax = 16.48 the value maps to
    // 0.95 + (25.119 - 16.48) / (41.21 - 16.48) x 0.05 = 0.9675. Reference: 0.9673797 (5.44 ppd).
    const FlipMap m = flipErrorMap(RgbImage(8, 8, Rgb(0)), RgbImage(8, 8, Rgb(255)), 5.44);
    EXPECT_NEAR(m.mean, 0.9673797, 2e-5);
    EXPECT_NEAR(m.mean, 0.9675, 5e-4);
    EXPECT_NEAR(m.max, m.mean, 1e-6); // the same everywhere
}

TEST(Flip, PureGreenAgainstPureBlueIsOne) {
    // cmax is defined by exactly this pair: the largest colour difference maps to 1.
    const double v = meanFlip(RgbImage(8, 8, Rgb(0, 255, 0)), RgbImage(8, 8, Rgb(0, 0, 255)), 10.0);
    EXPECT_NEAR(v, 1.0, 1e-6);
}

TEST(Flip, WhiteSquareMatchesTheReferenceImplementation) {
    const auto [a, b] = whiteSquare();
    EXPECT_NEAR(meanFlip(a, b, 5.44), 0.0584521, 2e-5);
    EXPECT_NEAR(meanFlip(a, b, 16.0), 0.0717088, 2e-5);
    // The square's own pixels differ most: the reference's maximum 0.9808407 at 5.44 ppd.
    EXPECT_NEAR(flipErrorMap(a, b, 5.44).max, 0.9808407, 2e-5);
    // A larger ppd spreads the blurred square over more pixels around it.
    EXPECT_NEAR(meanFlip(a, b, 67.0), 0.1450419, 1e-4);
}

TEST(Flip, OnePixelEdgeShiftMatchesTheReferenceImplementation) {
    const auto [a, b] = edgeShift();
    EXPECT_NEAR(meanFlip(a, b, 5.44), 0.0299007, 2e-5);
    EXPECT_NEAR(meanFlip(a, b, 16.0), 0.0417062, 2e-5);
}

TEST(Flip, NoiseMatchesTheReferenceImplementation) {
    const auto [a, b] = noise();
    EXPECT_NEAR(meanFlip(a, b, 5.44), 0.9172175, 2e-5);
    EXPECT_NEAR(meanFlip(a, b, 30.0), 0.7414309, 2e-5);
}

TEST(Flip, IsSymmetric) {
    // HyAB and the feature difference are symmetric in the two images.
    const auto [a, b] = whiteSquare();
    EXPECT_EQ(meanFlip(a, b, 5.44), meanFlip(b, a, 5.44));
}

TEST(Flip, PixelsPerDegreeFollowTheCamera) {
    // 360 px over 60 degrees seen from the centre of projection: 180 / tan(30°) = 311.77 px per
    // radian at the centre, x pi / 180 = 5.4414 px per degree.
    EXPECT_NEAR(flipPixelsPerDegree(360, 60.0 * 3.14159265358979 / 180.0), 5.4414, 1e-4);
    EXPECT_NEAR(flipPixelsPerDegree(1080, 60.0 * 3.14159265358979 / 180.0), 16.324, 1e-3);
}

TEST(Flip, RejectsMismatchedInput) {
    EXPECT_THROW(meanFlip(RgbImage(4, 4), RgbImage(4, 5), 5.0), Error);
    EXPECT_THROW(meanFlip(RgbImage(), RgbImage(), 5.0), Error);
    EXPECT_THROW(meanFlip(RgbImage(4, 4), RgbImage(4, 4), 0.0), Error);
    EXPECT_THROW(meanFlip(RgbImage(4, 4), RgbImage(4, 4), std::nan("")), Error);
}
