// Hand-edit constraints applied by local surgery on the automatic tree (see LocalConstraints.h).
#include "pipeline/cluster/LocalConstraints.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <string>

#include "pipeline/core/Error.h"

namespace hlod {

namespace {

void removeChild(ClusterNode& parent, Id child) {
    auto& c = parent.children;
    c.erase(std::remove(c.begin(), c.end(), child), c.end());
}

// The tree being edited: nodes keep their ids until result() renumbers them; `key` orders
// them (old nodes by id, new ones right after their highest child), `leaves` counts the
// leaves below, `dirty` marks clusters whose children changed (or whose descendants did).
class Surgery {
public:
    explicit Surgery(ClusterTree& tree) : tree_(tree), nodes_(tree.nodes) {
        const std::size_t n = nodes_.size();
        dead_.assign(n, 0);
        dirty_.assign(n, 0);
        count_.assign(n, 0);
        key_.resize(n);
        std::iota(key_.begin(), key_.end(), 0.0);
        leaves_.assign(n, 0);
        for (Id i = 0; i < n; ++i) { // children before parents (TreeBuilder's order)
            const ClusterNode& node = nodes_[i];
            if (node.isLeaf()) {
                leaves_[i] = 1;
                if (node.instance >= leafOf_.size()) leafOf_.resize(node.instance + 1, kNoId);
                leafOf_[node.instance] = i;
            }
            if (node.parent != kNoId) leaves_[node.parent] += leaves_[i];
        }
    }

    void exclude(const std::vector<Id>& instances) {
        for (Id instance : instances) {
            const Id leaf = leafOf_[instance];
            const Id parent = nodes_[leaf].parent;
            if (parent == kNoId) continue; // the only instance of the scene: it is the root
            detach(leaf);
            cleanUp(parent);
            excluded_.push_back(leaf);
        }
    }

    void lock(const std::vector<Id>& members);

    // The root over the excluded leaves and the rest (after every group is placed).
    void placeExcluded() {
        if (excluded_.empty()) return;
        std::vector<Id> top = excluded_;
        if (tree_.root != kNoId) top.push_back(tree_.root);
        tree_.root =
            top.size() == 1 ? top[0] : addNode(std::move(top), std::numeric_limits<double>::max());
    }

    ClusterTree result(const CostModel& model, double minExtent);

private:
    void markUp(Id from, std::size_t leaves, bool add) {
        for (Id a = from; a != kNoId; a = nodes_[a].parent) {
            leaves_[a] = add ? leaves_[a] + leaves : leaves_[a] - leaves;
            dirty_[a] = 1;
        }
    }
    void detach(Id child) {
        const Id parent = nodes_[child].parent;
        removeChild(nodes_[parent], child);
        nodes_[child].parent = kNoId;
        markUp(parent, leaves_[child], false);
    }
    void attach(Id child, Id parent) {
        nodes_[parent].children.push_back(child);
        nodes_[child].parent = parent;
        markUp(parent, leaves_[child], true);
    }
    Id addNode(std::vector<Id> children, double key);
    void cleanUp(Id node);

