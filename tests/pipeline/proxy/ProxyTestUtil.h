// Helpers for the proxy tests: hand-built cluster trees over tiny scenes, and geometric
// measurements (point-triangle distance after Ericson, "Real-Time Collision Detection" 5.1.5).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/proxy/ProxyMesh.h"
#include "pipeline/scene/Scene.h"

namespace hlod::test {

// Builds a ClusterTree by hand: leaves for instances, inner nodes over ids already added.
// finish() sets parents, levels, boxes and bounding spheres (box centre, half diagonal).
class TreeBuilder {
public:
    explicit TreeBuilder(const Scene& scene) : scene_(scene) {}
    Id leaf(Id instance) {
        ClusterNode n;
        n.instance = instance;
        n.box = scene_.instanceBounds(instance);
        tree_.nodes.push_back(n);
        return static_cast<Id>(tree_.nodes.size() - 1);
    }
    Id inner(const std::vector<Id>& children) {
        ClusterNode n;
        n.children = children;
        for (Id c : children) {
            n.box.expand(tree_.nodes[c].box);
            n.level = std::max(n.level, tree_.nodes[c].level + 1);
        }
        tree_.nodes.push_back(n);
        const Id id = static_cast<Id>(tree_.nodes.size() - 1);
        for (Id c : children)
            tree_.nodes[c].parent = id;
        return id;
    }
    ClusterTree finish(Id root) {
        tree_.root = root;
        for (ClusterNode& n : tree_.nodes) {
            n.sphere.center = n.box.center();
            n.sphere.radius = n.box.diagonal() * 0.5;
        }
        return tree_;
    }

private:
    const Scene& scene_;
    ClusterTree tree_;
};

inline glm::dvec3 closestPointOnTriangle(const glm::dvec3& p, const glm::dvec3& a,
                                         const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    const double denom = 1.0 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

// Distance from a world point to a proxy's surface (brute force: small meshes only).
inline double distanceToMesh(const ProxyMesh& m, const glm::dvec3& world) {
    const glm::dvec3 p = world - m.origin;
    double best = 1e300;
    for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        const glm::dvec3 q = closestPointOnTriangle(p, glm::dvec3(m.positions[m.indices[t]]),
                                                    glm::dvec3(m.positions[m.indices[t + 1]]),
                                                    glm::dvec3(m.positions[m.indices[t + 2]]));
        best = std::min(best, glm::length(q - p));
    }
    return best;
}

// World-space points on a proxy's triangles: corners, edge midpoints and centroids.
inline std::vector<glm::dvec3> surfaceSamples(const ProxyMesh& m) {
    std::vector<glm::dvec3> out;
    for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        const glm::dvec3 a = m.origin + glm::dvec3(m.positions[m.indices[t]]);
        const glm::dvec3 b = m.origin + glm::dvec3(m.positions[m.indices[t + 1]]);
        const glm::dvec3 c = m.origin + glm::dvec3(m.positions[m.indices[t + 2]]);
        out.insert(out.end(), {a, (a + b) * 0.5, (b + c) * 0.5, (c + a) * 0.5, (a + b + c) / 3.0});
    }
    return out;
}

// Signed volume (positive when triangles face outward, counter-clockwise seen from outside).
inline double signedVolume(const ProxyMesh& m) {
    double v = 0.0;
    for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        const glm::dvec3 a(m.positions[m.indices[t]]), b(m.positions[m.indices[t + 1]]),
            c(m.positions[m.indices[t + 2]]);
        v += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return v;
}

// Edges (by welded position) used by other than exactly two triangles: 0 for a closed surface.
inline std::size_t openEdgeCount(const ProxyMesh& m) {
    auto key = [](const glm::vec3& p) { return std::make_tuple(p.x, p.y, p.z); };
    using K = decltype(key(glm::vec3()));
    std::map<std::pair<K, K>, int> edges;
    for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        for (int k = 0; k < 3; ++k) {
            K a = key(m.positions[m.indices[t + k]]),
              b = key(m.positions[m.indices[t + (k + 1) % 3]]);
            if (b < a) std::swap(a, b);
            ++edges[{a, b}];
        }
    }
    std::size_t open = 0;
    for (const auto& [e, count] : edges)
        open += count != 2 ? 1 : 0;
    return open;
}

struct Soup {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
};

// A 1.2 m x 1.2 m terrain of 12 x 12 cells, heights 0-5 cm from an integer hash (the same on
// every platform): rough at the scale of a 2-3 cm budget, so the simplifier's samples miss a
// few input triangles between them and the repair has work to do.
inline Soup roughTerrain(std::uint32_t seed) {
    constexpr int n = 12;
    Soup s;
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
            std::uint32_t h =
                seed * 0x9e3779b9u ^ static_cast<std::uint32_t>(i * 73856093 ^ j * 19349663);
            h ^= h >> 15, h *= 0x2c1b3c6du, h ^= h >> 12, h *= 0x297a2d39u, h ^= h >> 15;
            s.positions.emplace_back(i * 0.1f, j * 0.1f,
                                     0.05f * static_cast<float>(h % 1000) / 1000.0f);
        }
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        for (std::uint32_t j = 0; j < n; ++j) {
            const std::uint32_t a = i * (n + 1) + j, b = a + 1, c = a + n + 1, d = c + 1;
            s.indices.insert(s.indices.end(), {a, c, b, b, c, d});
        }
    }
    return s;
}

// Largest distance from points spread over every triangle of `from` (a 12 x 12 barycentric
// grid, corners and edges included) to the surface of `to`, brute force.
inline double sampledDistance(std::span<const glm::vec3> fromPositions,
                              std::span<const std::uint32_t> from,
                              std::span<const glm::vec3> toPositions,
                              std::span<const std::uint32_t> to) {
    constexpr int k = 12;
    double worst = 0.0;
    for (std::size_t t = 0; t + 2 < from.size(); t += 3) {
        const glm::dvec3 a(fromPositions[from[t]]), b(fromPositions[from[t + 1]]),
            c(fromPositions[from[t + 2]]);
        for (int i = 0; i <= k; ++i) {
            for (int j = 0; i + j <= k; ++j) {
                const glm::dvec3 p = a + (b - a) * (double(i) / k) + (c - a) * (double(j) / k);
                double best = 1e300;
                for (std::size_t u = 0; u + 2 < to.size(); u += 3) {
                    const glm::dvec3 q = closestPointOnTriangle(p, glm::dvec3(toPositions[to[u]]),
                                                                glm::dvec3(toPositions[to[u + 1]]),
                                                                glm::dvec3(toPositions[to[u + 2]]));
                    best = std::min(best, glm::length(q - p));
                }
                worst = std::max(worst, best);
            }
        }
    }
    return worst;
}

} // namespace hlod::test
