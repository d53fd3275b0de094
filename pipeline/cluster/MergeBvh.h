// Bounding volume hierarchies over the units of one clustering level, for branch-and-bound
// "cheapest partner" queries and the neighbour self-join (LevelMerger.cpp).
//
// Based on the classic median-split BVH (e.g. Ericson, "Real-Time Collision Detection",
// 6.2): top-down, split at the median centroid of the longest axis, leaves of up to four
// items (fewer node pairs in the self-join for a few more item tests; four measured best).
// One hierarchy per size class (the caller's key, e.g. the binary exponent of the radius):
// real scenes mix bolts and floor plates, and a node holding both can bound neither the cost
// of joining a big part (at least its volume) nor that of a small one (low fill), so mixed
// nodes would be visited from everywhere. Within a class the bounds stay tight.
// Each node keeps a Region (CostBounds.h): a box and the aggregates the cost bounds need
// (largest F*V, smallest radius, volume, extents and cross-sections below it), computed
// bottom-up from the children.
// Storage: nodes and items keep their regions packed in single precision, rounded outward
// (CostBounds.h PackedRegion), so every bound computed from them stays a valid lower bound,
// only a little looser. Nodes are laid out depth first (the left child follows its parent), so
// a node is 40 bytes and an item 32 (plus 24 for the per-axis minima, box model only) instead
// of 136: the searches are bound by memory traffic.
// The shape never changes a query's answer: the search visits every node whose bound does
// not exceed the best cost found, so ties are resolved by the caller's key order alone, and
// the self-join reports every pair that its test does not reject, once.
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
        PackedRegion region;
        std::uint32_t first = 0; // leaf: first index into order_; inner: right child (the left
                                 // child is the next node)
        std::uint32_t count = 0; // leaf: item count; inner: 0
    };

    // Builds one hierarchy per distinct `sizeClass` over items 0..n-1. `boxModel`: the regions
    // are the box model's, whose bounds read the per-axis minima (CostBounds.h).
    void build(const std::vector<Region>& items, const std::vector<int>& sizeClass, bool boxModel);

    // Best-first descent: `bound(region)` (a PackedRef) is a lower bound of any answer below a
    // node; nodes whose bound exceeds `threshold` are skipped; `visit(item)` sees every other
    // item and may lower `threshold` (a reference the visitor updates).
    template <class Bound, class Visit>
    void search(Bound&& bound, Visit&& visit, const double& threshold) const;

    // Self-join: calls visit(i, j) once for every unordered pair of distinct items whose
    // packed regions (and those of the nodes holding them) are not separated by
    // `exceeds(a, b)` (PackedRefs; a lower bound above the threshold). Dual-tree traversal, so
    // the descent is shared by all items instead of one per item.
    template <class Exceeds, class Visit> void join(Exceeds&& exceeds, Visit&& visit) const {
        for (std::size_t i = 0; i < roots_.size(); ++i) {
            for (std::size_t j = i; j < roots_.size(); ++j) {
                joinNodes(roots_[i], roots_[j], exceeds, visit);
            }
        }
    }

