// A bounding volume hierarchy over the source triangles of an atlas bake, answering the two
// queries the texel sampler needs: every triangle a line segment crosses (the cast along the
// proxy normal, both ways) and the closest surface point (the fallback).
//
// Based on: binary BVH split on the longest centroid axis by the binned surface area heuristic
// (Wald, "On fast construction of SAH-based bounding volume hierarchies", 2007), median split
// when no bin separates, ray-triangle test of Moeller & Trumbore (1997), ray-box slab
// test (Kay & Kajiya 1986), closest point on a triangle after Ericson, "Real-Time Collision
// Detection" (2005) 5.1.5, nearest-point traversal pruned by the squared box distance.
// Contracts: positions and indices are borrowed (must outlive the BVH); degenerate triangles
// are never hit by segments but may be closest points. Results do not depend on thread count
// or call order (queries are const and visit nodes in a fixed order; ties go to the lower
// triangle index).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace hlod {

struct SegmentHit {
    std::uint32_t triangle = 0;
    float t = 0.0f;      // along the segment, from its start, in units of `dir`
    glm::vec2 bary{0.f}; // weights of corners 1 and 2 (corner 0 gets 1 - u - v)
};

struct ClosestPoint {
    std::uint32_t triangle = 0xffffffffu; // none when the BVH is empty
    float distanceSquared = 0.0f;
    glm::vec3 bary{0.0f}; // weights of corners 0, 1, 2
};

class SurfaceBvh {
public:
    SurfaceBvh(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices);

    // Calls `visit(const SegmentHit&)` for every triangle crossed by origin + t * dir,
    // t in [tMin, tMax].
    template <class Visit>
    void forEachHit(const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax,
                    Visit&& visit) const;

    // The closest surface point within sqrt(maxDistanceSquared) of `p` (none beyond it).
    ClosestPoint closest(const glm::vec3& p,
                         float maxDistanceSquared = std::numeric_limits<float>::infinity()) const;

    bool empty() const { return nodes_.empty(); }

private:
    struct Node {
        glm::vec3 lo, hi;
        std::uint32_t first = 0; // leaf: first index into order_; inner: right child
        std::uint32_t count = 0; // leaf: triangle count; inner: 0 (left child = this + 1)
    };
    std::uint32_t build(std::uint32_t begin, std::uint32_t end,
                        const std::vector<glm::vec3>& centroids, int depth);
    std::uint32_t sahSplit(std::uint32_t begin, std::uint32_t end,
                           const std::vector<glm::vec3>& centroids, int axis, float lo,
                           float extent);
    glm::vec3 corner(std::uint32_t tri, int k) const { return positions_[indices_[3 * tri + k]]; }

    static bool segmentHitsBox(const glm::vec3& o, const glm::vec3& invDir, float tMin, float tMax,
                               const Node& node);
    bool hitTriangle(std::uint32_t i, const glm::vec3& origin, const glm::vec3& dir, float tMin,
                     float tMax, SegmentHit& hit) const;

    // A triangle as the segment test reads it: first corner and the edges to the other two.
    struct Edges {
        glm::vec3 a, e1, e2;
    };

    std::span<const glm::vec3> positions_;
    std::span<const std::uint32_t> indices_;
    std::vector<std::uint32_t> order_; // triangle ids, leaves reference ranges
    std::vector<Edges> edges_;         // parallel to order_ (leaves read them in order)
    std::vector<Node> nodes_;
};

// Inline: forEachHit calls them per node and per leaf triangle.
inline bool SurfaceBvh::segmentHitsBox(const glm::vec3& o, const glm::vec3& invDir, float tMin,
                                       float tMax, const Node& node) {
    // All three slabs, then one test: tMin only grows and tMax only shrinks, so the answer is
    // the one of stopping at the first empty slab. NaN (0 * inf on a slab plane) never enters
    // the bounds, as comparisons with NaN are false.
    for (int a = 0; a < 3; ++a) {
        const float t0 = (node.lo[a] - o[a]) * invDir[a];
        const float t1 = (node.hi[a] - o[a]) * invDir[a];
        const bool swapped = t0 > t1;
        const float tNear = swapped ? t1 : t0, tFar = swapped ? t0 : t1;
        tMin = tNear > tMin ? tNear : tMin;
        tMax = tFar < tMax ? tFar : tMax;
    }
    return !(tMin > tMax);
}

inline bool SurfaceBvh::hitTriangle(std::uint32_t i, const glm::vec3& origin, const glm::vec3& dir,
                                    float tMin, float tMax, SegmentHit& hit) const {
    // Moeller-Trumbore, both faces.
    const Edges& tri = edges_[i];
    const glm::vec3 pv = glm::cross(dir, tri.e2);
    const float det = glm::dot(tri.e1, pv);
    if (!(std::abs(det) > 1e-20f)) return false;
    const float inv = 1.0f / det;
    const glm::vec3 tv = origin - tri.a;
    const float u = glm::dot(tv, pv) * inv;
    if (u < 0.0f || u > 1.0f) return false;
    const glm::vec3 qv = glm::cross(tv, tri.e1);
    const float v = glm::dot(dir, qv) * inv;
    if (v < 0.0f || u + v > 1.0f) return false;
    const float hitT = glm::dot(tri.e2, qv) * inv;
    if (hitT < tMin || hitT > tMax) return false;
    hit = SegmentHit{order_[i], hitT, {u, v}};
    return true;
}

template <class Visit>
void SurfaceBvh::forEachHit(const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax,
                            Visit&& visit) const {
    if (nodes_.empty()) return;
    const glm::vec3 invDir(1.0f / dir.x, 1.0f / dir.y, 1.0f / dir.z);
    std::uint32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const std::uint32_t id = stack[--top];
        const Node& node = nodes_[id];
        if (!segmentHitsBox(origin, invDir, tMin, tMax, node)) continue;
        if (node.count == 0) {
            if (top + 2 > 128) continue; // cannot happen at depth <= 60
            stack[top++] = node.first;
            stack[top++] = id + 1;
            continue;
        }
        SegmentHit hit;
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
            if (hitTriangle(i, origin, dir, tMin, tMax, hit)) visit(hit);
    }
}

} // namespace hlod
