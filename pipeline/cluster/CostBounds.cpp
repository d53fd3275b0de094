// Region descriptions and size classes for the cost bounds (see CostBounds.h).
#include "pipeline/cluster/CostBounds.h"

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

double lowerBound(const CostModel& model, const ClusterUnit& x, const Region& g) {
    return BoundQuery(model, x)(g);
}

} // namespace hlod
