// The certificate of one edge collapse: how far the surface moves, both ways, when the faces
// around an edge are replaced by a fan around one new vertex.
//
// Based on: Cohen, Manocha & Olano, "Simplifying Polygonal Models Using Successive Mappings"
// (IEEE Visualization 1997). The faces around the edge (the ring, before) and the fan that
// replaces them (after) are projected along one direction n onto a plane; when both project
// one-to-one onto the same polygon, the vertical correspondence (a point of one surface and the
// point of the other above or below it) is a continuous bijection between them, and the
// distance between corresponding points is |f(x)| = |h_before(x) - h_after(x)| for x in the
// plane, linear on every cell of the overlay of the two triangulations (a face before clipped
// by a face after).
// Bounds per vertex: every vertex carries a bound b, and the bound of a point of a face is the
// interpolation of its corners' (barycentric). Invariant: every point of the surface lies
// within its bound of the original surface, and every original point mapped onto it (through
// the composition of all collapses' correspondences) within that bound of it. A collapse keeps
// it when, at every point x of the ring, bound_after(x) >= bound_before(x) + |f(x)|; the link's
// vertices keep their bounds, so this asks for a least bound at the new vertex, found at the
// corners of the overlay's cells (the left side is linear on a cell, the right side convex):
// the new vertex, the removed ones and the crossings of the edges at them.
// Starting from 0 on the original meshes, this certifies the two-sided Hausdorff distance of the
// simplified surface against the original from the faces around each edge alone: no spatial
// queries against the input at all.
// Direction n: the area-weighted normal of the faces before, else the mean of their unit
// normals. Refused (infinite bound): a ring with no such projection (a face before or after
// that turns away from n or stands on edge to it: a fold, a thin fin, a vertex of more than a
// half-space of directions), or one whose two triangulations do not cover the same polygon.
// Precision: double, coordinates relative to the new vertex; points within a relative 1e-9 of
// a face count as inside it.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace hlod {

// Corner number of the new vertex in CollapseRing::after.
inline constexpr std::uint32_t kNewVertex = 0xfffffffeu;

struct CollapseRing {
    std::span<const glm::vec3> positions; // of every vertex the faces name
    std::span<const float> vertexBounds;  // per vertex (empty: all 0)
    std::uint32_t from = 0, to = 0;       // the edge's ends; both go, the new vertex replaces them
    glm::vec3 fromAt{0.0f};               // where `from` stands before (its position, or its
                                          // position moved onto its border, see caller)
    double fromExtra = 0.0;               // added to `from`'s bound (that move's length)
    glm::vec3 at{0.0f};                   // the new vertex
    // Every face touching `from` or `to` before the collapse (those on the edge included), and
    // the faces that survive it with `from`/`to` replaced by kNewVertex, in any order.
    std::span<const std::array<std::uint32_t, 3>> before;
    std::span<const std::array<std::uint32_t, 3>> after;
};

// Reused between calls so a simplification allocates only while its rings grow.
struct MappingScratch {
    std::vector<std::uint32_t> ids; // ring vertices (local number = index)
    std::vector<glm::dvec3> plane;  // per local vertex: (x, y) in the plane, z = height
    std::vector<std::array<std::uint32_t, 3>> beforeLocal, afterLocal;
    std::vector<std::array<std::uint32_t, 2>> oldEdges; // spokes before (local vertices)
    std::vector<std::uint32_t> newEnds;                 // link ends of the spokes after
    glm::dvec3 direction{0.0}; // the projection direction of the last certified collapse
};

// The least bound the new vertex needs (metres), or infinity when the collapse cannot be
// certified (see header). Infinity as well as soon as the bound is known to exceed `giveUp`
// (callers that only compare it with a limit pass the limit: most collapses tried fail, and
// most of those show it at the first corners).
double collapseBound(const CollapseRing& ring, MappingScratch& scratch, double giveUp = INFINITY);

} // namespace hlod
