// Aggregation: the input of an inner node's proxy (thesis 5.3: "takes as input the node's
// children"). Leaf children contribute their original mesh instance, inner children their
// proxy, never the whole original subtree again, so the cost of a node does not grow with the
// depth of the tree.
//
// Output: one triangle soup in the node's frame (positions relative to `origin`), colours per
// vertex standing in for the replaced materials: Material::effectiveColor() (base colour times
// the mean colour of the base colour texture) times the mesh's own vertex colour. Normals are
// left empty (proxy methods recompute them). Instances whose transform mirrors (negative
// determinant) have their triangle winding flipped so every part stays outward facing.
// Order: parts in the order given, vertices and triangles in source order (deterministic).
#pragma once

#include <span>

#include "pipeline/proxy/ProxyMesh.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

// One child's contribution: a scene instance (leaf) or an already baked proxy (inner child).
struct AggregatePart {
    Id instance = kNoId;              // set for leaf children
    const ProxyMesh* proxy = nullptr; // set for inner children
};

ProxyMesh aggregateParts(const Scene& scene, std::span<const AggregatePart> parts,
                         const glm::dvec3& origin);

// Triangle count aggregateParts would produce (for scheduling and statistics).
std::size_t aggregateTriangleCount(const Scene& scene, std::span<const AggregatePart> parts);

} // namespace hlod
