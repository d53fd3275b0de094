// Cluster tree invariant checks (see ClusterValidate.h and ClusterTree.h).
#include "pipeline/cluster/ClusterValidate.h"

#include <algorithm>
#include <vector>

#include "pipeline/bounds/BoundingSphere.h"

namespace hlod {

namespace {

std::string at(Id id, const std::string& what) {
    return "node " + std::to_string(id) + ": " + what;
}

bool boxContains(const Aabb& outer, const Aabb& inner) {
    const double tol = 1e-9 * std::max(1.0, outer.diagonal()) + 1e-9;
    return glm::all(glm::lessThanEqual(outer.min - tol, inner.min)) &&
           glm::all(glm::lessThanEqual(inner.max, outer.max + tol));
}

std::string checkNode(const ClusterTree& tree, Id id, std::size_t instanceCount,
                      std::vector<int>& instanceSeen) {
    const ClusterNode& n = tree.nodes[id];
    if (!(n.fill > 0.0 && n.fill <= 1.0 + 1e-12)) return at(id, "fill outside (0, 1]");
    if (n.isLeaf()) {
        if (n.instance == kNoId || n.instance >= instanceCount) {
            return at(id, "leaf without a valid instance");
        }
        if (instanceSeen[n.instance]++ > 0) {
            return at(id, "instance " + std::to_string(n.instance) + " in two leaves");
        }
        if (n.level != 0) return at(id, "leaf level is not 0");
        return {};
    }
    if (n.instance != kNoId) return at(id, "inner node references an instance");
    int level = 0;
    for (Id c : n.children) {
        if (c >= tree.nodes.size()) return at(id, "child id out of range");
        const ClusterNode& child = tree.nodes[c];
        if (child.parent != id) return at(c, "parent does not match the node listing it");
        if (!boxContains(n.box, child.box)) return at(id, "box does not contain a child");
        if (!sphereContains(n.sphere, child.sphere, 1e-9, 1e-9)) {
            return at(id, "sphere does not contain a child");
        }
        level = std::max(level, child.level + 1);
    }
    if (n.level != level) return at(id, "level is not 1 + max child level");
    return {};
}

} // namespace

std::string validateClusterTree(const ClusterTree& tree, std::size_t instanceCount) {
    if (tree.nodes.empty()) {
        return instanceCount == 0 && tree.root == kNoId ? "" : "empty tree for a scene";
    }
    if (tree.root >= tree.nodes.size()) return "root out of range";
    if (tree.nodes[tree.root].parent != kNoId) return "root has a parent";
    std::vector<int> instanceSeen(instanceCount, 0);
    std::vector<char> visited(tree.nodes.size(), 0);
    std::vector<Id> stack{tree.root};
    std::size_t count = 0;
    while (!stack.empty()) {
        const Id id = stack.back();
        stack.pop_back();
        if (visited[id]) return at(id, "reached twice (a cycle or a shared child)");
        visited[id] = 1;
        ++count;
        if (std::string e = checkNode(tree, id, instanceCount, instanceSeen); !e.empty()) {
            return e;
        }
        for (Id c : tree.nodes[id].children)
            stack.push_back(c);
    }
    if (count != tree.nodes.size()) return "some nodes are not reachable from the root";
    for (std::size_t i = 0; i < instanceCount; ++i) {
        if (instanceSeen[i] == 0) return "instance " + std::to_string(i) + " has no leaf";
    }
    return {};
}

} // namespace hlod
