// Conservative triangle rasterisation with edge functions (Pineda 1988), see
// RasterizeCharts.h.
#include "pipeline/proxy/atlas/RasterizeCharts.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>

namespace hlod {

namespace {

// A triangle's edge functions, normalised so they give signed distances in texels (> 0
// inside) and, divided by the area, barycentric weights.
struct EdgeSetup {
    glm::vec2 v[3];
    glm::vec2 normal[3]; // inward unit normal of the edge opposite corner k
    float offset[3];
    float weightScale[3]; // edge distance -> barycentric weight of corner k
    bool valid = false;

    EdgeSetup(const glm::vec2& a, const glm::vec2& b, const glm::vec2& c) : v{a, b, c} {
        const float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if (!(std::abs(area) > 1e-12f)) return;
        const float sign = area > 0.0f ? 1.0f : -1.0f;
        for (int e = 0; e < 3; ++e) {
            const glm::vec2 p0 = v[(e + 1) % 3], p1 = v[(e + 2) % 3];
            const glm::vec2 d = p1 - p0;
            const float len = glm::length(d);
            if (!(len > 0.0f)) return;
            normal[e] = sign * glm::vec2(-d.y, d.x) / len;
            offset[e] = -glm::dot(normal[e], p0);
            weightScale[e] = len / std::abs(area); // distance * |edge| / (2 area / 2)
        }
        valid = true;
    }

    // Signed distance of `p` inside (> 0), with the distances to the three edges in `d`.
    float depth(const glm::vec2& p, float (&d)[3]) const {
        for (int e = 0; e < 3; ++e)
            d[e] = glm::dot(normal[e], p) + offset[e];
        return std::min({d[0], d[1], d[2]});
    }

    // The barycentrics of the point at edge distances `d`, clamped to the triangle.
    glm::vec3 bary(const float (&d)[3]) const {
        const glm::vec3 w =
            glm::max(glm::vec3(d[0] * weightScale[0], d[1] * weightScale[1], d[2] * weightScale[2]),
                     glm::vec3(0.0f));
        const float sum = w.x + w.y + w.z;
        return sum > 0.0f ? w / sum : glm::vec3(1.0f / 3.0f);
    }
};

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
            const EdgeSetup edges(a, b, c);
            if (!edges.valid) continue;
            const glm::vec2 lo = glm::min(glm::min(a, b), c) - reach;
            const glm::vec2 hi = glm::max(glm::max(a, b), c) + reach;
            const int x0 = std::max(0, static_cast<int>(std::floor(lo.x)));
            const int y0 = std::max(0, static_cast<int>(std::floor(lo.y)));
            const int x1 = std::min(width - 1, static_cast<int>(std::floor(hi.x)));
            const int y1 = std::min(height - 1, static_cast<int>(std::floor(hi.y)));
            for (int y = y0; y <= y1; ++y) {
                for (int x = x0; x <= x1; ++x) {
                    float distances[3];
                    const float d = edges.depth({x + 0.5f, y + 0.5f}, distances);
                    if (d < -reach) continue;
                    const std::size_t i = static_cast<std::size_t>(y) * width + x;
                    const auto ti = static_cast<std::int32_t>(t);
                    if (d > best[i] || (d == best[i] && ti < out.triangle[i])) {
                        best[i] = d;
                        out.triangle[i] = ti;
                        out.bary[i] = edges.bary(distances); // only for the texels it takes
                    }
                }
            }
        }
    });
    return out;
}

} // namespace hlod
