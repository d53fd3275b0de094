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
// Packed regions: the BVH stores regions in single precision rounded outward (PackedRegion);
// the same bounds read either form through small accessors. PackedPairTest is the pair test
// written out per component; WideBounds.h evaluates the same terms for four regions at once.
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
// A packed region and its extra (null for the sphere model).
struct PackedRef {
    const PackedRegion* r;
    const PackedExtra* e;
};

// The bounds read a region through these, so they evaluate a Region and a packed one alike.
inline glm::dvec3 lowCorner(const Region& g) { return g.box.min; }
inline glm::dvec3 highCorner(const Region& g) { return g.box.max; }
inline double maxFvOf(const Region& g) { return g.maxFv; }
inline double minRadiusOf(const Region& g) { return g.minRadius; }
inline double minVolumeOf(const Region& g) { return g.minVolume; }
inline glm::dvec3 minExtentOf(const Region& g) { return g.minExtent; }
inline glm::dvec3 minAreaOf(const Region& g) { return g.minArea; }
inline glm::dvec3 lowCorner(PackedRef g) { return glm::dvec3(g.r->lo[0], g.r->lo[1], g.r->lo[2]); }
inline glm::dvec3 highCorner(PackedRef g) { return glm::dvec3(g.r->hi[0], g.r->hi[1], g.r->hi[2]); }
inline double maxFvOf(PackedRef g) { return g.r->maxFv; }
inline double minRadiusOf(PackedRef g) { return g.r->minSize; }
inline double minVolumeOf(PackedRef g) { return g.r->minSize; }
inline glm::dvec3 minExtentOf(PackedRef g) {
    return glm::dvec3(g.e->minExtent[0], g.e->minExtent[1], g.e->minExtent[2]);
}
inline glm::dvec3 minAreaOf(PackedRef g) {
    return glm::dvec3(g.e->minArea[0], g.e->minArea[1], g.e->minArea[2]);
}

// `r` packed as described at PackedRegion (`boxModel`: minSize is the volume and `extra` is
// written; else minSize is the radius).
void packRegion(const Region& r, bool boxModel, PackedRegion& out, PackedExtra& extra);
// A packed region widened back to a Region (exact: every float is a double); a PackedRef
// without extra is the sphere model's.
Region unpackRegion(PackedRef g);

// The region of the single cluster u (box: its centre for the sphere model, its padded box for
// the box model).
Region regionOf(const CostModel& model, const ClusterUnit& u);

// Size class for MergeBvh: binary exponent of the radius (sphere) or of the cube root of the
// volume (box), so clusters within a class differ in size by less than 2x.
int sizeClass(const CostModel& model, const ClusterUnit& u);

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

// Lower bound of mergeCost(x, g) over every x described by region `a` and g described by `b`
// (the spatial searches of a level; a single cluster is the region of itself alone), by the
// argument of the header:
// - Sphere: centres inside boxes a distance d apart are at least d apart.
// - Box: per axis, intervals of lengths >= w_a in [a_lo, a_hi] and >= w_b in [b_lo, b_hi] have
//   a hull of at least max(w_a, w_b, b_lo - a_hi + w_a + w_b, a_lo - b_hi + w_a + w_b); the
//   cross-sections are at least the larger of the two regions' minima.
struct PairBound {
    double lhs; // bound = lhs / den * kSafety (before the shape terms)
    double den; // > 0
    // Box model: lower bounds of the merged extents and volume, and the smallest extent of the
    // hull of the two regions (an upper bound of the merged box's smallest extent).
    glm::dvec3 ext{0.0};
    double v = 0.0;
    double minUb = 1.0;
};

