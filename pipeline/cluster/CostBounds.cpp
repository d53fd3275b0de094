// Region descriptions and size classes for the cost bounds (see CostBounds.h).
#include "pipeline/cluster/CostBounds.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace hlod {

Region emptyRegion() {
    Region r;
    constexpr double big = std::numeric_limits<double>::max();
    r.minRadius = big;
    r.minVolume = big;
    r.minExtent = glm::dvec3(big);
    r.minArea = glm::dvec3(big);
    return r;
}

namespace {

// The next float towards -infinity / +infinity of a float that is not NaN (std::nextafter
// without the library call: packing runs for every node of every level).
float nextDown(float f) {
    if (f == 0.0f) return -std::numeric_limits<float>::denorm_min();
    if (f == -std::numeric_limits<float>::infinity()) return f;
    const auto bits = std::bit_cast<std::uint32_t>(f);
    return std::bit_cast<float>(f > 0.0f ? bits - 1 : bits + 1);
}
float nextUp(float f) { return -nextDown(-f); }

// The float nearest to x on the side that keeps a bound valid.
float roundDown(double x) {
    const float f = static_cast<float>(x);
    return static_cast<double>(f) > x ? nextDown(f) : f;
}
float roundUp(double x) {
    const float f = static_cast<float>(x);
    return static_cast<double>(f) < x ? nextUp(f) : f;
}

} // namespace

void packRegion(const Region& r, bool boxModel, PackedRegion& out, PackedExtra& extra) {
    for (int a = 0; a < 3; ++a) {
        out.lo[a] = roundDown(r.box.min[a]);
        out.hi[a] = roundUp(r.box.max[a]);
    }
    out.maxFv = roundUp(r.maxFv);
    out.minSize = roundDown(boxModel ? r.minVolume : r.minRadius);
    if (boxModel) {
        for (int a = 0; a < 3; ++a) {
            extra.minExtent[a] = roundDown(r.minExtent[a]);
            extra.minArea[a] = roundDown(r.minArea[a]);
        }
    }
}

Region regionOf(const CostModel& model, const ClusterUnit& u) {
    Region r;
    if (model.volume() == VolumeType::Aabb) {
        r.box = u.box;
    } else {
        r.box = Aabb{u.sphere.center, u.sphere.center};
    }
    r.maxFv = u.fv;
    r.minRadius = u.sphere.radius;
    r.minVolume = u.volume;
    r.minExtent = u.box.max - u.box.min;
    r.minArea = crossSections(r.minExtent);
    return r;
}

int sizeClass(const CostModel& model, const ClusterUnit& u) {
    const double size =
        model.volume() == VolumeType::Sphere ? u.sphere.radius : std::cbrt(u.volume);
    return size > 0.0 ? std::ilogb(size) : std::numeric_limits<int>::min();
}

} // namespace hlod
