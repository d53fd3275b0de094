// Conservative triangle rasterisation with edge functions (Pineda 1988), see
// RasterizeCharts.h.
#include "pipeline/proxy/atlas/RasterizeCharts.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>

namespace hlod {

namespace {

// Signed distance (texels) of `p` inside triangle abc (> 0 inside), and its barycentrics
// clamped to the triangle.
float depthInside(const glm::vec2& p, const glm::vec2& a, const glm::vec2& b, const glm::vec2& c,
                  glm::vec3& bary) {
    const float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (!(std::abs(area) > 1e-12f)) return -std::numeric_limits<float>::infinity();
    const float sign = area > 0.0f ? 1.0f : -1.0f;
    const glm::vec2 v[3] = {a, b, c};
    float depth = std::numeric_limits<float>::infinity();
    float w[3];
    for (int e = 0; e < 3; ++e) {
        const glm::vec2 p0 = v[(e + 1) % 3], p1 = v[(e + 2) % 3];
        const float cross = (p1.x - p0.x) * (p.y - p0.y) - (p1.y - p0.y) * (p.x - p0.x);
        w[e] = cross / area; // weight of corner e
        depth = std::min(depth, sign * cross / glm::length(p1 - p0));
    }
    bary = glm::max(glm::vec3(w[0], w[1], w[2]), glm::vec3(0.0f));
    const float sum = bary.x + bary.y + bary.z;
    bary = sum > 0.0f ? bary / sum : glm::vec3(1.0f / 3.0f);
    return depth;
}

} // namespace

TexelCoverage rasterizeCharts(int width, int height, std::span<const glm::vec2> cornerTexels,
                              const std::vector<std::vector<std::uint32_t>>& chartTriangles,
                              float reach) {
    TexelCoverage out;
    out.width = width;
    out.height = height;
    const std::size_t texels = static_cast<std::size_t>(width) * height;
    out.triangle.assign(texels, -1);
    out.bary.assign(texels, glm::vec3(0.0f));
    std::vector<float> best(texels, -std::numeric_limits<float>::infinity());
    tbb::parallel_for(std::size_t(0), chartTriangles.size(), [&](std::size_t chart) {
        for (std::uint32_t t : chartTriangles[chart]) {
            const glm::vec2 a = cornerTexels[3 * t], b = cornerTexels[3 * t + 1],
                            c = cornerTexels[3 * t + 2];
            const glm::vec2 lo = glm::min(glm::min(a, b), c) - reach;
            const glm::vec2 hi = glm::max(glm::max(a, b), c) + reach;
            const int x0 = std::max(0, static_cast<int>(std::floor(lo.x)));
            const int y0 = std::max(0, static_cast<int>(std::floor(lo.y)));
            const int x1 = std::min(width - 1, static_cast<int>(std::floor(hi.x)));
            const int y1 = std::min(height - 1, static_cast<int>(std::floor(hi.y)));
            for (int y = y0; y <= y1; ++y) {
                for (int x = x0; x <= x1; ++x) {
                    glm::vec3 bary;
                    const float d = depthInside({x + 0.5f, y + 0.5f}, a, b, c, bary);
                    if (d < -reach) continue;
                    const std::size_t i = static_cast<std::size_t>(y) * width + x;
                    const auto ti = static_cast<std::int32_t>(t);
                    if (d > best[i] || (d == best[i] && ti < out.triangle[i])) {
                        best[i] = d;
                        out.triangle[i] = ti;
                        out.bary[i] = bary;
                    }
                }
            }
        }
    });
    return out;
}

} // namespace hlod
