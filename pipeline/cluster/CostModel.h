// The clustering cost of thesis sections 3.2.3 and 4.1-4.2: how two clusters merge, the fill
// factor of the result and what the merge costs.
//
// Sphere (Sappa & Garcia 2004, thesis algorithm 2 and eq. 3.1):
//     AB = smallest sphere enclosing A and B,   C_AB = r_AB^3 / F_AB
// AABB (thesis eq. 4.1):
//     AB = hull of A and B,   C_AB = V_AB / F_AB * (max extent / min extent)^k
// Fill factor (eq. 3.1), with the exact overlap of the two volumes (OverlapVolume.h):
//     F_AB = (F_A V_A + F_B V_B - V_overlap) / V_AB
//
// Choices the thesis leaves open (documented here because the fast clusterer, the naive test
// reference and the baselines all evaluate costs through this one class):
// - Clamped fill. With F < 1 the overlap term can exceed what the two clusters really hold
//   (two sparse clusters whose volumes overlap a lot), and eq. 3.1 then goes to zero or below,
//   which would make the cost infinite or negative. The numerator is clamped to
//   [max(F_A V_A, F_B V_B), V_AB]: the merged cluster holds at least the geometry of the
//   fuller part and at most its whole volume. So 0 < F <= 1 always.
// - Degenerate volumes. A flat part (a floor plate, a decal) has a zero box extent, which
//   makes V = 0 and the proportion ratio infinite. Every leaf box is padded about its centre to
//   a minimum extent `minExtent` per axis and every leaf sphere to a minimum radius
//   minExtent / 2 before clustering (the clusterer derives minExtent from the scene size, see
//   BottomUpClusterer.h). Only the clustering volumes are padded; ClusterNode::box stays exact.
// - Canonical operand order. merge(lo, hi) is evaluated with the lower-keyed cluster first, so
//   rounding never depends on who asked: cost(A, B) is one number.
// The unit stores F*V directly ("geometry volume") rather than F, so eq. 3.1 needs no
// volume recomputation and the fill is fv / volume.
#pragma once

#include <algorithm>
#include <cmath>

#include "pipeline/bounds/Sphere.h"
#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/scene/Aabb.h"

namespace hlod {

// A cluster as the cost model sees it. `volume` is V of the model's volume type (sphere or
// padded box), `fv` is F*V, `cost` is the model cost of this cluster.
struct ClusterUnit {
    Sphere sphere; // enclosing sphere (padded for leaves)
    Aabb box;      // padded box (hull of padded leaf boxes)
    double volume = 0.0;
    double fv = 0.0;
    double cost = 0.0;
    double fill() const { return volume > 0.0 ? fv / volume : 1.0; }
};

// What a spatial search knows about a set of clusters (a BVH node, MergeBvh.h): lower bounds
// of their size and an upper bound of their F*V.
struct Region {
    Aabb box;           // holds every cluster's search volume
    double maxFv = 0.0; // largest F*V
    double minRadius = 0.0;
    double minVolume = 0.0;
    glm::dvec3 minExtent{0.0}; // smallest box extent per axis
};

class CostModel {
public:
    // `volume` must be VolumeType::Sphere or VolumeType::Aabb; `k` >= 0 (used by Aabb only).
    // Throws Error(InvalidArgument) otherwise.
    CostModel(VolumeType volume, double k);

    VolumeType volume() const { return volume_; }
    double k() const { return k_; }

    // A leaf (F = 1) from its exact bounds, padded to `minExtent` (> 0) as described above.
    ClusterUnit leaf(const Sphere& sphere, const Aabb& box, double minExtent) const;

    // The cluster of lo and hi (both bounds, fill, cost). `lo` is the operand with the lower
    // tie-break key.
    ClusterUnit merge(const ClusterUnit& lo, const ClusterUnit& hi) const;

    // merge(lo, hi).cost, computing only what the cost needs (same arithmetic, same bits).
    double mergeCost(const ClusterUnit& lo, const ClusterUnit& hi) const;

    // Lower bound of mergeCost(x, g) over every cluster g described by `region`. Used to prune
    // spatial searches; it is slightly below the mathematical bound so rounding can never make
    // it exceed a real cost.
    double lowerBound(const ClusterUnit& x, const Region& region) const;

    // The region of the single cluster u (its search box: the sphere's box for the sphere
    // model).
    Region regionOf(const ClusterUnit& u) const;

    // Size class for MergeBvh: binary exponent of the radius (sphere) or of the cube root of
    // the volume (box), so clusters within a class differ in size by less than 2x.
    int sizeClass(const ClusterUnit& u) const;