template <class R>
[[gnu::always_inline]] inline PairBound pairBoundTerms(const CostModel& model, const R& a,
                                                       const R& b) {
    constexpr double kSphereVolume = 4.0 / 3.0 * 3.14159265358979323846;
    const double fvSum = maxFvOf(a) + maxFvOf(b);
    const glm::dvec3 aLo = lowCorner(a), aHi = highCorner(a);
    const glm::dvec3 bLo = lowCorner(b), bHi = highCorner(b);
    if (model.volume() == VolumeType::Sphere) {
        const glm::dvec3 gap = glm::max(glm::max(aLo - bHi, bLo - aHi), glm::dvec3(0.0));
        const double d = std::sqrt(glm::dot(gap, gap));
        const double ra = minRadiusOf(a), rb = minRadiusOf(b);
        const double r = std::max(std::max(ra, rb), (d + ra + rb) * 0.5);
        const double r3 = r * r * r;
        // r3 * max(1, c r3 / fvSum) = r3 * max(fvSum, c r3) / fvSum
        return PairBound{r3 * std::max(fvSum, kSphereVolume * r3), fvSum};
    }
    const glm::dvec3 wa = minExtentOf(a), wb = minExtentOf(b);
    const glm::dvec3 sum = wa + wb;
    PairBound out;
    out.ext = glm::max(glm::max(wa, wb), glm::max(bLo - aHi + sum, aLo - bHi + sum));
    out.v = std::max(minBoxVolume(out.ext, glm::max(minAreaOf(a), minAreaOf(b))),
                     std::max(minVolumeOf(a), minVolumeOf(b)));
    out.lhs = out.v * std::max(fvSum, out.v);
    out.den = fvSum;
    if (model.k() != 0.0) {
        const glm::dvec3 ub = glm::max(aHi, bHi) - glm::min(aLo, bLo);
        out.minUb = std::min(ub.x, std::min(ub.y, ub.z));
    }
    return out;
}

// pairLowerBound(model, a, b) > threshold, without divisions for k = 0, 1, 2 (the self-join's
// inner loop); the cheap volume bound is tried before the shape terms.
template <class R>
[[gnu::always_inline]] inline bool pairBoundExceeds(const CostModel& model, const R& a, const R& b,
                                                    double threshold) {
    constexpr double kSafety = 1.0 - 1e-9;
    const PairBound t = pairBoundTerms(model, a, b);
    const double lhs = t.lhs * kSafety;
    const double rhs = threshold * t.den;
    if (lhs > rhs) return true;
    if (model.volume() != VolumeType::Aabb || model.k() == 0.0) return false;
    const double k = model.k();
    const glm::dvec3& e = t.ext;
    const double hi = std::max(e.x, std::max(e.y, e.z));
    if (k == 1.0 || k == 2.0) {
        // shapeVolumeBound multiplied through by fvSum.
        const double mid = std::max(std::min(e.x, e.y), std::min(std::max(e.x, e.y), e.z));
        const double p = hi * hi * mid;
        const double coupled = k == 1.0 ? p * std::max(t.den, t.v) : p * p;
        if (coupled * kSafety > rhs) return true;
    } else if (shapeVolumeBound(k, e, t.v, t.den) * kSafety > threshold) {
        return true;
    }
    // Separate shape factor max(1, hi / minUb)^k, multiplied through by minUb^k.
    return lhs * model.powK(std::max(t.minUb, hi)) > rhs * model.powK(t.minUb);
}

// pairBoundExceeds(model, a, b, threshold) for packed regions, written out per component for
// the self-join's inner loop (same terms in the same order, so the same answer; the glm form
// above compiles to branches and several times the instructions). The tests check both.
class PackedPairTest {
public:
    PackedPairTest(const CostModel& model, double threshold)
        : threshold_(threshold), k_(model.k()), sphere_(model.volume() == VolumeType::Sphere) {}

    [[gnu::always_inline]] bool exceeds(PackedRef a, PackedRef b) const {
        return sphere_ ? sphereExceeds(*a.r, *b.r) : boxExceeds(a, b);
    }

private:
    static constexpr double kSafety = 1.0 - 1e-9;
    static constexpr double kSphereVolume = 4.0 / 3.0 * 3.14159265358979323846;

    static double gapOf(const PackedRegion& a, const PackedRegion& b, int i) {
        return std::max(static_cast<double>(a.lo[i]) - b.hi[i],
                        static_cast<double>(b.lo[i]) - a.hi[i]);
    }

