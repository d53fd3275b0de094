// The HLOD hierarchy produced by every clusterer (thesis ch. 3-4) and consumed by proxy
// baking, LOD selection, export and the editor.
//
// Invariants (checked by validateClusterTree in tests):
// - nodes[root] has no parent; every other node has exactly one parent listing it as a child.
// - A leaf references exactly one mesh instance of the scene (`instance`); inner nodes
//   reference none (they get proxies). Every scene instance appears in exactly one leaf.
// - Bounds of a node contain the bounds of all its descendants (AABB and sphere).
// - level: leaves are 0; an inner node's level is 1 + max level of its children.
// Units: metres, world space of the scene.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "pipeline/bounds/Sphere.h"
#include "pipeline/scene/Aabb.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

enum class VolumeType { Sphere, Aabb, Octree, Original };

const char* toString(VolumeType v);
// Parses "sphere", "aabb", "octree", "original"; throws Error(InvalidArgument) otherwise.
VolumeType volumeTypeFromString(const std::string& s);

struct ClusterNode {
    Id parent = kNoId;
    std::vector<Id> children;
    Id instance = kNoId; // leaves only: the scene's MeshInstance id
    Aabb box;            // world AABB of everything below
    Sphere sphere;       // bounding sphere of everything below
    double fill = 1.0;   // fill factor F in (0, 1]; 1 for leaves
    double cost = 0.0;   // clustering cost of this node under the tree's volume type
    int level = 0;       // 0 for leaves
    bool locked = false; // hand edit: kept whole when clustering reruns
    bool isLeaf() const { return children.empty(); }
};

struct ClusterTree {
    std::vector<ClusterNode> nodes;
    Id root = kNoId;
    VolumeType volume = VolumeType::Sphere;
    double k = 0.0; // AABB proportion constraint used (0 for other volume types)

    std::size_t leafCount() const;
    int height() const { return root == kNoId ? 0 : nodes[root].level; }
};

// The nodes of the subtrees under `roots` (the whole tree: {tree.root}), every child before its
// parent (iterative: trees can be deep).
std::vector<Id> childrenFirst(const ClusterTree& tree, const std::vector<Id>& roots);

// Appends the leaves below node `id` (itself when it is a leaf) to `out`, in child order.
void leavesBelow(const ClusterTree& tree, Id id, std::vector<Id>& out);

// Original triangles below every node (instanced: a mesh placed twice counts twice), the sum
// over the leaves of the subtree (a leaf whose instance `scene` lacks counts 0).
std::vector<std::uint64_t> subtreeTriangles(const ClusterTree& tree, const Scene& scene);

} // namespace hlod
