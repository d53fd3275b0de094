// See AtlasStep.h.
#include "pipeline/proxy/AtlasStep.h"

#include <algorithm>

#include "pipeline/proxy/BakeFrame.h"
#include "pipeline/proxy/atlas/BakeAtlas.h"

namespace hlod {

namespace {

constexpr std::uint64_t kAtlasFormatVersion = 1;

// Leaves under `id`, with `to` the map from `id`'s frame into the target node's frame. Each
// child is placed in `id`'s frame as the baker places it (placeInFrame, BakeFrame.h).
void addSubtree(SourceSurfaces& out, const Scene& scene, const ClusterTree& tree, Id id,
                const PartPlacement& to, const std::vector<NodeBake>& nodes) {
    const NodeBake& self = nodes[id];
    for (Id c : tree.nodes[id].children) {
        const ClusterNode& child = tree.nodes[c];
        if (child.isLeaf()) {
            if (child.instance == kNoId) continue;
            const glm::dmat4& world = scene.instanceTransform(child.instance);
            const PartPlacement p =
                placeInFrame(self.frame, glm::dmat3(world), glm::dvec3(world[3]), self.errorBudget);
            out.addInstance(scene, child.instance, to.linear * p.linear,
                            to.linear * p.offset + to.offset);
        } else {
            const PartPlacement p = placeInFrame(self.frame, nodes[c].frame.rotation,
                                                 nodes[c].frame.origin, self.errorBudget);
            addSubtree(out, scene, tree, c,
                       PartPlacement{to.linear * p.linear, to.linear * p.offset + to.offset},
                       nodes);
        }
    }
}

} // namespace

SourceSurfaces gatherNodeSources(const Scene& scene, const ClusterTree& tree, Id node,
                                 const std::vector<NodeBake>& nodes) {
    SourceSurfaces out;
    addSubtree(out, scene, tree, node, PartPlacement{}, nodes);
    return out;
}

ProxyMesh bakeNodeAtlas(const ProxyMesh& proxy, const Scene& scene, const ClusterTree& tree,
                        Id node, const std::vector<NodeBake>& nodes, const BakeParams& params,
                        TextureMips& mips) {
    if (!params.atlas.enabled || proxy.empty()) return proxy;
    // A scene without any texture image: bakeAtlas would return the proxy unchanged
    // (skipUntextured), so the subtree's surfaces are not gathered (at the root: the scene).
    const bool anyImage =
        std::any_of(scene.textures.begin(), scene.textures.end(),
                    [](const Texture& t) { return t.image && !t.image->empty(); });
    if (params.atlas.skipUntextured && !anyImage) return proxy;
    const SourceSurfaces sources = gatherNodeSources(scene, tree, node, nodes);
    const double texelSize = nodes[node].errorBudget / params.screen.pixelError;
    ProxyMesh out =
        bakeAtlas(proxy, sources, nodes[node].errorBudget, texelSize, params.atlas, mips);
    out.origin = proxy.origin;
    return out;
}

void hashAtlasOptions(ContentHash& h, const AtlasOptions& options) {
    if (!options.enabled) return;
    h.addValue(kAtlasFormatVersion);
    h.addValue(options.maxSize);
    h.addValue(options.padding);
    h.addValue(options.jpegQuality);
    h.addValue(options.maxNormalDegrees);
    h.addValue(options.skipUntextured);
}

std::vector<std::uint64_t> textureHashes(const Scene& scene) {
    std::vector<std::uint64_t> out;
    for (const Texture& t : scene.textures) {
        if (!t.image) {
            out.push_back(0);
            continue;
        }
        ContentHash h(0x746578); // "tex"
        h.addValue(t.image->width);
        h.addValue(t.image->height);
        h.addVector(t.image->pixels);
        out.push_back(h.digest());
    }
    return out;
}

std::uint64_t leafLookHash(const Scene& scene, Id instance,
                           const std::vector<std::uint64_t>& textureHash) {
    const Mesh& mesh = scene.meshes[scene.instances[instance].mesh];
    const Material& m = scene.materials[mesh.material < scene.materials.size() ? mesh.material : 0];
    ContentHash h(0x6c6f6f6b); // "look"
    h.addVector(mesh.uvs);
    h.addValue(m.baseColor);
    h.addValue(m.alphaMode);
    h.addValue(m.alphaCutoff);
    h.addValue(m.texture < textureHash.size() ? textureHash[m.texture] : std::uint64_t(0));
    return h.digest();
}

} // namespace hlod
