// Exact comparison of two cluster trees for the clustering tests: structure and every value,
// bit for bit (the fast and naive clusterers evaluate the same CostModel arithmetic in the
// same operand order, so equal trees have equal doubles, not just close ones).
#pragma once

#include <string>

#include "pipeline/cluster/ClusterTree.h"

namespace hlod::test {

// Empty when equal, else the first difference.
inline std::string treeDifference(const ClusterTree& a, const ClusterTree& b) {
    if (a.nodes.size() != b.nodes.size()) {
        return "node count " + std::to_string(a.nodes.size()) + " vs " +
               std::to_string(b.nodes.size());
    }
    if (a.root != b.root) return "root differs";
    if (a.volume != b.volume || a.k != b.k) return "volume type or k differs";
    for (std::size_t i = 0; i < a.nodes.size(); ++i) {
        const ClusterNode& x = a.nodes[i];
        const ClusterNode& y = b.nodes[i];
        const std::string at = "node " + std::to_string(i) + ": ";
        if (x.parent != y.parent) return at + "parent differs";
        if (x.children != y.children) return at + "children differ";
        if (x.instance != y.instance) return at + "instance differs";
        if (x.level != y.level) return at + "level differs";
        if (x.locked != y.locked) return at + "locked differs";
        if (x.box.min != y.box.min || x.box.max != y.box.max) return at + "box differs";
        if (x.sphere.center != y.sphere.center || x.sphere.radius != y.sphere.radius) {
            return at + "sphere differs";
        }
        if (x.fill != y.fill) return at + "fill differs";
        if (x.cost != y.cost) return at + "cost differs";
    }
    return {};
}

} // namespace hlod::test
