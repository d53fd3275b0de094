// Small helpers of the cluster tree (ClusterTree.h).
#include "pipeline/cluster/ClusterTree.h"

#include <algorithm>

#include "pipeline/core/Error.h"

namespace hlod {

const char* toString(VolumeType v) {
    switch (v) {
    case VolumeType::Sphere:
        return "sphere";
    case VolumeType::Aabb:
        return "aabb";
    case VolumeType::Octree:
        return "octree";
    case VolumeType::Original:
        return "original";
    }
    return "unknown";
}

VolumeType volumeTypeFromString(const std::string& s) {
    for (VolumeType v :
         {VolumeType::Sphere, VolumeType::Aabb, VolumeType::Octree, VolumeType::Original}) {
        if (s == toString(v)) return v;
    }
    throw Error(ErrorCode::InvalidArgument,
                "unknown volume type '" + s + "' (expected sphere, aabb, octree or original)");
}

std::size_t ClusterTree::leafCount() const {
    std::size_t n = 0;
    for (const ClusterNode& node : nodes)
        n += node.isLeaf() ? 1 : 0;
    return n;
}

std::vector<Id> childrenFirst(const ClusterTree& tree, const std::vector<Id>& roots) {
    std::vector<Id> order, stack(roots.rbegin(), roots.rend());
    while (!stack.empty()) {
        const Id id = stack.back();
        stack.pop_back();
        order.push_back(id);
        for (Id c : tree.nodes[id].children)
            stack.push_back(c);
    }
    std::reverse(order.begin(), order.end());
    return order;
}

std::vector<std::uint64_t> subtreeTriangles(const ClusterTree& tree, const Scene& scene) {
    std::vector<std::uint64_t> tris(tree.nodes.size(), 0);
    if (tree.root == kNoId) return tris;
    for (Id id : childrenFirst(tree, {tree.root})) { // every child complete before its parent
        const ClusterNode& node = tree.nodes[id];
        if (node.isLeaf() && node.instance < scene.instances.size())
            tris[id] = scene.meshes[scene.instances[node.instance].mesh].triangleCount();
        if (node.parent != kNoId) tris[node.parent] += tris[id];
    }
    return tris;
}

void leavesBelow(const ClusterTree& tree, Id id, std::vector<Id>& out) {
    if (tree.nodes[id].isLeaf()) {
        out.push_back(id);
        return;
    }
    for (Id c : tree.nodes[id].children)
        leavesBelow(tree, c, out);
}

} // namespace hlod
