// Filtered texture lookups for the atlas bake: a texel of the atlas covers many texels of a
// finely tiled source texture (a race track's grass repeats every few metres, an atlas texel
// at a high node is metres wide), so sampling the source at one point would alias. Like a GPU,
// the lookup picks the mip level whose texels match the footprint and filters it bilinearly
// (GL_LINEAR_MIPMAP_NEAREST, OpenGL 4.6 section 8.14); the pyramid is built with a 2x2 box
// filter in linear space (odd sizes: the last row/column is folded into its neighbour) and
// stored as 8-bit sRGB.
//
// Thread-safe: a texture's pyramid is built once, on first use, under a per-texture lock;
// lookups are const afterwards. Deterministic: the pyramid is a pure function of the image.
// Ownership: images are borrowed from the scene and must outlive this object.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "pipeline/scene/RgbaImage.h"

namespace hlod {

// The levels of one texture: [0] is the image itself, then halves down to 1x1.
struct MipLevels {
    std::vector<const RgbaImage*> levels;
    // Linear RGBA at `uv` (repeat wrap) for a footprint of `footprint` texels of level 0
    // (<= 1: plain bilinear at level 0).
    glm::vec4 sample(glm::vec2 uv, float footprint) const;
};

class TextureMips {
public:
    // The pyramid of `image`, built on first use (look it up once, sample it many times: the
    // lookup takes a lock).
    MipLevels levelsOf(const RgbaImage& image);

    glm::vec4 sample(const RgbaImage& image, glm::vec2 uv, float footprint) {
        return levelsOf(image).sample(uv, footprint);
    }

private:
    struct Pyramid {
        std::once_flag built;
        std::vector<RgbaImage> levels; // levels[0] = level 1 (level 0 is the image itself)
    };
    Pyramid& pyramidOf(const RgbaImage& image);

    std::mutex mutex_;
    std::map<const RgbaImage*, std::unique_ptr<Pyramid>> pyramids_;
};

// The next level of a pyramid (exposed for tests): half the size, rounded down, at least 1.
RgbaImage downsample(const RgbaImage& image);

} // namespace hlod
