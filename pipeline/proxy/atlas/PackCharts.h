// Packs the charts of one proxy into one atlas image: every chart gets a rectangle of texels
// (its size in metres / texel size, rounded up, plus `padding` texels on each side for the
// dilated gutter), placed with stb_rect_pack's skyline packer (Jukka Jylanki, "A Thousand Ways
// to Pack the Bin", 2010: skyline bottom-left) in the smallest power-of-two atlas that holds
// them: a square of about 1.08 x their area, grown by 6 % until they fit, then cut to the rows
// used; sides are multiples of 4 (JPEG blocks, glTF 2.0 and WebGL 2 take any size; power-of-
// two sizes would waste up to 3/4 of the texels). When they do not fit `maxSize` x `maxSize`
// the texel size grows (by 15 % steps) until they do: the atlas is capped, the detail gives.
// Deterministic (the packer sorts with a total order on its input).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "pipeline/proxy/atlas/Charts.h"

namespace hlod {

struct ChartPlacement {
    glm::ivec2 offset{0}; // texel of the rectangle's top-left corner (padding included)
    glm::ivec2 size{0};   // texels, padding included
};

struct AtlasLayout {
    int width = 0, height = 0;
    float texelSize = 0.0f; // metres per texel actually used (>= the requested one)
    int padding = 0;
    std::vector<ChartPlacement> placements; // per chart
};

// `texelSize` > 0 metres; maxSize a multiple of 4, >= 16.
AtlasLayout packCharts(const std::vector<Chart>& charts, float texelSize, int maxSize,
                       int padding);

} // namespace hlod
