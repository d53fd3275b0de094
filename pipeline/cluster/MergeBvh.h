// Bounding volume hierarchy over the units of one clustering level, for branch-and-bound
// "cheapest partner" queries and the neighbour self-join (LevelMerger.cpp).
//
// A 4-wide BVH: every node has four slots, each holding either one item or a child node, and
// keeps the four slots' regions side by side (WideBounds.h), so one node test bounds the cost
// against all four at once in SIMD lanes, without a branch per slot. Built top-down like the
// classic median-split BVH (e.g. Ericson, "Real-Time Collision Detection", 6.2), two median
// splits per node (the longest axis of the centroids, then each half's longest axis): a
// range of five or more items becomes four parts, a range of two to four items a node of item
// slots. Wide nodes (as in Embree's BVH4) halve the depth and replace the branchy node-by-node
// recursion of a binary tree by one vector test per node.
// One hierarchy per size class (the caller's key, e.g. the binary exponent of the radius):
// real scenes mix bolts and floor plates, and a node holding both can bound neither the cost
// of joining a big part (at least its volume) nor that of a small one (low fill), so mixed
// nodes would be visited from everywhere. Within a class the bounds stay tight. The class
// hierarchies hang from one top (slots grouped four by four in class order), so every query
// starts at one node.
// Each slot keeps a Region (CostBounds.h): a box and the aggregates the cost bounds need
// (largest F*V, smallest radius, volume, extents and cross-sections below it), computed
// bottom-up in double precision and stored packed in single precision rounded outward
// (PackedRegion), so every bound computed from them stays a valid lower bound, only a little
// looser. A node is four cache lines.
// The shape never changes a query's answer: the search visits every slot whose bound does not
// exceed the best cost found, so ties are resolved by the caller's key order alone, and the
// self-join reports every pair that its test does not reject, once.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "pipeline/cluster/WideBounds.h"

namespace hlod {

class MergeBvh {
public:
    struct alignas(64) Node {
        WideRegions slots{};
        std::uint32_t child[4] = {}; // kItem | the item's position, or a node index
        std::uint32_t end[4] = {};   // one past the last item position below the slot; 0: unused
    };
    static constexpr std::uint32_t kItem = 0x80000000u;

    // Builds the hierarchy over items 0..n-1 with their regions and size classes, for the
    // bounds of `model` (which must outlive the queries).
    void build(const std::vector<Region>& items, const std::vector<int>& sizeClass,
               const CostModel& model);

    // Cheapest-partner search for item `self`: nearest slots first, skipping every slot whose
    // lower bound exceeds `threshold`; `visit(item)` sees every other item not skipped (and
    // may see `self`) and may lower `threshold` (a reference the visitor updates).
    template <class Visit>
    void search(std::uint32_t self, const double& threshold, Visit&& visit) const;

    // Self-join: calls visit(i, j) once for every unordered pair of distinct items whose
    // pair bound (and those of the slots holding them) does not exceed `threshold`.
    // Dual-tree: the hierarchy's own nodes are the query groups. A group tests the target
    // lanes its parent kept, opens the target nodes at least as large as itself and keeps the
    // rest for its parts; an item finally descends what its group kept. Only slots holding
    // items after the query's first item (in the hierarchy's order) are tested, so each pair
    // is met once, from its first item.
    template <class Visit> void join(double threshold, Visit&& visit) const;

private:
    // A target node and the lanes of it still to test.
    struct Entry {
        std::uint32_t node;
        unsigned mask;
    };
    using JoinScratch = std::vector<std::vector<Entry>>; // one list per query depth
    static constexpr std::size_t kMaxDepth = 64;

    template <class Visit>
    void joinGroup(const PackedRegion& region, const PackedExtra& extra, std::uint32_t q,
                   std::uint32_t begin, const std::vector<Entry>& targets, std::size_t depth,
                   double threshold, Visit& visit, JoinScratch& scratch) const;
    template <class Visit>
    void joinItem(std::uint32_t p, const std::vector<Entry>& targets, double threshold,
                  Visit& visit) const;
    // Lanes holding an item after position p (each pair is met from its first item only).
    static unsigned laterThan(const Node& node, std::uint32_t p) {
        unsigned out = 0;
        for (int l = 0; l < 4; ++l)
            out |= node.end[l] > p + 1 ? 1u << l : 0u;
        return out;
    }
    static double diagonal2(const PackedRegion& r) {
        double d = 0.0;
        for (int i = 0; i < 3; ++i) {
            const double x = static_cast<double>(r.hi[i]) - r.lo[i];
            d += x * x;
        }
        return d;
    }
    static double laneDiagonal2(const WideRegions& w, int l) {
        double d = 0.0;
        for (int i = 0; i < 3; ++i) {
            const double x = static_cast<double>(w.hi[i][l]) - w.lo[i][l];
            d += x * x;
        }
        return d;
    }

    struct Slot {
        std::uint32_t child;
        std::uint32_t end;
        Region region;
    };

    WideQuery queryOf(std::uint32_t position) const {
        return WideQuery(*model_, packed_[position], packedExtra_[position]);
    }
    Slot buildRange(std::uint32_t begin, std::uint32_t end, const std::vector<Region>& items,
                    const std::vector<glm::dvec3>& centers);
    Slot makeNode(const Slot* parts, std::size_t count);
    std::uint32_t medianSplit(std::uint32_t begin, std::uint32_t end,
                              const std::vector<glm::dvec3>& centers);

