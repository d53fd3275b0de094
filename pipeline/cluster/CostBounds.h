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
// term keeps a set with a gap along one axis prunable.
#pragma once

#include <algorithm>
#include <cmath>

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

// The region of the single cluster u (box: its centre for the sphere model, its padded box for
// the box model).
Region regionOf(const CostModel& model, const ClusterUnit& u);

// Size class for MergeBvh: binary exponent of the radius (sphere) or of the cube root of the
// volume (box), so clusters within a class differ in size by less than 2x.
int sizeClass(const CostModel& model, const ClusterUnit& u);

// Lower bound of mergeCost(x, g) over every cluster g described by `region`.
double lowerBound(const CostModel& model, const ClusterUnit& x, const Region& region);

// Lower bound of the hull length of the interval [a, b] and an interval of length >= w that
// lies inside [lo, hi] (starting at some c in [lo, hi - w]): the hull max(b, c + w) - min(a, c)
// is at least b - a, w, (lo + w) - a and b - (hi - w). Branch-free: it runs in the inner loop
// of every search.
inline double minHullLength(double a, double b, double lo, double hi, double w) {
    return std::max(std::max(b - a, w), std::max(lo + w - a, b - hi + w));
}

// Lower bound of a box volume with per-axis extents of at least `e` and cross-sections of at
// least `area` (see the header): max over the axes of e_i * max(area_i, e_j e_k).
inline double minBoxVolume(const glm::dvec3& e, const glm::dvec3& area) {
    const double vx = e.x * std::max(area.x, e.y * e.z);
    const double vy = e.y * std::max(area.y, e.x * e.z);
    const double vz = e.z * std::max(area.z, e.x * e.y);
    return std::max(vx, std::max(vy, vz));
}

inline glm::dvec3 crossSections(const glm::dvec3& e) {
    return glm::dvec3(e.y * e.z, e.x * e.z, e.x * e.y);
}

// lowerBound for one cluster x against many regions, inline for the searches' inner loop.
// - Sphere: the centre distance is at least the distance from x's centre to the region's
//   centre box, every radius at least minRadius (see the header).
// - Box: per axis the merged box holds x's interval and g's, which is at least minExtent long
//   and lies inside the region (minHullLength); its cross-sections are at least x's and the
//   region's; its volume is also at least minVolume; the merged box lies in the hull of x and
//   the region, which bounds the shape ratio.
class BoundQuery {
public:
    BoundQuery(const CostModel& model, const ClusterUnit& x)
        : model_(model), x_(x), xArea_(crossSections(x.box.max - x.box.min)),
          sphere_(model.volume() == VolumeType::Sphere), hasShape_(model.k() != 0.0) {}

    double operator()(const Region& g) const {
        constexpr double kSafety = 1.0 - 1e-9;
        const double fvSum = x_.fv + g.maxFv;
        if (sphere_) {
            const glm::dvec3 c = x_.sphere.center;
            const glm::dvec3 q = glm::clamp(c, g.box.min, g.box.max) - c;
            const double d = std::sqrt(glm::dot(q, q));
            const double r = std::max(std::max(x_.sphere.radius, g.minRadius),
                                      (d + x_.sphere.radius + g.minRadius) * 0.5);
            const double r3 = r * r * r;
            return r3 * std::max(1.0, kSphereVolume * r3 / fvSum) * kSafety;
        }
        const glm::dvec3 e(
            minHullLength(x_.box.min.x, x_.box.max.x, g.box.min.x, g.box.max.x, g.minExtent.x),
            minHullLength(x_.box.min.y, x_.box.max.y, g.box.min.y, g.box.max.y, g.minExtent.y),
            minHullLength(x_.box.min.z, x_.box.max.z, g.box.min.z, g.box.max.z, g.minExtent.z));
        const double v = std::max(minBoxVolume(e, glm::max(xArea_, g.minArea)), g.minVolume);
        double bound = v * std::max(1.0, v / fvSum) * kSafety;
        if (hasShape_) {
            const glm::dvec3 ub = glm::max(x_.box.max, g.box.max) - glm::min(x_.box.min, g.box.min);
            const double shape =
                std::max(e.x, std::max(e.y, e.z)) / std::min(ub.x, std::min(ub.y, ub.z));
            bound *= model_.powK(std::max(1.0, shape));
        }
        return bound;
    }

private:
    static constexpr double kSphereVolume = 4.0 / 3.0 * 3.14159265358979323846;
    const CostModel& model_;
    const ClusterUnit& x_;
    glm::dvec3 xArea_;
    bool sphere_;
    bool hasShape_;
};

