// The scalar forms of the clustering's set bounds (pipeline/cluster/CostBounds.h explains why
// they hold): on exact Regions or packed ones, one pair at a time. Production evaluates them
// four lanes at a time (WideBounds.h); the tests check the lanes against these and these
// against real costs.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "pipeline/cluster/CostBounds.h"

namespace hlod {

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

// A packed region widened back to a Region (exact: every float is a double); a PackedRef
// without extra is the sphere model's.
inline Region unpackRegion(PackedRef g) {
    Region r;
    r.box = Aabb{lowCorner(g), highCorner(g)};
    r.maxFv = maxFvOf(g);
    // The minima the model does not read stay 0 (a valid lower bound of anything).
    r.minRadius = g.e == nullptr ? minRadiusOf(g) : 0.0;
    r.minVolume = g.e != nullptr ? minVolumeOf(g) : 0.0;
    if (g.e != nullptr) {
        r.minExtent = minExtentOf(g);
        r.minArea = minAreaOf(g);
    }
    return r;
}

// Lower bound of a box volume with per-axis extents of at least `e` and cross-sections of at
// least `area` (see the header): max over the axes of e_i * max(area_i, e_j e_k).
inline double minBoxVolume(const glm::dvec3& e, const glm::dvec3& area) {
    const double vx = e.x * std::max(area.x, e.y * e.z);
    const double vy = e.y * std::max(area.y, e.x * e.z);
    const double vz = e.z * std::max(area.z, e.x * e.y);
    return std::max(vx, std::max(vy, vz));
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
