// Cluster cost and fill factor (thesis eq. 3.1, algorithm 2, eq. 4.1; contract in CostModel.h).
#include "pipeline/cluster/CostModel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "pipeline/bounds/BoundingSphere.h"
#include "pipeline/bounds/OverlapVolume.h"
#include "pipeline/core/Error.h"

namespace hlod {

namespace {

// Lower bounds are scaled by this so a few ulps of rounding in either the bound or the real
// cost cannot prune a candidate that ties the best one.
constexpr double kBoundSafety = 1.0 - 1e-9;

Aabb hull(const Aabb& a, const Aabb& b) {
    return Aabb{glm::min(a.min, b.min), glm::max(a.max, b.max)};
}

double boxVolume(const Aabb& b) {
    const glm::dvec3 e = b.max - b.min;
    return e.x * e.y * e.z;
}

double proportion(const glm::dvec3& e) {
    return std::max({e.x, e.y, e.z}) / std::min({e.x, e.y, e.z});
}

} // namespace

Aabb padBox(const Aabb& b, double minExtent) {
    if (b.empty()) return b;
    Aabb out = b;
    for (int a = 0; a < 3; ++a) {
        const double e = b.max[a] - b.min[a];
        if (e < minExtent) {
            const double c = (b.min[a] + b.max[a]) * 0.5;
            out.min[a] = c - minExtent * 0.5;
            out.max[a] = c + minExtent * 0.5;
        }
    }
    return out;
}

CostModel::CostModel(VolumeType volume, double k) : volume_(volume), k_(k) {
    if (volume != VolumeType::Sphere && volume != VolumeType::Aabb) {
        throw Error(ErrorCode::InvalidArgument,
                    std::string("cost model needs volume sphere or aabb, got ") + toString(volume));
    }
    if (!(k >= 0.0) || !std::isfinite(k)) {
        throw Error(ErrorCode::InvalidArgument, "proportion exponent k must be >= 0");
    }
}

double CostModel::powK(double ratio) const {
    // Exact for the thesis' k = 0, 1, 2 and cheaper than pow().
    if (k_ == 0.0) return 1.0;
    if (k_ == 1.0) return ratio;
    if (k_ == 2.0) return ratio * ratio;
    return std::pow(ratio, k_);
}

double CostModel::costOf(const Sphere& s, const Aabb& box, double volume, double fv) const {
    const double fill = fv / volume;
    if (volume_ == VolumeType::Sphere) return s.radius * s.radius * s.radius / fill;
    return volume / fill * powK(proportion(box.max - box.min));
}

ClusterUnit CostModel::leaf(const Sphere& sphere, const Aabb& box, double minExtent) const {
    ClusterUnit u;
    u.sphere = Sphere{sphere.center, std::max(sphere.radius, minExtent * 0.5)};
    u.box = padBox(box, minExtent);
    u.volume = volume_ == VolumeType::Sphere ? u.sphere.volume() : boxVolume(u.box);
    u.fv = u.volume;
    u.cost = costOf(u.sphere, u.box, u.volume, u.fv);
    return u;
}

CostModel::Eval CostModel::evaluate(const ClusterUnit& lo, const ClusterUnit& hi,
                                    const Sphere& sphere, const Aabb& box) const {
    Eval e{};
    double overlap = 0.0;
    if (volume_ == VolumeType::Sphere) {
        e.volume = sphere.volume();
        overlap = sphereIntersectionVolume(lo.sphere, hi.sphere);
    } else {
        e.volume = boxVolume(box);
        overlap = boxIntersectionVolume(lo.box, hi.box);
    }
    const double raw = lo.fv + hi.fv - overlap;
    e.fv = std::min(std::max(raw, std::max(lo.fv, hi.fv)), e.volume);
    e.cost = costOf(sphere, box, e.volume, e.fv);
    return e;
}

ClusterUnit CostModel::merge(const ClusterUnit& lo, const ClusterUnit& hi) const {
    ClusterUnit u;
    u.sphere = enclosingSphere(lo.sphere, hi.sphere);
    u.box = hull(lo.box, hi.box);
    const Eval e = evaluate(lo, hi, u.sphere, u.box);
    u.volume = e.volume;
    u.fv = e.fv;
    u.cost = e.cost;
    return u;
}

double CostModel::mergeCost(const ClusterUnit& lo, const ClusterUnit& hi) const {
    // The unused volume's bound is not needed by the cost; pass the operand's own as filler.
    if (volume_ == VolumeType::Sphere) {
        return evaluate(lo, hi, enclosingSphere(lo.sphere, hi.sphere), lo.box).cost;
    }
    return evaluate(lo, hi, lo.sphere, hull(lo.box, hi.box)).cost;
}

Region CostModel::regionOf(const ClusterUnit& u) const {
    Region r;
    if (volume_ == VolumeType::Aabb) {
        r.box = u.box;
    } else {
        const glm::dvec3 radius(u.sphere.radius);
        r.box = Aabb{u.sphere.center - radius, u.sphere.center + radius};
    }
    r.maxFv = u.fv;
    r.minRadius = u.sphere.radius;
    r.minVolume = u.volume;
    r.minExtent = u.box.max - u.box.min;
    return r;
}

int CostModel::sizeClass(const ClusterUnit& u) const {
    const double size = volume_ == VolumeType::Sphere ? u.sphere.radius : std::cbrt(u.volume);
    return size > 0.0 ? std::ilogb(size) : std::numeric_limits<int>::min();
}

double CostModel::lowerBound(const ClusterUnit& x, const Region& g) const {
    // cost = V_AB^2 / fv_AB * shape, with fv_AB <= min(V_AB, fv_x + fv_g) (clamp above), so
    // cost >= V_AB * max(1, V_AB / (fv_x + maxFv)) * shape, increasing in V_AB: it suffices to
    // bound V_AB (and the shape factor) from below.
    const double fvSum = x.fv + g.maxFv;
    if (volume_ == VolumeType::Sphere) {
        // The merged sphere holds x's ball and g's ball (radius >= minRadius, inside the box).
        // When x's centre is outside the box (distance d > 0) g's farthest point is at least
        // d + 2 minRadius away, else at least minRadius; the diameter is at least that plus
        // r_x.
        const glm::dvec3 c = x.sphere.center;
        const double d = glm::length(glm::clamp(c, g.box.min, g.box.max) - c);
        const double far = d > 0.0 ? d + 2.0 * g.minRadius : g.minRadius;
        const double r = std::max({x.sphere.radius, g.minRadius, (far + x.sphere.radius) * 0.5});
        const double v = 4.0 / 3.0 * std::numbers::pi * r * r * r;
        return r * r * r * std::max(1.0, v / fvSum) * kBoundSafety;
    }
    // The merged box holds x's box, a point of the region (per axis: x's extent plus the gap)
    // and g's box (at least minExtent per axis, minVolume in all); it lies in the hull of x
    // and the region.
    const glm::dvec3 lbExt = glm::max(
        glm::max(x.box.max, g.box.min) - glm::min(x.box.min, g.box.max), g.minExtent);
    const glm::dvec3 ubExt = glm::max(x.box.max, g.box.max) - glm::min(x.box.min, g.box.min);
    const double v = std::max(lbExt.x * lbExt.y * lbExt.z, g.minVolume);
    const double shape =
        std::max(1.0, std::max({lbExt.x, lbExt.y, lbExt.z}) / std::min({ubExt.x, ubExt.y,
                                                                        ubExt.z}));
    return v * std::max(1.0, v / fvSum) * powK(shape) * kBoundSafety;
}

} // namespace hlod
