// See RgbaImage.h. sRGB curves after IEC 61966-2-1; bilinear filtering as OpenGL's
// GL_LINEAR with GL_REPEAT (texel centres at half-integers).
#include "pipeline/scene/RgbaImage.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace hlod {

RgbaImage::RgbaImage(int w, int h, glm::u8vec4 fill) : width(w), height(h) {
    pixels.resize(static_cast<std::size_t>(std::max(w, 0)) * std::max(h, 0) * 4);
    for (std::size_t i = 0; i < pixels.size(); i += 4) {
        pixels[i] = fill.r;
        pixels[i + 1] = fill.g;
        pixels[i + 2] = fill.b;
        pixels[i + 3] = fill.a;
    }
}

bool RgbaImage::hasTranslucentTexels() const {
    for (std::size_t i = 3; i < pixels.size(); i += 4) {
        if (pixels[i] < 255) return true;
    }
    return false;
}

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

float linearToSrgb(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

namespace {

// Built before main (no guard on every lookup: texture sampling calls this per channel).
const std::array<float, 256> kSrgbToLinear = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i)
        t[static_cast<std::size_t>(i)] = srgbToLinear(static_cast<float>(i) / 255.0f);
    return t;
}();

} // namespace

float srgbByteToLinear(std::uint8_t c) { return kSrgbToLinear[c]; }

namespace {

inline glm::vec4 linearTexel(const RgbaImage& image, int x, int y) {
    const std::uint8_t* p = &image.pixels[(static_cast<std::size_t>(y) * image.width + x) * 4];
    return {kSrgbToLinear[p[0]], kSrgbToLinear[p[1]], kSrgbToLinear[p[2]],
            static_cast<float>(p[3]) * (1.0f / 255.0f)};
}

int wrap(int i, int n) {
    const int r = i % n;
    return r < 0 ? r + n : r;
}

} // namespace

glm::vec4 sampleBilinear(const RgbaImage& image, glm::vec2 uv) {
    if (image.empty()) return glm::vec4(1.0f);
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = glm::vec2(0.0f);
    // Keep the coordinate small before scaling so float precision does not degrade on
    // tiled textures with large uvs (TORCS track uvs reach several hundred).
    const float u = uv.x - std::floor(uv.x), v = uv.y - std::floor(uv.y);
    const float x = u * static_cast<float>(image.width) - 0.5f;
    const float y = v * static_cast<float>(image.height) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const float tx = x - fx, ty = y - fy;
    // fx lies in [-1, width - 1] here: the wrap's division only for what falls outside.
    auto wrapped = [](int i, int n) {
        return static_cast<unsigned>(i) < static_cast<unsigned>(n) ? i : wrap(i, n);
    };
    const int x0 = wrapped(static_cast<int>(fx), image.width),
              x1 = x0 + 1 < image.width ? x0 + 1 : 0;
    const int y0 = wrapped(static_cast<int>(fy), image.height),
              y1 = y0 + 1 < image.height ? y0 + 1 : 0;
    const glm::vec4 top = glm::mix(linearTexel(image, x0, y0), linearTexel(image, x1, y0), tx);
    const glm::vec4 bottom = glm::mix(linearTexel(image, x0, y1), linearTexel(image, x1, y1), tx);
    return glm::mix(top, bottom, ty);
}

glm::vec4 meanLinearColor(const RgbaImage& image) {
    if (image.empty()) return glm::vec4(1.0f);
    // Sum in double; sample every texel up to 4M, strided beyond (the mean barely moves).
    const std::size_t count = static_cast<std::size_t>(image.width) * image.height;
    const std::size_t stride = count > (1u << 22) ? count / (1u << 22) : 1;
    double sum[4] = {0, 0, 0, 0};
    std::size_t n = 0;
    for (std::size_t i = 0; i < count; i += stride, ++n) {
        const std::uint8_t* p = &image.pixels[i * 4];
        for (int c = 0; c < 3; ++c)
            sum[c] += srgbByteToLinear(p[c]);
        sum[3] += p[3] / 255.0;
    }
    return glm::vec4(static_cast<float>(sum[0] / n), static_cast<float>(sum[1] / n),
                     static_cast<float>(sum[2] / n), static_cast<float>(sum[3] / n));
}

} // namespace hlod