    const CostModel* model_ = nullptr;
    std::vector<Node> nodes_;
    std::uint32_t root_ = 0;    // valid when nodes_ is not empty
    PackedRegion rootRegion_{}; // the region of everything
    PackedExtra rootExtra_{};
    std::vector<std::uint32_t> order_;     // position -> item; leaf ranges contiguous
    std::vector<std::uint32_t> position_;  // item -> position
    std::vector<PackedRegion> packed_;     // by position
    std::vector<PackedExtra> packedExtra_; // by position (box model)
};

// Depth: median splits into four make a class hierarchy at most 17 levels deep (log4 of 2^32
// items, plus the item) and the tops above them add log4 of the class count (at most 6 for
// the 2,100 binary exponents of a double), so a descent's stack (at most four slots pushed per
// node popped) fits in 128 entries and the join's group recursion in kMaxDepth levels.
template <class Visit>
void MergeBvh::search(std::uint32_t self, const double& threshold, Visit&& visit) const {
    if (nodes_.empty()) return;
    const WideQuery q = queryOf(position_[self]);
    struct Pending {
        std::uint32_t node;
        double lb;
    };
    std::array<Pending, 128> stack;
    std::size_t top = 0;
    stack[top++] = Pending{root_, 0.0};
    while (top > 0) {
        const Pending e = stack[--top];
        if (e.lb > threshold) continue;
        const Node& n = nodes_[e.node];
        double lb[4];
        q.bounds(n.slots, lb);
        // Lanes in ascending bound order (insertion sort of at most four).
        int lane[4];
        int used = 0;
        for (int l = 0; l < 4; ++l) {
            if (n.end[l] == 0) continue;
            int at = used++;
            while (at > 0 && lb[lane[at - 1]] > lb[l]) {
                lane[at] = lane[at - 1];
                --at;
            }
            lane[at] = l;
        }
        // Items at once, nearest first; nodes pushed farthest first so the nearest pops next.
        for (int i = 0; i < used; ++i) {
            const int l = lane[i];
            if ((n.child[l] & kItem) != 0 && lb[l] <= threshold) visit(order_[n.child[l] & ~kItem]);
        }
        for (int i = used - 1; i >= 0; --i) {
            const int l = lane[i];
            if ((n.child[l] & kItem) == 0 && lb[l] <= threshold)
                stack[top++] = Pending{n.child[l], lb[l]};
        }
    }
}

template <class Visit> void MergeBvh::join(double threshold, Visit&& visit) const {
    if (nodes_.empty()) return;
    JoinScratch scratch(kMaxDepth);
    const std::vector<Entry> all{Entry{root_, 0xfu}};
    joinGroup(rootRegion_, rootExtra_, root_, 0, all, 0, threshold, visit, scratch);
}

template <class Visit>
void MergeBvh::joinGroup(const PackedRegion& region, const PackedExtra& extra, std::uint32_t q,
                         std::uint32_t begin, const std::vector<Entry>& targets, std::size_t depth,
                         double threshold, Visit& visit, JoinScratch& scratch) const {
    const WideQuery query(*model_, region, extra);
    const double size = diagonal2(region);
    // The targets' lanes this group may still pair with; a node lane at least as large as the
    // group is opened here, a smaller one is left for the group's parts to test.
    std::vector<Entry>& kept = scratch[depth];
    kept.clear();
    std::array<Entry, 128> stack;
    for (const Entry& target : targets) {
        std::size_t top = 0;
        stack[top++] = target;
        while (top > 0) {
            const Entry e = stack[--top];
            const Node& node = nodes_[e.node];
            const unsigned keep =
                e.mask & laterThan(node, begin) & ~query.exceeds(node.slots, threshold);
            unsigned open = 0;
            for (unsigned m = keep; m != 0; m &= m - 1) {
                const int l = __builtin_ctz(m);
                if ((node.child[l] & kItem) == 0 && laneDiagonal2(node.slots, l) > size) {
                    open |= 1u << l;
                    stack[top++] = Entry{node.child[l], 0xfu};
                }
            }
            if ((keep & ~open) != 0) kept.push_back(Entry{e.node, keep & ~open});
        }
    }
    const Node& group = nodes_[q];
    for (int l = 0; l < 4 && group.end[l] != 0; ++l) {
        const std::uint32_t c = group.child[l];
        if ((c & kItem) != 0) {
            joinItem(c & ~kItem, kept, threshold, visit);
            continue;
        }
        PackedRegion r{};
        PackedExtra e{};
        getLane(group.slots, l, r, e);
        joinGroup(r, e, c, l == 0 ? begin : group.end[l - 1], kept, depth + 1, threshold, visit,
                  scratch);
    }
}

template <class Visit>
void MergeBvh::joinItem(std::uint32_t p, const std::vector<Entry>& targets, double threshold,
                        Visit& visit) const {
    const WideQuery query = queryOf(p);
    std::array<Entry, 128> stack;
    for (const Entry& target : targets) {
        std::size_t top = 0;
        stack[top++] = target;
        while (top > 0) {
            const Entry e = stack[--top];
            const Node& node = nodes_[e.node];
            unsigned keep = e.mask & laterThan(node, p) & ~query.exceeds(node.slots, threshold);
            for (; keep != 0; keep &= keep - 1) {
                const std::uint32_t c = node.child[__builtin_ctz(keep)];
                if ((c & kItem) != 0) {
                    visit(order_[p], order_[c & ~kItem]);
                } else {
                    stack[top++] = Entry{c, 0xfu};
                }
            }
        }
    }
}

} // namespace hlod
