// Lower bounds of the clustering cost (CostModel.h) over sets of clusters, for the spatial
// searches of level merging (MergeBvh.h, LevelMerger.cpp): branch and bound prunes a set whose
// bound exceeds the best (or budget) cost, so a bound must never exceed a real cost.
//
// Why the bounds hold: cost = V_AB^2 / fv_AB * shape (sphere: r^3 / F = r^3 V / fv) and the
// clamp of eq. 3.1 gives fv_AB <= min(V_AB, fv_x + fv_g), so
//     cost >= V_AB * max(1, V_AB / (fv_x + maxFv)) * shape,
// which increases with V_AB: a lower bound of V_AB (and of the shape factor) from what is known
// about the set gives a lower bound of the cost. The sets are described by a Region: a box
// (sphere model: the box of the cluster centres; box model: the box holding the clusters'
// boxes), the largest F*V, and the smallest radius, volume, per-axis extent and per-axis
// cross-section. Every bound is scaled by 1 - 1e-9, so rounding can never make it exceed a
// real cost (a tie with the best candidate must not be pruned: ties decide by id).
//
// Sphere: the smallest sphere enclosing balls A and B with centres d apart has radius
// max(r_A, r_B, (d + r_A + r_B) / 2) (containment included), so a lower bound of d (the
// distance between the centre boxes) and of the radii bounds it.
// Box: per axis the merged box is at least as long as both operands and as the gap between
// them plus their lengths; its cross-section across an axis is at least either operand's
// cross-section across that axis (the merged box holds both in the other two axes), so
// V_AB >= extent_axis * max(cross-section_A, cross-section_B, product of the other two
// extents). The per-axis minima of a set come from different members, so the product of the
// three minimum extents alone is weak for sets mixing flat and long parts; the cross-section
// term keeps a set with a gap along one axis prunable. For k > 0 the shape factor is bounded
// twice: on its own (largest extent over the hull's smallest) and coupled with the volume
// (shapeVolumeBound: the proportion is E_max^2 E_mid / V), which keeps two sets apart along
// one axis prunable when their hull is wide in every axis.
// Packed regions: the BVH stores regions in single precision rounded outward (PackedRegion).
// WideBounds.h evaluates these bounds for four packed regions at once; the scalar forms the
// tests check it against are in tests/pipeline/cluster/ScalarBounds.h.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "pipeline/cluster/CostModel.h"

namespace hlod {

// What a spatial search knows about a set of clusters (a BVH node, MergeBvh.h): lower bounds
// of their size and an upper bound of their F*V.
struct Region {
    Aabb box;           // sphere model: holds every centre; box model: every padded box
    double maxFv = 0.0; // largest F*V
    double minRadius = 0.0;
    double minVolume = 0.0;
    glm::dvec3 minExtent{0.0}; // smallest box extent per axis
    glm::dvec3 minArea{0.0};   // smallest box cross-section per axis (y z, x z, x y)
};

// A region that holds nothing (the identity of includeRegion).
Region emptyRegion();

// Makes `into` describe the clusters of `r` too.
inline void includeRegion(Region& into, const Region& r) {
    into.box.min = glm::min(into.box.min, r.box.min);
    into.box.max = glm::max(into.box.max, r.box.max);
    into.maxFv = std::max(into.maxFv, r.maxFv);
    into.minRadius = std::min(into.minRadius, r.minRadius);
    into.minVolume = std::min(into.minVolume, r.minVolume);
    into.minExtent = glm::min(into.minExtent, r.minExtent);
    into.minArea = glm::min(into.minArea, r.minArea);
}

// A Region in single precision, rounded outward (boxes and the largest F*V up, the smallest
// sizes down), so it describes a superset of what the exact region does and every bound below
// computed from it stays a valid lower bound, only a little looser (the BVH stores these,
// MergeBvh.h). `minSize` is the smallest radius (sphere model) or volume (box model); the
// per-axis minima live in a PackedExtra, read by the box model only.
struct PackedRegion {
    float lo[3];
    float hi[3];
    float maxFv;
    float minSize;
};
struct PackedExtra {
    float minExtent[3];
    float minArea[3];
};
// `r` packed as described at PackedRegion (`boxModel`: minSize is the volume and `extra` is
// written; else minSize is the radius).
void packRegion(const Region& r, bool boxModel, PackedRegion& out, PackedExtra& extra);

// The region of the single cluster u (box: its centre for the sphere model, its padded box for
// the box model).
Region regionOf(const CostModel& model, const ClusterUnit& u);

// Size class for MergeBvh: binary exponent of the radius (sphere) or of the cube root of the
// volume (box; the volume's exponent divided by three, rounded down, with no root taken), so
// clusters within a class differ in size by less than 2x.
int sizeClass(const CostModel& model, const ClusterUnit& u);

inline glm::dvec3 crossSections(const glm::dvec3& e) {
    return glm::dvec3(e.y * e.z, e.x * e.z, e.x * e.y);
}

// Shape and volume coupled (box model, 0 < k <= 2). With E_max >= E_mid >= E_min the merged
// box's extents, V = E_max E_mid E_min, so the proportion is E_max / E_min = P / V with
// P = E_max^2 E_mid, and
//     cost = V^2 / fv * (P / V)^k >= max(V^(1 - k), V^(2 - k) / fvSum) * P^k,
// using fv <= min(V, fvSum). For k <= 1 both terms grow with V, for 1 < k <= 2 only the
// second: lower bounds of V and of the sorted extents (each order statistic of the extents is
// at least that of their per-axis lower bounds) give a lower bound of the cost. Unlike the
// separate shape factor (largest extent over an upper bound of the smallest), it stays tight
// for the node pairs of a search: two small boxes far apart along one axis merge into a thin
// box whose cost this gives exactly, where the separate factor, bounded by the node's size,
// is near 1. 0 for other k (then only the separate bounds apply).
inline double shapeVolumeBound(double k, const glm::dvec3& e, double v, double fvSum) {
    const double hi = std::max(e.x, std::max(e.y, e.z));
    const double mid = std::max(std::min(e.x, e.y), std::min(std::max(e.x, e.y), e.z));
    const double p = hi * hi * mid;
    if (k == 1.0) return p * std::max(1.0, v / fvSum);
    if (k == 2.0) return p * p / fvSum;
    if (k > 0.0 && k < 1.0) {
        return std::max(std::pow(v, 1.0 - k), std::pow(v, 2.0 - k) / fvSum) * std::pow(p, k);
    }
    if (k > 1.0 && k < 2.0) return std::pow(v, 2.0 - k) / fvSum * std::pow(p, k);
    return 0.0;
}

} // namespace hlod
