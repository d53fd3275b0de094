// Which proxy triangle every atlas texel belongs to: the charts' triangles rasterised in
// atlas space, conservatively (a texel whose centre lies within `reach` texels outside a
// triangle is covered too, with its barycentrics clamped to the triangle), so bilinear
// filtering at chart borders reads sampled texels, not gutter.
// Overlaps (shared edges, the conservative margin) go to the triangle whose interior the
// texel centre lies deepest in (ties: lower triangle index): independent of the order the
// triangles are drawn in. Charts are rasterised in parallel (their rectangles are disjoint and
// the margin stays inside the padding).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace hlod {

struct TexelCoverage {
    int width = 0, height = 0;
    std::vector<std::int32_t> triangle; // per texel, -1 when uncovered
    std::vector<glm::vec3> bary;        // per texel, weights of the triangle's corners
};

// `cornerTexels`: per triangle corner, its position in texel units (x right, y down, texel
// centres at +0.5). `chartTriangles`: the triangles of each chart (rasterised chart by chart).
TexelCoverage rasterizeCharts(int width, int height, std::span<const glm::vec2> cornerTexels,
                              const std::vector<std::vector<std::uint32_t>>& chartTriangles,
                              float reach = 0.75f);

} // namespace hlod