    ClusterTree& tree_;
    std::vector<ClusterNode>& nodes_;
    std::vector<char> dead_, dirty_;
    std::vector<std::size_t> count_; // members of the group being placed below each node
    std::vector<double> key_;
    std::vector<std::size_t> leaves_;
    std::vector<Id> leafOf_;
    std::vector<Id> excluded_;
};

Id Surgery::addNode(std::vector<Id> children, double key) {
    const Id id = static_cast<Id>(nodes_.size());
    nodes_.emplace_back();
    dead_.push_back(0);
    dirty_.push_back(1);
    count_.push_back(0);
    key_.push_back(key);
    leaves_.push_back(0);
    for (Id c : children) {
        nodes_[id].children.push_back(c);
        nodes_[c].parent = id;
        leaves_[id] += leaves_[c];
    }
    return id;
}

void Surgery::cleanUp(Id node) {
    while (node != kNoId && !dead_[node]) {
        ClusterNode& n = nodes_[node];
        const Id parent = n.parent;
        if (n.children.empty() && n.instance == kNoId) { // a cluster that lost everything
            dead_[node] = 1;
            if (parent != kNoId) {
                removeChild(nodes_[parent], node);
                dirty_[parent] = 1;
            } else {
                tree_.root = kNoId;
            }
            node = parent;
            continue;
        }
        if (n.children.size() == 1 && !n.locked) { // a cluster of one is no cluster
            const Id child = n.children[0];
            dead_[node] = 1;
            n.children.clear();
            nodes_[child].parent = parent;
            if (parent != kNoId) {
                std::replace(nodes_[parent].children.begin(), nodes_[parent].children.end(), node,
                             child);
                dirty_[parent] = 1;
            } else {
                tree_.root = child;
            }
        }
        return;
    }
}

void Surgery::lock(const std::vector<Id>& members) {
    if (members.size() == 1) {
        nodes_[leafOf_[members[0]]].locked = true;
        return;
    }
    std::vector<Id> touched;
    for (Id m : members)
        for (Id a = leafOf_[m]; a != kNoId; a = nodes_[a].parent)
            if (count_[a]++ == 0) touched.push_back(a);
    auto full = [&](Id a) { return count_[a] == leaves_[a]; };
    std::vector<Id> fragments;
    for (Id a : touched)
        if (full(a) && (nodes_[a].parent == kNoId || !full(nodes_[a].parent)))
            fragments.push_back(a);
    Id lca = leafOf_[members[0]];
    while (count_[lca] != members.size())
        lca = nodes_[lca].parent;
    for (Id a : touched)
        count_[a] = 0;
    if (fragments.size() == 1) {
        nodes_[fragments[0]].locked = true;
        return;
    }
    std::sort(fragments.begin(), fragments.end());
    std::vector<Id> clusters;
    std::vector<Id> oldParents;
    for (Id f : fragments) {
        if (!nodes_[f].isLeaf()) clusters.push_back(f);
        oldParents.push_back(nodes_[f].parent);
    }
    Id group = kNoId;
    if (clusters.size() == 1) { // meshes join the one cluster
        group = clusters[0];
        for (Id f : fragments) {
            if (f == group) continue;
            detach(f);
            attach(f, group);
        }
    } else { // a new cluster over the fragments, where they meet
        double key = 0.0;
        for (Id f : fragments) {
            detach(f);
            key = std::max(key, key_[f]);
        }
        group = addNode(fragments, key + 0.5);
        attach(group, lca);
    }
    nodes_[group].locked = true;
    for (Id parent : oldParents)
        cleanUp(parent);
}

ClusterTree Surgery::result(const CostModel& model, double minExtent) {
    std::vector<Id> order;
    for (Id i = 0; i < nodes_.size(); ++i)
        if (!dead_[i]) order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](Id a, Id b) { return key_[a] < key_[b]; });
    std::vector<Id> newId(nodes_.size(), kNoId);
    for (Id i = 0; i < order.size(); ++i)
        newId[order[i]] = i;
    ClusterTree out;
    out.volume = tree_.volume;
    out.k = tree_.k;
    out.root = tree_.root == kNoId ? kNoId : newId[tree_.root];
    out.nodes.resize(order.size());
    std::vector<char> dirty(order.size(), 0);
    for (Id i = 0; i < order.size(); ++i) {
        ClusterNode node = std::move(nodes_[order[i]]);
        dirty[i] = dirty_[order[i]];
        node.parent = node.parent == kNoId ? kNoId : newId[node.parent];
        for (Id& c : node.children) {
            c = newId[c];
            if (c >= i) throw Error(ErrorCode::InvalidArgument, "cluster tree: edit out of order");
        }
        std::sort(node.children.begin(), node.children.end());
        out.nodes[i] = std::move(node);
    }
    // Bounds, fill and cost of the changed clusters: fold the children's clustering units.
    std::vector<ClusterUnit> units(out.nodes.size());
    for (Id i = 0; i < out.nodes.size(); ++i) {
        ClusterNode& n = out.nodes[i];
        ClusterUnit& u = units[i];
        if (n.isLeaf()) {
            u = model.leaf(n.sphere, n.box, minExtent);
            continue;
        }
        if (dirty[i]) {
            u = units[n.children[0]];
            for (std::size_t c = 1; c < n.children.size(); ++c)
                u = model.merge(u, units[n.children[c]]);
            n.sphere = u.sphere;
            n.fill = u.fill();
            n.cost = u.cost;
        } else {
            u.sphere = n.sphere;
            for (Id c : n.children)
                u.box.expand(units[c].box);
            u.volume = model.volume() == VolumeType::Sphere ? n.sphere.volume() : u.box.volume();
            u.fv = n.fill * u.volume;
            u.cost = n.cost;
        }
        n.box = Aabb{};
        n.level = 0;
        for (Id c : n.children) {
            n.box.expand(out.nodes[c].box);
            n.level = std::max(n.level, out.nodes[c].level + 1);
        }
    }
    return out;
}

} // namespace

ClusterTree applyLocalConstraints(ClusterTree tree, const ClusterParams& params,
                                  const CostModel& model, double minExtent) {
    if (tree.root == kNoId) return tree;
    Surgery surgery(tree);
    std::vector<Id> excluded = params.excluded;
    std::sort(excluded.begin(), excluded.end());
    excluded.erase(std::unique(excluded.begin(), excluded.end()), excluded.end());
    surgery.exclude(excluded);
    for (std::vector<Id> group : params.lockedGroups) {
        std::sort(group.begin(), group.end());
        group.erase(std::unique(group.begin(), group.end()), group.end());
        surgery.lock(group);
    }
    surgery.placeExcluded();
    return surgery.result(model, minExtent);
}

} // namespace hlod
