// UV charts of a proxy: its triangles segmented into connected groups of similar orientation,
// each flattened by an orthographic projection onto a plane.
//
// Based on: greedy region growing in the spirit of Sander et al., "Texture Mapping Progressive
// Meshes" (SIGGRAPH 2001) and Levy et al., "Least Squares Conformal Maps" (2002, its charting
// by normal deviation), simplified to planar projections, which suit proxies: simplified or
// remeshed shells made of large, mostly flat regions.
// Segmentation: seeds are taken in order of decreasing area (ties: lower index); a chart grows
// across shared edges to triangles whose normal is within `maxNormalDegrees` of the seed's and
// whose projection does not overlap the chart's triangles already placed (a 2D separating axis
// test on a grid), so a chart never maps two surface points to one texel.
// Flattening: projection onto the plane orthogonal to the seed normal, then rotated (in 5.625°
// steps over 90°) to the smallest bounding rectangle. Lengths stay metres, and the stretch is
// at most 1 / cos(maxNormalDegrees).
// Deterministic; O(n log n) in the triangle count. Degenerate triangles join a neighbour's chart
// (or form their own) with zero area.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace hlod {

struct Chart {
    std::vector<std::uint32_t> triangles;
    glm::vec2 size{0.0f}; // bounding rectangle of the flattened triangles, metres
};

struct Charting {
    std::vector<Chart> charts;
    std::vector<std::uint32_t> chartOf;  // per triangle
    std::vector<glm::vec2> cornerCoords; // per triangle corner (3 per triangle), metres, in
                                         // [0, size] of the triangle's chart
};

Charting buildCharts(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                     float maxNormalDegrees = 50.0f);

} // namespace hlod
