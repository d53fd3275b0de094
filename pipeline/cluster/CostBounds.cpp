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

// The float nearest to x on the side that keeps a bound valid (x not NaN): the conversion,
// then one step down (up) when it rounded the wrong way. Without branches, in integer masks
// (a conditional expression here compiles to jumps): packing runs for every node of every
// level, and which way a conversion rounds is a coin toss for the branch predictor. A step
// down from a positive float is its bit pattern minus one, from a negative one plus one; a
// zero is taken as -0, whose step (plus one) is the negative smallest denormal; +infinity
// steps to the largest float, and -infinity never needs a step.
float roundDown(double x) {
    const float f = static_cast<float>(x);
    const auto bits = std::bit_cast<std::uint32_t>(f);
    const std::uint32_t zero = (bits << 1) == 0 ? 1u : 0u;
    const std::uint32_t below = bits | zero << 31;
    const std::uint32_t step = below - 1u + 2u * (below >> 31);
    const std::uint32_t wrong = 0u - (static_cast<double>(f) > x ? 1u : 0u);
    return std::bit_cast<float>((step & wrong) | (bits & ~wrong));
}
float roundUp(double x) { return -roundDown(-x); }

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
    if (model.volume() == VolumeType::Sphere) {
        return u.sphere.radius > 0.0 ? std::ilogb(u.sphere.radius)
                                     : std::numeric_limits<int>::min();
    }
    // floor(log2(cbrt(V))) = floor(floor(log2(V)) / 3), without the cube root.
    if (!(u.volume > 0.0)) return std::numeric_limits<int>::min();
    const int e = std::ilogb(u.volume);
    return e >= 0 ? e / 3 : -((2 - e) / 3);
}

} // namespace hlod
