// Bounding volume hierarchy over the units of one clustering level, for branch-and-bound
// "cheapest partner" queries (LevelMerger.cpp).
//
// Based on the classic median-split BVH (e.g. Ericson, "Real-Time Collision Detection",
// 6.2): top-down, split at the median centroid of the longest axis, leaves of up to four items.
// Each node keeps a box and the largest F*V of the clusters below it, which is what
// CostModel::lowerBound needs. While a level runs, items join groups whose volumes are larger
// than the items': `grow` enlarges the nodes on the item's path to the root so that every node
// still bounds the groups of its items. Bounds only grow (stale groups keep them loose, never
// wrong), which keeps every pruning bound valid.
// The tree shape never changes a query's answer: the search visits every node whose bound does
// not exceed the best cost found, so ties are resolved by the caller's key order alone.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "pipeline/scene/Aabb.h"

namespace hlod {

class MergeBvh {
public:
    struct Node {
        Aabb box;
        double maxFv = 0.0;
        std::uint32_t first = 0;  // leaf: first index into order(); inner: left child
        std::uint32_t second = 0; // inner: right child
        std::uint32_t count = 0;  // leaf: item count; inner: 0
        std::uint32_t parent = 0xffffffffu;
    };

    // Builds over items 0..n-1 with their boxes and F*V values.
    void build(const std::vector<Aabb>& boxes, const std::vector<double>& fv);

    // Makes every node above `item` bound `box` and `fv` too.
    void grow(std::uint32_t item, const Aabb& box, double fv);

    // Best-first descent: `bound(node)` is a lower bound of any answer below the node; nodes
    // whose bound exceeds `threshold` are skipped; `visit(item)` sees every other item and may
    // lower `threshold` (a reference the visitor updates).
    template <class Bound, class Visit>
    void search(Bound&& bound, Visit&& visit, const double& threshold) const;

private:
    std::uint32_t buildRange(std::uint32_t begin, std::uint32_t end,
                             const std::vector<glm::dvec3>& centers, std::uint32_t parent);

    std::vector<Node> nodes_;
    std::vector<std::uint32_t> order_;  // items, leaf ranges contiguous
    std::vector<std::uint32_t> leafOf_; // item -> leaf node
    const std::vector<Aabb>* boxes_ = nullptr;
    const std::vector<double>* fv_ = nullptr;
};

template <class Bound, class Visit>
void MergeBvh::search(Bound&& bound, Visit&& visit, const double& threshold) const {
    if (nodes_.empty()) return;
    // Median splits keep the depth below 40 for any item count that fits in memory; each level
    // pushes at most one deferred sibling.
    struct Entry {
        std::uint32_t node;
        double lb;
    };
    std::array<Entry, 96> stack;
    std::size_t top = 0;
    stack[top++] = Entry{0, bound(nodes_[0])};
    while (top > 0) {
        const Entry e = stack[--top];
        if (e.lb > threshold) continue;
        const Node& n = nodes_[e.node];
        if (n.count > 0) {
            for (std::uint32_t i = n.first; i < n.first + n.count; ++i) visit(order_[i]);
            continue;
        }
        const double lbA = bound(nodes_[n.first]);
        const double lbB = bound(nodes_[n.second]);
        // Push the farther child first so the nearer one is explored first.
        if (lbA <= lbB) {
            if (lbB <= threshold) stack[top++] = Entry{n.second, lbB};
            if (lbA <= threshold) stack[top++] = Entry{n.first, lbA};
        } else {
            if (lbA <= threshold) stack[top++] = Entry{n.first, lbA};
            if (lbB <= threshold) stack[top++] = Entry{n.second, lbB};
        }
    }
}

} // namespace hlod