private:
    PackedRef nodeRef(std::uint32_t n) const {
        return PackedRef{&nodes_[n].region, boxModel_ ? &nodeExtra_[n] : nullptr};
    }
    PackedRef itemRef(std::uint32_t i) const {
        return PackedRef{&ordered_[i], boxModel_ ? &orderedExtra_[i] : nullptr};
    }

    template <class Exceeds, class Visit>
    void joinNodes(std::uint32_t a, std::uint32_t b, Exceeds& exceeds, Visit& visit) const;
    template <class Exceeds, class Visit>
    void joinItem(std::uint32_t i, std::uint32_t node, Exceeds& exceeds, Visit& visit) const;

    std::uint32_t buildRange(std::uint32_t begin, std::uint32_t end,
                             const std::vector<Region>& items,
                             const std::vector<glm::dvec3>& centers);

    bool boxModel_ = false;
    std::vector<Node> nodes_;
    std::vector<PackedExtra> nodeExtra_; // box model: per node
    std::vector<std::uint32_t> roots_;
    std::vector<std::uint32_t> order_;      // items, leaf ranges contiguous
    std::vector<PackedRegion> ordered_;     // the items' regions in order_ (contiguous leaves)
    std::vector<PackedExtra> orderedExtra_; // box model: per item in order_
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
        roots[i] = {bound(nodeRef(roots_[i])), roots_[i]};
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
            const std::uint32_t left = e.node + 1;
            const double lbA = bound(nodeRef(left));
            const double lbB = bound(nodeRef(n.first));
            // Push the farther child first so the nearer one is explored first.
            const bool aFirst = lbA <= lbB;
            const Entry near{aFirst ? left : n.first, aFirst ? lbA : lbB};
            const Entry far{aFirst ? n.first : left, aFirst ? lbB : lbA};
            if (far.lb <= threshold) stack[top++] = far;
            if (near.lb <= threshold) stack[top++] = near;
        }
    }
}

template <class Exceeds, class Visit>
void MergeBvh::joinNodes(std::uint32_t a, std::uint32_t b, Exceeds& exceeds, Visit& visit) const {
    const Node& A = nodes_[a];
    const Node& B = nodes_[b];
    if (exceeds(nodeRef(a), nodeRef(b))) return;
    if (A.count > 0 && B.count > 0) {
        for (std::uint32_t i = A.first; i < A.first + A.count; ++i) {
            const PackedRef ri = itemRef(i);
            const std::uint32_t from = a == b ? i + 1 : B.first;
            for (std::uint32_t j = from; j < B.first + B.count; ++j) {
                if (!exceeds(ri, itemRef(j))) visit(order_[i], order_[j]);
            }
        }
        return;
    }
    if (A.count > 0 || B.count > 0) {
        // A leaf against a subtree: each of the leaf's items descends on its own, because the
        // leaf's region spans the space between its items (wide in a sparse size class) and
        // would keep every node in between.
        const Node& leaf = A.count > 0 ? A : B;
        const std::uint32_t tree = A.count > 0 ? b : a;
        for (std::uint32_t i = leaf.first; i < leaf.first + leaf.count; ++i) {
            joinItem(i, tree, exceeds, visit);
        }
        return;
    }
    const std::uint32_t aRight = A.first, bRight = B.first;
    if (a == b) {
        joinNodes(a + 1, a + 1, exceeds, visit);
        joinNodes(a + 1, aRight, exceeds, visit);
        joinNodes(aRight, aRight, exceeds, visit);
        return;
    }
    // Split the larger node.
    auto diagonal2 = [](const PackedRegion& r) {
        const float x = r.hi[0] - r.lo[0], y = r.hi[1] - r.lo[1], z = r.hi[2] - r.lo[2];
        return x * x + y * y + z * z;
    };
    if (diagonal2(A.region) >= diagonal2(B.region)) {
        joinNodes(a + 1, b, exceeds, visit);
        joinNodes(aRight, b, exceeds, visit);
    } else {
        joinNodes(a, b + 1, exceeds, visit);
        joinNodes(a, bRight, exceeds, visit);
    }
}

template <class Exceeds, class Visit>
void MergeBvh::joinItem(std::uint32_t i, std::uint32_t node, Exceeds& exceeds, Visit& visit) const {
    const PackedRef ri = itemRef(i);
    // Depth-first over the subtree with an explicit stack (depth < 40, see search()).
    std::array<std::uint32_t, 64> stack;
    std::size_t top = 0;
    stack[top++] = node;
    while (top > 0) {
        const std::uint32_t n = stack[--top];
        const Node& N = nodes_[n];
        if (exceeds(ri, nodeRef(n))) continue;
        if (N.count > 0) {
            for (std::uint32_t j = N.first; j < N.first + N.count; ++j) {
                if (!exceeds(ri, itemRef(j))) visit(order_[i], order_[j]);
            }
            continue;
        }
        stack[top++] = N.first;
        stack[top++] = n + 1;
    }
}

} // namespace hlod
