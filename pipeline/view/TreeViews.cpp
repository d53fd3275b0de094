// Read-only views of a ClusterTree (see TreeViews.h).
#include "pipeline/view/TreeViews.h"

#include <algorithm>

namespace hlod {

namespace {

// Nodes of the tree, parents before children (iterative: trees can be thousands deep).
std::vector<Id> preorder(const ClusterTree& tree) {
    std::vector<Id> order;
    if (tree.root == kNoId || tree.root >= tree.nodes.size()) return order;
    order.reserve(tree.nodes.size());
    std::vector<Id> stack{tree.root};
    while (!stack.empty()) {
        const Id n = stack.back();
        stack.pop_back();
        order.push_back(n);
        const auto& children = tree.nodes[n].children;
        for (auto it = children.rbegin(); it != children.rend(); ++it)
            stack.push_back(*it);
    }
    return order;
}

} // namespace

std::vector<Id> nodesAtLevel(const ClusterTree& tree, int level) {
    level = std::max(level, 0);
    std::vector<Id> cut;
    for (Id n : preorder(tree)) {
        const ClusterNode& node = tree.nodes[n];
        if (node.level > level) continue;
        if (node.parent == kNoId || tree.nodes[node.parent].level > level) cut.push_back(n);
    }
    std::sort(cut.begin(), cut.end());
    return cut;
}

std::vector<int> clusterOfInstances(const ClusterTree& tree, const std::vector<Id>& cut,
                                    std::size_t instanceCount) {
    std::vector<int> out(instanceCount, -1);
    std::vector<int> cutIndex(tree.nodes.size(), -1);
    for (std::size_t i = 0; i < cut.size(); ++i)
        if (cut[i] < tree.nodes.size()) cutIndex[cut[i]] = static_cast<int>(i);
    // Parents come first in preorder: a node inherits its parent's cut index unless it is a
    // cut node itself.
    std::vector<int> inherited(tree.nodes.size(), -1);
    for (Id n : preorder(tree)) {
        const ClusterNode& node = tree.nodes[n];
        const int fromParent = node.parent == kNoId ? -1 : inherited[node.parent];
        inherited[n] = cutIndex[n] >= 0 ? cutIndex[n] : fromParent;
        if (node.isLeaf() && node.instance < instanceCount) out[node.instance] = inherited[n];
    }
    return out;
}

std::vector<int> nodeDepths(const ClusterTree& tree) {
    std::vector<int> depth(tree.nodes.size(), 0);
    for (Id n : preorder(tree)) {
        const Id parent = tree.nodes[n].parent;
        depth[n] = parent == kNoId ? 0 : depth[parent] + 1;
    }
    return depth;
}

std::vector<Id> instancesBelow(const ClusterTree& tree, Id node) {
    std::vector<Id> out;
    if (node >= tree.nodes.size()) return out;
    std::vector<Id> stack{node};
    while (!stack.empty()) {
        const Id n = stack.back();
        stack.pop_back();
        const ClusterNode& c = tree.nodes[n];
        if (c.isLeaf()) {
            if (c.instance != kNoId) out.push_back(c.instance);
            continue;
        }
        for (auto it = c.children.rbegin(); it != c.children.rend(); ++it)
            stack.push_back(*it);
    }
    return out;
}

Id leafOfInstance(const ClusterTree& tree, Id instance) {
    if (instance == kNoId) return kNoId;
    for (Id n = 0; n < tree.nodes.size(); ++n)
        if (tree.nodes[n].isLeaf() && tree.nodes[n].instance == instance) return n;
    return kNoId;
}

bool isInSubtree(const ClusterTree& tree, Id node, Id ancestor) {
    if (ancestor >= tree.nodes.size()) return false;
    for (Id n = node; n < tree.nodes.size(); n = tree.nodes[n].parent)
        if (n == ancestor) return true;
    return false;
}

} // namespace hlod
