// Trilinear filtering over a box-filtered pyramid, see TextureMips.h.
#include "pipeline/proxy/atlas/TextureMips.h"

#include <algorithm>
#include <cmath>

namespace hlod {

RgbaImage downsample(const RgbaImage& image) {
    const int w = std::max(1, image.width / 2), h = std::max(1, image.height / 2);
    RgbaImage out(w, h);
    for (int y = 0; y < h; ++y) {
        // Source rows of this texel: 2y, 2y+1, and the odd last row folded into the last texel.
        const int y0 = std::min(2 * y, image.height - 1);
        const int y1 = y == h - 1 ? image.height : std::min(2 * y + 2, image.height);
        for (int x = 0; x < w; ++x) {
            const int x0 = std::min(2 * x, image.width - 1);
            const int x1 = x == w - 1 ? image.width : std::min(2 * x + 2, image.width);
            glm::vec4 sum(0.0f);
            for (int sy = y0; sy < y1; ++sy) {
                for (int sx = x0; sx < x1; ++sx) {
                    const glm::u8vec4 c = image.at(sx, sy);
                    sum += glm::vec4(srgbByteToLinear(c.r), srgbByteToLinear(c.g),
                                     srgbByteToLinear(c.b), c.a / 255.0f);
                }
            }
            const float n = static_cast<float>((y1 - y0) * (x1 - x0));
            sum /= n;
            out.set(x, y,
                    glm::u8vec4(static_cast<std::uint8_t>(std::lround(linearToSrgb(sum.r) * 255.0f)),
                                static_cast<std::uint8_t>(std::lround(linearToSrgb(sum.g) * 255.0f)),
                                static_cast<std::uint8_t>(std::lround(linearToSrgb(sum.b) * 255.0f)),
                                static_cast<std::uint8_t>(std::lround(sum.a * 255.0f))));
        }
    }
    return out;
}

TextureMips::Pyramid& TextureMips::pyramidOf(const RgbaImage& image) {
    Pyramid* pyramid = nullptr;
    {
        const std::lock_guard lock(mutex_);
        auto& slot = pyramids_[&image];
        if (!slot) slot = std::make_unique<Pyramid>();
        pyramid = slot.get();
    }
    std::call_once(pyramid->built, [&] {
        const RgbaImage* previous = &image;
        while (previous->width > 1 || previous->height > 1) {
            pyramid->levels.push_back(downsample(*previous));
            previous = &pyramid->levels.back();
        }
    });
    return *pyramid;
}

MipLevels TextureMips::levelsOf(const RgbaImage& image) {
    MipLevels out;
    out.levels.push_back(&image);
    if (image.width <= 1 && image.height <= 1) return out;
    const Pyramid& pyramid = pyramidOf(image);
    for (const RgbaImage& level : pyramid.levels)
        out.levels.push_back(&level);
    return out;
}

glm::vec4 MipLevels::sample(glm::vec2 uv, float footprint) const {
    if (levels.empty() || levels[0]->empty()) return glm::vec4(1.0f);
    const int last = static_cast<int>(levels.size()) - 1;
    if (!(footprint > 1.0f) || last == 0) return sampleBilinear(*levels[0], uv);
    // The level whose texels match the footprint best (GL_LINEAR_MIPMAP_NEAREST): half the
    // cost of blending two, and the bake's texel already averages over its footprint.
    const float lod = std::min(std::log2(footprint), static_cast<float>(last));
    const auto level = static_cast<std::size_t>(std::lround(lod));
    return sampleBilinear(*levels[level], uv);
}

} // namespace hlod