// Lower bound of mergeCost(x, g) over every x described by region `a` and g described by `b`
// (the spatial self-join of a level). Same argument as BoundQuery with x's exact bounds
// replaced by its region:
// - Sphere: centres inside boxes a distance d apart are at least d apart.
// - Box: per axis, intervals of lengths >= w_a in [a_lo, a_hi] and >= w_b in [b_lo, b_hi] have
//   a hull of at least max(w_a, w_b, b_lo - a_hi + w_a + w_b, a_lo - b_hi + w_a + w_b); the
//   cross-sections are at least the larger of the two regions' minima.
struct PairBound {
    double lhs;   // bound = lhs / den * kSafety
    double den;   // > 0
    double shape; // shape factor terms (box model with k != 0): maxExt and minUb
    double minUb;
};

[[gnu::always_inline]] inline PairBound pairBoundTerms(const CostModel& model, const Region& a,
                                                       const Region& b) {
    constexpr double kSphereVolume = 4.0 / 3.0 * 3.14159265358979323846;
    const double fvSum = a.maxFv + b.maxFv;
    const glm::dvec3 gap =
        glm::max(glm::max(a.box.min - b.box.max, b.box.min - a.box.max), glm::dvec3(0.0));
    if (model.volume() == VolumeType::Sphere) {
        const double d = std::sqrt(glm::dot(gap, gap));
        const double r =
            std::max(std::max(a.minRadius, b.minRadius), (d + a.minRadius + b.minRadius) * 0.5);
        const double r3 = r * r * r;
        // r3 * max(1, c r3 / fvSum) = r3 * max(fvSum, c r3) / fvSum
        return PairBound{r3 * std::max(fvSum, kSphereVolume * r3), fvSum, 1.0, 1.0};
    }
    const glm::dvec3 sum = a.minExtent + b.minExtent;
    const glm::dvec3 ext =
        glm::max(glm::max(a.minExtent, b.minExtent),
                 glm::max(b.box.min - a.box.max + sum, a.box.min - b.box.max + sum));
    const double v = std::max(minBoxVolume(ext, glm::max(a.minArea, b.minArea)),
                              std::max(a.minVolume, b.minVolume));
    PairBound out{v * std::max(fvSum, v), fvSum, 1.0, 1.0};
    if (model.k() != 0.0) {
        // shape = max(1, maxExt / minUb)
        const glm::dvec3 ub = glm::max(a.box.max, b.box.max) - glm::min(a.box.min, b.box.min);
        out.minUb = std::min(ub.x, std::min(ub.y, ub.z));
        out.shape = std::max(out.minUb, std::max(ext.x, std::max(ext.y, ext.z)));
    }
    return out;
}

// pairLowerBound(model, a, b) > threshold, without divisions (the self-join's inner loop).
[[gnu::always_inline]] inline bool pairBoundExceeds(const CostModel& model, const Region& a,
                                                    const Region& b, double threshold) {
    constexpr double kSafety = 1.0 - 1e-9;
    const PairBound t = pairBoundTerms(model, a, b);
    double lhs = t.lhs * kSafety;
    double rhs = threshold * t.den;
    if (model.k() != 0.0 && model.volume() == VolumeType::Aabb) {
        // Multiply through by minUb^k instead of dividing.
        lhs *= model.powK(t.shape);
        rhs *= model.powK(t.minUb);
    }
    return lhs > rhs;
}

inline double pairLowerBound(const CostModel& model, const Region& a, const Region& b) {
    constexpr double kSafety = 1.0 - 1e-9;
    const PairBound t = pairBoundTerms(model, a, b);
    double bound = t.lhs / t.den * kSafety;
    if (model.k() != 0.0 && model.volume() == VolumeType::Aabb) {
        bound *= model.powK(t.shape / t.minUb);
    }
    return bound;
}

} // namespace hlod
