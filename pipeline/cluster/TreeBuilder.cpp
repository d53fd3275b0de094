// ClusterTree construction shared by the clusterers (contract in TreeBuilder.h).
#include "pipeline/cluster/TreeBuilder.h"

#include <algorithm>
#include <string>

#include "pipeline/core/Error.h"

namespace hlod {

Id TreeBuilder::addLeaf(Id instance, const Aabb& exactBox, const ClusterUnit& unit) {
    ClusterNode n;
    n.instance = instance;
    n.box = exactBox;
    nodes_.push_back(std::move(n));
    units_.push_back(unit);
    return static_cast<Id>(nodes_.size() - 1);
}

Id TreeBuilder::addNode(std::vector<Id> children, const ClusterUnit& unit) {
    const Id id = static_cast<Id>(nodes_.size());
    std::sort(children.begin(), children.end());
    for (Id c : children) {
        if (c >= id || nodes_[c].parent != kNoId) {
            throw Error(ErrorCode::InvalidArgument,
                        "cluster tree: node " + std::to_string(c) + " cannot get a parent");
        }
        nodes_[c].parent = id;
    }
    ClusterNode n;
    n.children = std::move(children);
    nodes_.push_back(std::move(n));
    units_.push_back(unit);
    return id;
}

Id TreeBuilder::addFoldedNode(std::vector<Id> children) {
    std::sort(children.begin(), children.end());
    if (children.size() < 2) {
        throw Error(ErrorCode::InvalidArgument, "cluster tree: an inner node needs 2 children");
    }
    ClusterUnit u = units_[children[0]];
    for (std::size_t i = 1; i < children.size(); ++i)
        u = model_.merge(u, units_[children[i]]);
    return addNode(std::move(children), u);
}

ClusterTree TreeBuilder::finish(Id root, VolumeType volume, double k) {
    ClusterTree tree;
    tree.volume = volume;
    tree.k = volume == VolumeType::Aabb ? k : 0.0;
    tree.root = root;
    // Children always have smaller ids than their parent (nodes are appended bottom-up), so
    // one ascending pass sees every child before its parent.
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
        ClusterNode& n = nodes_[i];
        const ClusterUnit& u = units_[i];
        n.sphere = u.sphere;
        n.fill = u.fill();
        n.cost = u.cost;
        if (n.isLeaf()) continue;
        n.box = Aabb{};
        n.level = 0;
        for (Id c : n.children) {
            n.box.expand(nodes_[c].box);
            n.level = std::max(n.level, nodes_[c].level + 1);
        }
    }
    tree.nodes = std::move(nodes_);
    nodes_.clear();
    units_.clear();
    units_.shrink_to_fit();
    return tree;
}

} // namespace hlod
