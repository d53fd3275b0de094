// A bounding volume hierarchy over the source triangles of an atlas bake, answering the two
// queries the texel sampler needs: every triangle a line segment crosses (the cast along the
// proxy normal, both ways) and the closest surface point (the fallback).
//
// Based on: binary BVH with median splits on the longest centroid axis (Wald, Boulos,
// Shirley 2007 for the layout), ray-triangle test of Moeller & Trumbore (1997), ray-box slab
// test (Kay & Kajiya 1986), closest point on a triangle after Ericson, "Real-Time Collision
// Detection" (2005) 5.1.5, nearest-point traversal pruned by the squared box distance.
// Contracts: positions and indices are borrowed (must outlive the BVH); degenerate triangles
// are never hit by segments but may be closest points. Results do not depend on thread count
// or call order (queries are const and visit nodes in a fixed order; ties go to the lower
// triangle index).
#pragma once

#include <cstdint>
#include <functional>
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

    // Calls `visit` for every triangle crossed by origin + t * dir, t in [tMin, tMax].
    void forEachHit(const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax,
                    const std::function<void(const SegmentHit&)>& visit) const;

    ClosestPoint closest(const glm::vec3& p) const;

    bool empty() const { return nodes_.empty(); }

private:
    struct Node {
        glm::vec3 lo, hi;
        std::uint32_t first = 0; // leaf: first index into order_; inner: right child
        std::uint32_t count = 0; // leaf: triangle count; inner: 0 (left child = this + 1)
    };
    std::uint32_t build(std::uint32_t begin, std::uint32_t end,
                        const std::vector<glm::vec3>& centroids, int depth);
    glm::vec3 corner(std::uint32_t tri, int k) const { return positions_[indices_[3 * tri + k]]; }

    std::span<const glm::vec3> positions_;
    std::span<const std::uint32_t> indices_;
    std::vector<std::uint32_t> order_; // triangle ids, leaves reference ranges
    std::vector<Node> nodes_;
};

} // namespace hlod
