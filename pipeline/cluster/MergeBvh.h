// Bounding volume hierarchies over the units of one clustering level, for branch-and-bound
// "cheapest partner" queries (LevelMerger.cpp).
//
// Based on the classic median-split BVH (e.g. Ericson, "Real-Time Collision Detection",
// 6.2): top-down, split at the median centroid of the longest axis, leaves of up to two items.
// One hierarchy per size class (the caller's key, e.g. the binary exponent of the radius):
// real scenes mix bolts and floor plates, and a node holding both can bound neither the cost
// of joining a big part (at least its volume) nor that of a small one (low fill), so mixed
// nodes would be visited from everywhere. Within a class the bounds stay tight.
// Each node keeps a Region (CostBounds.h): a box and the aggregates the cost bounds need
// (largest F*V, smallest radius, volume, extents and cross-sections below it), computed
// bottom-up from the children.
// The shape never changes a query's answer: the search visits every node whose bound does
// not exceed the best cost found, so ties are resolved by the caller's key order alone.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "pipeline/cluster/CostBounds.h"
#include "pipeline/scene/Aabb.h"

namespace hlod {

class MergeBvh {
public:
    struct Node {
        Region region;
        std::uint32_t first = 0;  // leaf: first index into order_; inner: left child
        std::uint32_t second = 0; // inner: right child
        std::uint32_t count = 0;  // leaf: item count; inner: 0
    };

    // Builds one hierarchy per distinct `sizeClass` over items 0..n-1.
    void build(const std::vector<Region>& items, const std::vector<int>& sizeClass);

    // Best-first descent: `bound(region)` is a lower bound of any answer below a node; nodes
    // whose bound exceeds `threshold` are skipped; `visit(item)` sees every other item and may
    // lower `threshold` (a reference the visitor updates).
    template <class Bound, class Visit>
    void search(Bound&& bound, Visit&& visit, const double& threshold) const;

    // Self-join: calls visit(i, ri, j, rj) (items and their regions) once for every unordered
    // pair of distinct items whose nodes are not separated by `exceeds(regionA, regionB)`
    // (a lower bound above the threshold). Dual-tree traversal, so the descent is shared by
    // all items instead of one per item.
    template <class Exceeds, class Visit> void join(Exceeds&& exceeds, Visit&& visit) const {
        for (std::size_t i = 0; i < roots_.size(); ++i) {
            for (std::size_t j = i; j < roots_.size(); ++j) {
                joinNodes(roots_[i], roots_[j], exceeds, visit);
            }
        }
    }

private:
    template <class Exceeds, class Visit>
    void joinNodes(std::uint32_t a, std::uint32_t b, Exceeds& exceeds, Visit& visit) const;

    std::uint32_t buildRange(std::uint32_t begin, std::uint32_t end,
                             const std::vector<Region>& items,
                             const std::vector<glm::dvec3>& centers);

    std::vector<Node> nodes_;
    std::vector<std::uint32_t> roots_;
    std::vector<std::uint32_t> order_; // items, leaf ranges contiguous
    std::vector<Region> ordered_;      // the items' regions in order_ (contiguous leaves)
};

template <class Bound, class Visit>
void MergeBvh::search(Bound&& bound, Visit&& visit, const double& threshold) const {
    // Hierarchies in increasing order of their root bound: the likely answers come first and
    // lower the threshold for the rest.
    std::array<std::pair<double, std::uint32_t>, 64> local;
    std::vector<std::pair<double, std::uint32_t>> heapRoots;
    std::pair<double, std::uint32_t>* roots = local.data();
    if (roots_.size() > local.size()) {
        heapRoots.resize(roots_.size());
        roots = heapRoots.data();
    }
    for (std::size_t i = 0; i < roots_.size(); ++i) {
        roots[i] = {bound(nodes_[roots_[i]].region), roots_[i]};
    }
    std::sort(roots, roots + roots_.size());
    // Median splits keep each depth below 40 for any item count that fits in memory; each
    // level pushes at most one deferred sibling.
    struct Entry {
        std::uint32_t node;
        double lb;
    };
    std::array<Entry, 96> stack;
    for (std::size_t r = 0; r < roots_.size(); ++r) {
        const auto [rootBound, root] = roots[r];
        if (rootBound > threshold) break;
        std::size_t top = 0;
        stack[top++] = Entry{root, rootBound};
        while (top > 0) {
            const Entry e = stack[--top];
            if (e.lb > threshold) continue;
            const Node& n = nodes_[e.node];
            if (n.count > 0) {
                for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
                    visit(order_[i]);
                }
                continue;
            }
            const double lbA = bound(nodes_[n.first].region);
            const double lbB = bound(nodes_[n.second].region);
            // Push the farther child first so the nearer one is explored first.
            const bool aFirst = lbA <= lbB;
            const Entry near{aFirst ? n.first : n.second, aFirst ? lbA : lbB};
            const Entry far{aFirst ? n.second : n.first, aFirst ? lbB : lbA};
            if (far.lb <= threshold) stack[top++] = far;
            if (near.lb <= threshold) stack[top++] = near;
        }
    }
}

template <class Exceeds, class Visit>
void MergeBvh::joinNodes(std::uint32_t a, std::uint32_t b, Exceeds& exceeds, Visit& visit) const {
    const Node& A = nodes_[a];
    const Node& B = nodes_[b];
    if (exceeds(A.region, B.region)) return;
    if (A.count > 0 && B.count > 0) {
        for (std::uint32_t i = A.first; i < A.first + A.count; ++i) {
            const std::uint32_t from = a == b ? i + 1 : B.first;
            for (std::uint32_t j = from; j < B.first + B.count; ++j) {
                if (!exceeds(ordered_[i], ordered_[j])) {
                    visit(order_[i], order_[j]);
                }
            }
        }
        return;
    }
    if (a == b) {
        joinNodes(A.first, A.first, exceeds, visit);
        joinNodes(A.first, A.second, exceeds, visit);
        joinNodes(A.second, A.second, exceeds, visit);
        return;
    }
    // Split the larger node (a leaf cannot split).
    const glm::dvec3 ea = A.region.box.max - A.region.box.min;
    const glm::dvec3 eb = B.region.box.max - B.region.box.min;
    const bool splitA = A.count == 0 && (B.count > 0 || glm::dot(ea, ea) >= glm::dot(eb, eb));
    if (splitA) {
        joinNodes(A.first, b, exceeds, visit);
        joinNodes(A.second, b, exceeds, visit);
    } else {
        joinNodes(a, B.first, exceeds, visit);
        joinNodes(a, B.second, exceeds, visit);
    }
}

} // namespace hlod