    // Model cost of a single cluster with its own volume and fill.
    double costOf(const Sphere& s, const Aabb& box, double volume, double fv) const;

private:
    struct Eval {
        double volume;
        double fv;
        double cost;
    };
    Eval evaluate(const ClusterUnit& lo, const ClusterUnit& hi, const Sphere& sphere,
                  const Aabb& box) const;

public:
    // ratio^k; exact for the thesis' k = 0, 1, 2 and cheaper than pow() there.
    double powK(double ratio) const {
        if (k_ == 0.0) return 1.0;
        if (k_ == 1.0) return ratio;
        if (k_ == 2.0) return ratio * ratio;
        return std::pow(ratio, k_);
    }

private:
    VolumeType volume_;
    double k_;
};

// Box `b` grown about its centre so that every extent is at least `minExtent`.
Aabb padBox(const Aabb& b, double minExtent);

// Lower bound of the hull length of the interval [a, b] and an interval of length >= w that
// lies inside [lo, hi] (starting at some c in [lo, hi - w]): the hull max(b, c + w) - min(a, c)
// is at least b - a, w, (lo + w) - a and b - (hi - w). Branch-free: it runs in the inner loop
// of every search.
inline double minHullLength(double a, double b, double lo, double hi, double w) {
    return std::max(std::max(b - a, w), std::max(lo + w - a, b - hi + w));
}

// CostModel::lowerBound for one cluster x against many regions, inline for the searches' inner
// loop. Why it is a bound: cost = V_AB^2 / fv_AB * shape with fv_AB <= min(V_AB, fv_x + fv_g)
// (the clamp), so cost >= V_AB * max(1, V_AB / (fv_x + maxFv)) * shape, increasing in V_AB:
// a lower bound of V_AB (and of the shape factor) gives one of the cost.
// - Sphere: the merged sphere holds x's ball and g's ball (radius >= minRadius, inside the
//   box). When x's centre is outside the box (distance d > 0) g's farthest point is at least
//   d + 2 minRadius away, else at least minRadius away; the diameter is at least that plus r_x.
// - Box: per axis the merged box holds x's interval and g's, which is at least minExtent long
//   and lies inside the region (minHullLength); its volume is also at least minVolume; the
//   merged box lies in the hull of x and the region, which bounds the shape ratio.
// The result is scaled by 1 - 1e-9 so rounding can never make it exceed a real cost (a tie
// with the best candidate must not be pruned).
class BoundQuery {
public:
    BoundQuery(const CostModel& model, const ClusterUnit& x)
        : model_(model), x_(x), sphere_(model.volume() == VolumeType::Sphere),
          hasShape_(model.k() != 0.0) {}

