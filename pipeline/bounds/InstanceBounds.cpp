// Per-instance world bounds (contract in InstanceBounds.h).
#include "pipeline/bounds/InstanceBounds.h"

#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "pipeline/bounds/BoundingSphere.h"
#include "pipeline/core/Error.h"

namespace hlod {

bool isSimilarity(const glm::dmat4& m, double& scale) {
    if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0) return false;
    const glm::dvec3 c0(m[0]), c1(m[1]), c2(m[2]);
    const double l0 = glm::dot(c0, c0), l1 = glm::dot(c1, c1), l2 = glm::dot(c2, c2);
    if (l0 <= 0.0) return false;
    // Tolerances relative to the squared scale: exported transforms carry float noise.
    const double tol = 1e-9 * l0;
    if (std::abs(l1 - l0) > tol || std::abs(l2 - l0) > tol) return false;
    if (std::abs(glm::dot(c0, c1)) > tol || std::abs(glm::dot(c0, c2)) > tol ||
        std::abs(glm::dot(c1, c2)) > tol) {
        return false;
    }
    scale = std::sqrt(l0);
    return true;
}

namespace {

Sphere localSphere(const Mesh& mesh) {
    std::vector<glm::dvec3> pts(mesh.positions.begin(), mesh.positions.end());
    return minimumBoundingSphere(pts);
}

InstanceBounds boundsOf(const Scene& scene, Id instance, const std::vector<Sphere>& local,
                        const std::vector<char>& hasLocal) {
    const MeshInstance& inst = scene.instances[instance];
    const Mesh& mesh = scene.meshes[inst.mesh];
    const glm::dmat4& m = scene.instanceTransform(instance);
    InstanceBounds out;
    if (mesh.positions.empty()) {
        const glm::dvec3 origin(m[3]);
        out.box.expand(origin);
        out.sphere = Sphere{origin, 0.0};
        return out;
    }
    std::vector<glm::dvec3> world;
    double scale = 1.0;
    const bool similar = hasLocal[inst.mesh] && isSimilarity(m, scale);
    if (!similar) world.reserve(mesh.positions.size());
    for (const glm::vec3& p : mesh.positions) {
        const glm::dvec3 w(m * glm::dvec4(glm::dvec3(p), 1.0));
        out.box.expand(w);
        if (!similar) world.push_back(w);
    }
    if (similar) {
        const Sphere& s = local[inst.mesh];
        out.sphere = Sphere{glm::dvec3(m * glm::dvec4(s.center, 1.0)), s.radius * scale};
    } else {
        out.sphere = minimumBoundingSphere(world);
    }
    return out;
}

} // namespace

std::vector<InstanceBounds> computeInstanceBounds(const Scene& scene, const Progress& progress) {
    const std::size_t n = scene.instances.size();
    // Local spheres only for meshes that some similarity instance will reuse.
    std::vector<char> hasLocal(scene.meshes.size(), 0);
    for (Id i = 0; i < n; ++i) {
        double scale = 0.0;
        if (isSimilarity(scene.instanceTransform(i), scale)) {
            hasLocal[scene.instances[i].mesh] = 1;
        }
    }
    std::vector<Sphere> local(scene.meshes.size());
    tbb::parallel_for(std::size_t(0), scene.meshes.size(), [&](std::size_t m) {
        if (hasLocal[m] && !progress.cancelled()) local[m] = localSphere(scene.meshes[m]);
    });
    progress.throwIfCancelled();

    std::vector<InstanceBounds> out(n);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          if (progress.cancelled()) return;
                          for (std::size_t i = r.begin(); i < r.end(); ++i) {
                              out[i] = boundsOf(scene, static_cast<Id>(i), local, hasLocal);
                          }
                      });
    progress.throwIfCancelled();
    return out;
}

} // namespace hlod