    [[gnu::always_inline]] bool sphereExceeds(const PackedRegion& a, const PackedRegion& b) const {
        const double fvSum = static_cast<double>(a.maxFv) + b.maxFv;
        const double gx = std::max(gapOf(a, b, 0), 0.0);
        const double gy = std::max(gapOf(a, b, 1), 0.0);
        const double gz = std::max(gapOf(a, b, 2), 0.0);
        const double d = std::sqrt(gx * gx + gy * gy + gz * gz);
        const double ra = a.minSize, rb = b.minSize;
        const double r = std::max(std::max(ra, rb), (d + ra + rb) * 0.5);
        const double r3 = r * r * r;
        return r3 * std::max(fvSum, kSphereVolume * r3) * kSafety > threshold_ * fvSum;
    }

    [[gnu::always_inline]] bool boxExceeds(PackedRef pa, PackedRef pb) const {
        const PackedRegion& a = *pa.r;
        const PackedRegion& b = *pb.r;
        const PackedExtra& xa = *pa.e;
        const PackedExtra& xb = *pb.e;
        const double fvSum = static_cast<double>(a.maxFv) + b.maxFv;
        double e[3];
        double area[3];
        for (int i = 0; i < 3; ++i) {
            const double wa = xa.minExtent[i], wb = xb.minExtent[i];
            e[i] = std::max(std::max(wa, wb), gapOf(b, a, i) + (wa + wb));
            area[i] = std::max(xa.minArea[i], xb.minArea[i]);
        }
        const double vx = e[0] * std::max(area[0], e[1] * e[2]);
        const double vy = e[1] * std::max(area[1], e[0] * e[2]);
        const double vz = e[2] * std::max(area[2], e[0] * e[1]);
        const double v = std::max(std::max(vx, std::max(vy, vz)),
                                  static_cast<double>(std::max(a.minSize, b.minSize)));
        const double lhs = v * std::max(fvSum, v) * kSafety;
        const double rhs = threshold_ * fvSum;
        if (lhs > rhs) return true;
        if (k_ == 0.0) return false;
        const double hi = std::max(e[0], std::max(e[1], e[2]));
        if (k_ == 1.0 || k_ == 2.0) {
            const double mid = std::max(std::min(e[0], e[1]), std::min(std::max(e[0], e[1]), e[2]));
            const double p = hi * hi * mid;
            const double coupled = k_ == 1.0 ? p * std::max(fvSum, v) : p * p;
            if (coupled * kSafety > rhs) return true;
        } else if (shapeVolumeBound(k_, glm::dvec3(e[0], e[1], e[2]), v, fvSum) * kSafety >
                   threshold_) {
            return true;
        }
        double minUb = std::numeric_limits<double>::max();
        for (int i = 0; i < 3; ++i) {
            minUb = std::min(minUb, static_cast<double>(std::max(a.hi[i], b.hi[i])) -
                                        std::min(a.lo[i], b.lo[i]));
        }
        const double shape = std::max(minUb, hi);
        if (k_ == 1.0) return lhs * shape > rhs * minUb;
        if (k_ == 2.0) return lhs * (shape * shape) > rhs * (minUb * minUb);
        return lhs * std::pow(shape, k_) > rhs * std::pow(minUb, k_);
    }

    double threshold_;
    double k_;
    bool sphere_;
};

template <class R> double pairLowerBound(const CostModel& model, const R& a, const R& b) {
    constexpr double kSafety = 1.0 - 1e-9;
    const PairBound t = pairBoundTerms(model, a, b);
    double bound = t.lhs / t.den * kSafety;
    if (model.k() != 0.0 && model.volume() == VolumeType::Aabb) {
        const double hi = std::max(t.ext.x, std::max(t.ext.y, t.ext.z));
        bound *= model.powK(std::max(t.minUb, hi) / t.minUb);
        bound = std::max(bound, shapeVolumeBound(model.k(), t.ext, t.v, t.den) * kSafety);
    }
    return bound;
}

} // namespace hlod
