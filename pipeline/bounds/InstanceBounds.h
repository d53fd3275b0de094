// Bounds of every mesh instance of a scene in world space: the exact world AABB (every vertex
// transformed) and the tight bounding sphere (Welzl, BoundingSphere.h), as the clustering of
// thesis section 3.2.3 needs them.
//
// Instancing: a mesh placed with a similarity transform (rotation, uniform scale, translation)
// reuses the mesh's local minimum sphere, transformed (a similarity maps the minimum ball of a
// point set to the minimum ball of the mapped points). Any other transform (non-uniform scale,
// shear) recomputes the sphere from the transformed vertices.
// A mesh without vertices gets a zero-size box and sphere at its instance's origin.
// Threads: computed in parallel with TBB; every instance writes only its own slot, so the
// result does not depend on the thread count. Checks the progress cancel flag.
#pragma once

#include <vector>

#include "pipeline/bounds/Sphere.h"
#include "pipeline/core/Progress.h"
#include "pipeline/scene/Aabb.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

struct InstanceBounds {
    Aabb box;
    Sphere sphere;
};

// One entry per scene instance, in instance order. Throws Error(Cancelled).
std::vector<InstanceBounds> computeInstanceBounds(const Scene& scene,
                                                  const Progress& progress = {});

// True when the upper 3x3 of `m` is a rotation times a uniform scale and the last row is
// (0, 0, 0, 1); `scale` receives the scale factor.
bool isSimilarity(const glm::dmat4& m, double& scale);

} // namespace hlod
