// Face and feature-edge quadrics (Garland & Heckbert 1997), see Quadric.h.
#include "pipeline/proxy/Quadric.h"

#include <algorithm>
#include <tuple>

namespace hlod {

namespace {

constexpr double kFeatureWeight = 10.0;
constexpr double kFoldCosine = -0.766; // 140 degrees

// One triangle corner's edge, stored from its smaller to its larger vertex.
struct HalfEdge {
    std::uint32_t lo, hi, tri;
    bool forward; // the triangle runs lo -> hi
};

glm::dvec3 triNormal(std::span<const glm::vec3> pos, std::span<const std::uint32_t> idx,
                     std::uint32_t t) {
    const glm::dvec3 a(pos[idx[3 * t]]), b(pos[idx[3 * t + 1]]), c(pos[idx[3 * t + 2]]);
    return glm::cross(b - a, c - a);
}

} // namespace

bool Quadric::minimum(glm::dvec3& p) const {
    const glm::dmat3 a(a00, a01, a02, a01, a11, a12, a02, a12, a22);
    const double det = glm::determinant(a);
    const double scale = a00 * a11 * a22;
    if (!(std::abs(det) > 1e-6 * std::abs(scale)) || !(scale != 0.0)) return false;
    p = glm::inverse(a) * glm::dvec3(-b0, -b1, -b2);
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

void addQuadrics(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                 std::vector<Quadric>& out) {
    const std::size_t faces = indices.size() / 3;
    for (std::size_t t = 0; t < faces; ++t) {
        const glm::dvec3 n = triNormal(positions, indices, static_cast<std::uint32_t>(t));
        const double len = glm::length(n);
        if (!(len > 0.0)) continue;
        const glm::dvec3 unit = n / len;
        const double d = -glm::dot(unit, glm::dvec3(positions[indices[3 * t]]));
        for (int k = 0; k < 3; ++k)
            out[indices[3 * t + k]].addPlane(unit, d, std::sqrt(0.5 * len));
    }
    std::vector<HalfEdge> edges;
    edges.reserve(indices.size());
    for (std::size_t t = 0; t < faces; ++t) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = indices[3 * t + k], b = indices[3 * t + (k + 1) % 3];
            edges.push_back(
                HalfEdge{std::min(a, b), std::max(a, b), static_cast<std::uint32_t>(t), a < b});
        }
    }
    std::sort(edges.begin(), edges.end(), [](const HalfEdge& x, const HalfEdge& y) {
        return std::tie(x.lo, x.hi, x.tri, x.forward) < std::tie(y.lo, y.hi, y.tri, y.forward);
    });
    for (std::size_t first = 0; first < edges.size();) {
        std::size_t last = first + 1;
        while (last < edges.size() && edges[last].lo == edges[first].lo &&
               edges[last].hi == edges[first].hi)
            ++last;
        bool feature = last - first != 2;
        if (!feature) {
            const HalfEdge &e0 = edges[first], &e1 = edges[first + 1];
            const glm::dvec3 n0 = triNormal(positions, indices, e0.tri),
                             n1 = triNormal(positions, indices, e1.tri);
            const double l0 = glm::length(n0), l1 = glm::length(n1);
            feature = e0.forward == e1.forward ||
                      (l0 > 0.0 && l1 > 0.0 && glm::dot(n0, n1) < kFoldCosine * l0 * l1);
        }
        if (feature) {
            const std::uint32_t a = edges[first].lo, b = edges[first].hi;
            const glm::dvec3 e = glm::dvec3(positions[b]) - glm::dvec3(positions[a]);
            const double len = glm::length(e);
            for (std::size_t i = first; len > 0.0 && i < last; ++i) {
                const glm::dvec3 n = glm::cross(e, triNormal(positions, indices, edges[i].tri));
                const double nl = glm::length(n);
                if (!(nl > 0.0)) continue;
                const glm::dvec3 unit = n / nl;
                const double d = -glm::dot(unit, glm::dvec3(positions[a]));
                out[a].addPlane(unit, d, kFeatureWeight * len);
                out[b].addPlane(unit, d, kFeatureWeight * len);
            }
        }
        first = last;
    }
}

} // namespace hlod