    double operator()(const Region& g) const {
        constexpr double kSafety = 1.0 - 1e-9;
        const double fvSum = x_.fv + g.maxFv;
        if (sphere_) {
            const glm::dvec3 c = x_.sphere.center;
            const glm::dvec3 q = glm::clamp(c, g.box.min, g.box.max) - c;
            const double d2 = glm::dot(q, q);
            const double far = d2 > 0.0 ? std::sqrt(d2) + 2.0 * g.minRadius : g.minRadius;
            const double r =
                std::max(std::max(x_.sphere.radius, g.minRadius), (far + x_.sphere.radius) * 0.5);
            const double r3 = r * r * r;
            return r3 * std::max(1.0, kSphereVolume * r3 / fvSum) * kSafety;
        }
        const double ex =
            minHullLength(x_.box.min.x, x_.box.max.x, g.box.min.x, g.box.max.x, g.minExtent.x);
        const double ey =
            minHullLength(x_.box.min.y, x_.box.max.y, g.box.min.y, g.box.max.y, g.minExtent.y);
        const double ez =
            minHullLength(x_.box.min.z, x_.box.max.z, g.box.min.z, g.box.max.z, g.minExtent.z);
        const double v = std::max(ex * ey * ez, g.minVolume);
        double bound = v * std::max(1.0, v / fvSum) * kSafety;
        if (hasShape_) {
            const glm::dvec3 ub = glm::max(x_.box.max, g.box.max) - glm::min(x_.box.min, g.box.min);
            const double shape =
                std::max(ex, std::max(ey, ez)) / std::min(ub.x, std::min(ub.y, ub.z));
            bound *= model_.powK(std::max(1.0, shape));
        }
        return bound;
    }

private:
    static constexpr double kSphereVolume = 4.0 / 3.0 * 3.14159265358979323846;
    const CostModel& model_;
    const ClusterUnit& x_;
    bool sphere_;
    bool hasShape_;
};

// Lower bound of mergeCost(x, g) over every x described by region `a` and g described by `b`
// (the spatial self-join of a level). Same argument as BoundQuery with x's exact bounds
// replaced by its region:
// - Sphere: balls inside boxes a distance d > 0 apart are at least d apart, so the enclosing
//   diameter is at least d + 2 minRadius_a + 2 minRadius_b; else at least twice the larger
//   minimum radius.
// - Box: per axis, intervals of lengths >= w_a in [a_lo, a_hi] and >= w_b in [b_lo, b_hi] have
//   a hull of at least max(w_a, w_b, b_lo - a_hi + w_a + w_b, a_lo - b_hi + w_a + w_b).
// pairLowerBound(model, a, b) > threshold, without divisions (the self-join's inner loop).
[[gnu::always_inline]] inline bool pairBoundExceeds(const CostModel& model, const Region& a,
                                                    const Region& b, double threshold) {
    constexpr double kSafety = 1.0 - 1e-9;
    constexpr double kSphereVolume = 4.0 / 3.0 * 3.14159265358979323846;
    const double fvSum = a.maxFv + b.maxFv;
    const glm::dvec3 gap =
        glm::max(glm::max(a.box.min - b.box.max, b.box.min - a.box.max), glm::dvec3(0.0));
    if (model.volume() == VolumeType::Sphere) {
        const double d2 = glm::dot(gap, gap);
        const double diameter = d2 > 0.0 ? std::sqrt(d2) + 2.0 * (a.minRadius + b.minRadius)
                                         : 2.0 * std::max(a.minRadius, b.minRadius);
        const double r = diameter * 0.5;
        const double r3 = r * r * r;
        // r3 * max(1, c r3 / fvSum) > t  <=>  r3 * max(fvSum, c r3) > t * fvSum
        return r3 * std::max(fvSum, kSphereVolume * r3) * kSafety > threshold * fvSum;
    }
    const glm::dvec3 sum = a.minExtent + b.minExtent;
    const glm::dvec3 ext =
        glm::max(glm::max(a.minExtent, b.minExtent),
                 glm::max(b.box.min - a.box.max + sum, a.box.min - b.box.max + sum));
    const double v = std::max(ext.x * ext.y * ext.z, std::max(a.minVolume, b.minVolume));
    double lhs = v * std::max(fvSum, v) * kSafety;
    double rhs = threshold * fvSum;
    if (model.k() != 0.0) {
        // shape = max(1, maxExt / minUb): multiply through by minUb^k instead of dividing.
        const glm::dvec3 ub = glm::max(a.box.max, b.box.max) - glm::min(a.box.min, b.box.min);
        const double minUb = std::min(ub.x, std::min(ub.y, ub.z));
        const double maxExt = std::max(minUb, std::max(ext.x, std::max(ext.y, ext.z)));
        lhs *= model.powK(maxExt);
        rhs *= model.powK(minUb);
    }
    return lhs > rhs;
}

inline double pairLowerBound(const CostModel& model, const Region& a, const Region& b) {
    constexpr double kSafety = 1.0 - 1e-9;
    constexpr double kSphereVolume = 4.0 / 3.0 * 3.14159265358979323846;
    const double fvSum = a.maxFv + b.maxFv;
    const glm::dvec3 gap =
        glm::max(glm::max(a.box.min - b.box.max, b.box.min - a.box.max), glm::dvec3(0.0));
    if (model.volume() == VolumeType::Sphere) {
        const double d2 = glm::dot(gap, gap);
        const double diameter = d2 > 0.0 ? std::sqrt(d2) + 2.0 * (a.minRadius + b.minRadius)
                                         : 2.0 * std::max(a.minRadius, b.minRadius);
        const double r = diameter * 0.5;
        const double r3 = r * r * r;
        return r3 * std::max(1.0, kSphereVolume * r3 / fvSum) * kSafety;
    }
    const glm::dvec3 sum = a.minExtent + b.minExtent;
    const glm::dvec3 ext =
        glm::max(glm::max(a.minExtent, b.minExtent),
                 glm::max(b.box.min - a.box.max + sum, a.box.min - b.box.max + sum));
    const double v = std::max(ext.x * ext.y * ext.z, std::max(a.minVolume, b.minVolume));
    double bound = v * std::max(1.0, v / fvSum) * kSafety;
    if (model.k() != 0.0) {
        const glm::dvec3 ub = glm::max(a.box.max, b.box.max) - glm::min(a.box.min, b.box.min);
        const double shape =
            std::max(ext.x, std::max(ext.y, ext.z)) / std::min(ub.x, std::min(ub.y, ub.z));
        bound *= model.powK(std::max(1.0, shape));
    }
    return bound;
}

} // namespace hlod
