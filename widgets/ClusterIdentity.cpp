// Stable identity of clusters across rebuilds (see ClusterIdentity.h).
#include "widgets/ClusterIdentity.h"

#include <algorithm>

namespace hlod::widgets {

namespace {

// splitmix64's finaliser: spreads consecutive instance ids over all 64 bits.
ClusterKey mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

} // namespace

std::vector<ClusterKey> clusterKeys(const ClusterTree& tree) {
    std::vector<ClusterKey> keys(tree.nodes.size(), 0);
    if (tree.root == kNoId) return keys;
    // Post-order without recursion (ids need not grow toward the root).
    std::vector<std::pair<Id, bool>> stack{{tree.root, false}};
    while (!stack.empty()) {
        const auto [id, expanded] = stack.back();
        stack.pop_back();
        const ClusterNode& n = tree.nodes[id];
        if (n.isLeaf()) {
            keys[id] = mix(n.instance);
        } else if (!expanded) {
            stack.push_back({id, true});
            for (Id c : n.children)
                stack.push_back({c, false});
        } else {
            ClusterKey sum = 0;
            for (Id c : n.children)
                sum += keys[c];
            keys[id] = sum;
        }
    }
    return keys;
}

void ClusterLabels::reset() {
    labels_.clear();
    next_ = 0;
}

std::vector<int> ClusterLabels::assign(const ClusterTree& tree,
                                       const std::vector<ClusterKey>& keys) {
    std::vector<int> out(tree.nodes.size(), -1);
    const bool first = labels_.empty();
    if (first) next_ = static_cast<int>(tree.nodes.size());
    for (Id n = 0; n < tree.nodes.size() && n < keys.size(); ++n) {
        const ClusterNode& node = tree.nodes[n];
        if (node.isLeaf()) {
            out[n] = static_cast<int>(node.instance);
            continue;
        }
        const auto it = labels_.find(keys[n]);
        if (it != labels_.end()) {
            out[n] = it->second;
            continue;
        }
        out[n] = first ? static_cast<int>(n) : next_++;
        labels_.emplace(keys[n], out[n]);
    }
    return out;
}

} // namespace hlod::widgets
