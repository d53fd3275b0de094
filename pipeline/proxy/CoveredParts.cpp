// Greedy removal of parts within the budget of the rest of the proxy, see CoveredParts.h.
#include "pipeline/proxy/CoveredParts.h"

#include <algorithm>
#include <numeric>

#include "pipeline/proxy/SurfaceQuery.h"

namespace hlod {

using namespace surface;

namespace {

// Triangles grouped by part (CSR): triangle numbers of `indices`, parts in order.
struct Grouped {
    std::vector<std::uint32_t> offsets, triangles;
};

Grouped groupByPart(std::span<const std::uint32_t> indices,
                    std::span<const std::uint32_t> partOfVertex, std::size_t partCount) {
    Grouped g;
    g.offsets.assign(partCount + 1, 0);
    const std::size_t n = indices.size() / 3;
    for (std::size_t t = 0; t < n; ++t)
        ++g.offsets[partOfVertex[indices[3 * t]] + 1];
    for (std::size_t p = 0; p < partCount; ++p)
        g.offsets[p + 1] += g.offsets[p];
    std::vector<std::uint32_t> fill(g.offsets.begin(), g.offsets.end() - 1);
    g.triangles.resize(n);
    for (std::size_t t = 0; t < n; ++t)
        g.triangles[fill[partOfVertex[indices[3 * t]]]++] = static_cast<std::uint32_t>(t);
    return g;
}

} // namespace

std::vector<std::uint8_t> keepUncoveredParts(std::span<const glm::vec3> positions,
                                             std::span<const std::uint32_t> input,
                                             std::span<const glm::vec3> simplifiedPositions,
                                             std::span<const std::uint32_t> simplified,
                                             std::span<const std::uint32_t> partOfVertex,
                                             std::size_t partCount, double limit) {
    std::vector<std::uint8_t> keep(partCount, 1);
    if (partCount < 2 || !(limit > 0.0)) return keep;
    const Grouped in = groupByPart(input, partOfVertex, partCount);
    const Grouped out = groupByPart(simplified, partOfVertex, partCount);
    std::vector<double> area(partCount, 0.0);
    for (std::size_t p = 0; p < partCount; ++p) {
        for (std::uint32_t k = in.offsets[p]; k < in.offsets[p + 1]; ++k) {
            const std::uint32_t* c = &input[3 * in.triangles[k]];
            area[p] += 0.5 * glm::length(glm::cross(glm::dvec3(positions[c[1]] - positions[c[0]]),
                                                    glm::dvec3(positions[c[2]] - positions[c[0]])));
        }
    }
    std::vector<std::uint32_t> order(partCount);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return area[a] > area[b]; });

    const auto l = static_cast<float>(limit);
    NearSurface kept;
    kept.reset(simplifiedPositions, simplified, l * (1.0f - kSlackFraction));
    std::vector<std::uint8_t> active(simplified.size() / 3, 0);
    kept.setActive(active.data());
    Coverage coverage(kept, l * kSlackFraction);
    bool any = false;
    glm::vec3 failAt;
    for (std::uint32_t p : order) {
        bool covered = any;
        for (std::uint32_t k = in.offsets[p]; covered && k < in.offsets[p + 1]; ++k) {
            const std::uint32_t* c = &input[3 * in.triangles[k]];
            covered = coverage.covers(positions[c[0]], positions[c[1]], positions[c[2]], {}, failAt);
        }
        if (covered) {
            keep[p] = 0;
            continue;
        }
        for (std::uint32_t k = out.offsets[p]; k < out.offsets[p + 1]; ++k)
            active[out.triangles[k]] = 1;
        any = any || out.offsets[p + 1] > out.offsets[p];
    }
    return keep;
}

} // namespace hlod
