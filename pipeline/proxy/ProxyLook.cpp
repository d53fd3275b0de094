// A proxy's sidedness and emission from the originals under it, see ProxyLook.h.
#include "pipeline/proxy/ProxyLook.h"

#include <algorithm>
#include <cmath>

namespace hlod {

namespace {

// Where a base colour channel is black the atlas cannot carry that original's emission; its
// ratio is capped instead of exploding (dark but non-zero channels keep their exact ratio:
// TORCS' emis equals its rgb, ratio 1, over textures of any darkness).
constexpr double kMinBase = 1e-6;
constexpr double kMaxRatio = 16.0;

// World area of a mesh's triangles under the linear map `linear`.
double placedArea(const Mesh& mesh, const glm::dmat3& linear) {
    double area = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec3 a = linear * glm::dvec3(mesh.positions[mesh.indices[t]]);
        const glm::dvec3 b = linear * glm::dvec3(mesh.positions[mesh.indices[t + 1]]);
        const glm::dvec3 c = linear * glm::dvec3(mesh.positions[mesh.indices[t + 2]]);
        area += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    return area;
}

} // namespace

void ProxyLookSums::add(const ProxyLookSums& other) {
    doubleSided = doubleSided || other.doubleSided;
    area += other.area;
    emissiveOverBase += other.emissiveOverBase;
    emissive += other.emissive;
}

ProxyLookSums instanceLookSums(const Scene& scene, Id instance, bool withAreas) {
    ProxyLookSums out;
    const MeshInstance& inst = scene.instances[instance];
    const Mesh& mesh = scene.meshes[inst.mesh];
    const Material& m = scene.materials[mesh.material < scene.materials.size() ? mesh.material : 0];
    out.doubleSided = m.doubleSided;
    if (!withAreas) return out;
    out.area = placedArea(mesh, glm::dmat3(scene.nodes[inst.node].world));
    if (!m.emits()) return out;
    const glm::dvec3 emitted(m.effectiveEmissive());
    const glm::dvec3 base(m.effectiveColor());
    for (int c = 0; c < 3; ++c) {
        const double ratio = emitted[c] / std::max(base[c], kMinBase);
        out.emissiveOverBase[c] = out.area * std::min(ratio, kMaxRatio);
    }
    out.emissive = out.area * emitted;
    return out;
}

std::vector<ProxyLookSums> subtreeLookSums(const Scene& scene, const ClusterTree& tree,
                                           const std::vector<Id>& postOrder,
                                           std::vector<ProxyLookSums> known) {
    const bool anyEmits = std::any_of(scene.materials.begin(), scene.materials.end(),
                                      [](const Material& m) { return m.emits(); });
    std::vector<ProxyLookSums> sums = std::move(known);
    sums.resize(tree.nodes.size());
    for (Id id : postOrder) {
        const ClusterNode& node = tree.nodes[id];
        if (node.isLeaf()) {
            if (node.instance < scene.instances.size())
                sums[id] = instanceLookSums(scene, node.instance, anyEmits);
            continue;
        }
        for (Id c : node.children)
            sums[id].add(sums[c]);
    }
    return sums;
}

void applyProxyLook(ProxyMesh& proxy, const ProxyLookSums& sums) {
    proxy.doubleSided = sums.doubleSided;
    proxy.emissive = glm::vec3(0.0f);
    if (!(sums.area > 0.0)) return;
    const glm::dvec3 mean = (proxy.hasAtlas() ? sums.emissiveOverBase : sums.emissive) / sums.area;
    proxy.emissive = glm::vec3(mean);
}

} // namespace hlod
