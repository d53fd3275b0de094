// A decoded 8-bit RGBA image and texture sampling as a glTF renderer does it.
//
// Layout: row-major, top row first (v = 0 at the top, as glTF texture coordinates), 4 bytes
// per texel. Colour channels hold the values as stored in the source file: for base colour
// textures that is sRGB-encoded colour (glTF 2.0 section 3.9.2); alpha is linear coverage.
// Sampling (sampleBilinear) follows glTF's default sampler: repeat wrap, bilinear filtering
// between texel centres, colour decoded to linear before filtering (as a GPU sampling an
// sRGB texture does).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace hlod {

struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels; // width * height * 4

    RgbaImage() = default;
    RgbaImage(int w, int h, glm::u8vec4 fill = glm::u8vec4(0));

    bool empty() const { return width <= 0 || height <= 0; }
    glm::u8vec4 at(int x, int y) const {
        const std::uint8_t* p = &pixels[(static_cast<std::size_t>(y) * width + x) * 4];
        return {p[0], p[1], p[2], p[3]};
    }
    void set(int x, int y, glm::u8vec4 c) {
        std::uint8_t* p = &pixels[(static_cast<std::size_t>(y) * width + x) * 4];
        p[0] = c.r;
        p[1] = c.g;
        p[2] = c.b;
        p[3] = c.a;
    }
    // True when some texel's alpha is below 255.
    bool hasTranslucentTexels() const;
};

// sRGB transfer functions (IEC 61966-2-1), per channel, in [0, 1].
float srgbToLinear(float c);
float linearToSrgb(float c);
// 8-bit sRGB value -> linear, from a table.
float srgbByteToLinear(std::uint8_t c);

// The linear RGBA value a renderer filters at `uv` (repeat wrap, bilinear). White for an
// empty image.
glm::vec4 sampleBilinear(const RgbaImage& image, glm::vec2 uv);

// Mean linear RGBA over all texels (sRGB decoded first, as a far-away renderer averages).
glm::vec4 meanLinearColor(const RgbaImage& image);

} // namespace hlod
