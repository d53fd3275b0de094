// What a proxy shows besides its base colour (issue 28, "materials as authored"): whether it is
// drawn from both sides and what light it emits, decided from the originals it stands for
// (every leaf of its node's subtree, dissolved nodes included).
//
// Double-sided: a proxy is double-sided when any original under it is. A proxy over a
// two-sided card (a fence, a tree billboard) seen from behind would otherwise vanish in every
// engine, while drawing the back faces of a proxy whose originals are all one-sided costs
// only the overdraw of faces that the front faces hide.
// Emissive: glTF adds emissiveFactor x emissiveTexture after lighting, and a proxy has one
// material. With a baked atlas (which holds base colour x texture) the atlas is also the
// emissive texture and the factor is the area-weighted mean, per channel, of each original's
// emitted colour over its base colour: exact when every original's emission is proportional
// to its base colour (AC3D `emis` drawn through its texture, as TORCS does: factor 1 for
// TORCS' `rgb 0.4 emis 0.4`), a mean otherwise. Without an atlas (vertex colours, which glTF
// does not apply to emission) the factor is the area-weighted mean emitted colour
// (Material::effectiveEmissive), a flat glow. Areas are world areas of the original triangles
// (the linear part of each placement applied).
// Deterministic: sums run in tree order, so nodes with equal bake keys (equal originals, equal
// placements) get equal factors.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/proxy/ProxyMesh.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

// Sums over the originals under a node.
struct ProxyLookSums {
    bool doubleSided = false;
    double area = 0.0;                // m², every original triangle
    glm::dvec3 emissiveOverBase{0.0}; // sum of area x emitted / base colour, per channel
    glm::dvec3 emissive{0.0};         // sum of area x emitted colour

    void add(const ProxyLookSums& other);
};

// The sums of one original instance (all zero but doubleSided when nothing in `scene` emits:
// `withAreas` false skips the triangle walk).
ProxyLookSums instanceLookSums(const Scene& scene, Id instance, bool withAreas);

// Per tree node, the sums over its subtree (leaves: their instance's), for the nodes of
// `postOrder` (children before parents; other entries stay as in `known`, zero when empty:
// a node outside postOrder counts with its entry there).
std::vector<ProxyLookSums> subtreeLookSums(const Scene& scene, const ClusterTree& tree,
                                           const std::vector<Id>& postOrder,
                                           std::vector<ProxyLookSums> known = {});

// Sets proxy.doubleSided and proxy.emissive from `sums`, for the proxy as it is now (with or
// without its atlas).
void applyProxyLook(ProxyMesh& proxy, const ProxyLookSums& sums);

} // namespace hlod
