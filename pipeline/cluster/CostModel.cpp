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
    return mergeCostWithin(lo, hi, std::numeric_limits<double>::infinity());
}

double CostModel::mergeCostWithin(const ClusterUnit& lo, const ClusterUnit& hi,
                                  double limit) const {
    // The unused volume's bound is not needed by the cost; pass the operand's own as filler.
    if (volume_ == VolumeType::Sphere) {
        const Sphere s = enclosingSphere(lo.sphere, hi.sphere);
        const double r3 = s.radius * s.radius * s.radius; // costOf's numerator, same bits
        if (r3 > limit) return r3;
        return evaluate(lo, hi, s, lo.box).cost;
    }
    const Aabb box = hull(lo.box, hi.box);
    const double v = boxVolume(box);
    if (v > limit) return v;
    return evaluate(lo, hi, lo.sphere, box).cost;
}

} // namespace hlod
