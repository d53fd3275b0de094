// Aggregation: the input of an inner node's proxy (thesis 5.3: "takes as input the node's
// children"). Leaf children contribute their original mesh instance, inner children their
// proxy, never the whole original subtree again, so the cost of a node does not grow with the
// depth of the tree.
//
// Output: one triangle soup in the node's frame (positions relative to `origin`, or placed by
// the parts' own offsets and linear maps), its error bound the largest of its proxies'
// (ProxyMesh.h; 0 for original meshes; rigid maps keep distances), colours per
// vertex standing in for the replaced materials: Material::effectiveColor() (base colour times
// the mean colour of the base colour texture) times the mesh's own vertex colour. Normals are
// left empty (proxy methods recompute them). Parts whose linear map mirrors (negative
// determinant) have their triangle winding flipped so every part stays outward facing.
// Order: parts in the order given, vertices and triangles in source order (deterministic).
#pragma once

#include <optional>
#include <span>

#include "pipeline/proxy/ProxyMesh.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

// One child's contribution: a scene instance (leaf) or an already baked proxy (inner child).
// `offset`: where the part's own frame (the instance's translation, the proxy's origin) sits
// relative to the node's origin; unset = computed from the world positions. `linear`: the map
// from the part's frame (the instance's mesh, the proxy's frame) into the node's; unset = the
// instance's world linear part, the identity for a proxy. The baker sets both to quantised
// values in the node's frame (BakeFrame.h), so rigid copies of a cluster aggregate to
// identical floats.
struct AggregatePart {
    Id instance = kNoId;              // set for leaf children
    const ProxyMesh* proxy = nullptr; // set for inner children
    std::optional<glm::dvec3> offset = std::nullopt;
    std::optional<glm::dmat3> linear = std::nullopt;
};

ProxyMesh aggregateParts(const Scene& scene, std::span<const AggregatePart> parts,
                         const glm::dvec3& origin);

// Triangle count aggregateParts would produce (for scheduling and statistics).
std::size_t aggregateTriangleCount(const Scene& scene, std::span<const AggregatePart> parts);

} // namespace hlod
