// Texture sampling as a glTF renderer does it: texel centres, repeat wrap, bilinear in linear
// space; sRGB curves at their defining points.
#include <gtest/gtest.h>

#include "pipeline/scene/RgbaImage.h"

using namespace hlod;

TEST(RgbaImage, SrgbCurvesHitTheirDefiningPoints) {
    EXPECT_FLOAT_EQ(srgbToLinear(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(srgbToLinear(1.0f), 1.0f);
    EXPECT_NEAR(srgbByteToLinear(188), 0.5029f, 1e-4f); // sRGB 188 is about linear 0.5
    EXPECT_NEAR(linearToSrgb(0.5f) * 255.0f, 187.5f, 0.5f);
}

TEST(RgbaImage, TexelCentresSampleExactlyAndEdgesWrap) {
    // 2x1: black, white. Texel centres at u = 0.25 and 0.75.
    RgbaImage image(2, 1, glm::u8vec4(0, 0, 0, 255));
    image.set(1, 0, glm::u8vec4(255, 255, 255, 255));
    EXPECT_FLOAT_EQ(sampleBilinear(image, {0.25f, 0.5f}).r, 0.0f);
    EXPECT_FLOAT_EQ(sampleBilinear(image, {0.75f, 0.5f}).r, 1.0f);
    // Half way between the centres: the mean in linear space.
    EXPECT_FLOAT_EQ(sampleBilinear(image, {0.5f, 0.5f}).r, 0.5f);
    // u = 0 lies between the last texel (wrapped) and the first: also half way.
    EXPECT_FLOAT_EQ(sampleBilinear(image, {0.0f, 0.5f}).r, 0.5f);
    // Repeat: u + 3 samples like u.
    EXPECT_FLOAT_EQ(sampleBilinear(image, {3.75f, 7.5f}).r, 1.0f);
    EXPECT_FLOAT_EQ(sampleBilinear(image, {-0.25f, 0.5f}).r, 1.0f);
}
