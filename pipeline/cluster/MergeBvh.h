// Bounding volume hierarchy over the units of one clustering level, for branch-and-bound
// "cheapest partner" queries and the neighbour self-join (LevelMerger.cpp).
//
// A 4-wide BVH: every node has four slots, each holding either one item or a child node, and
// keeps the four slots' regions side by side (WideBounds.h), so one node test bounds the cost
// against all four at once in SIMD lanes, without a branch per slot. Built top-down from the
// Morton order of the items' centres (Morton.h), as the radix-tree builders of Karras
// ("Maximizing parallelism in the construction of BVHs, octrees, and k-d trees", HPG 2012) do:
// a range of items sorted by code splits where the highest bit in which its first and last
// codes differ turns on, which is the plane between two octree cells, and a range of equal
// codes in the middle. Two splits per node (each half split again unless it is one item): a
// range of five or more items becomes up to four parts, a range of two to four items a node
// of item slots. A level's units come in Morton order already (LevelMerger.cpp), so the build
// is a binary search per split and linear in the items, where median splits along the longest
// axis (the classic top-down build, Ericson, "Real-Time Collision Detection", 6.2) selected a
// median over every range, three times per node. The items under a node lie in one octree
// cell (splits of the curve at equal counts put far apart items together where the curve
// jumps), and the self-join over this shape runs 9 % fewer instructions than over the median
// splits' (docs/benchmarks.md, round 7).
// Wide nodes (as in Embree's BVH4) halve the depth and replace the branchy node-by-node
// recursion of a binary tree by one vector test per node. The queries exist twice: for the
// baseline target (two lanes per SSE2 vector) and compiled for AVX2 (four lanes per vector,
// a third fewer instructions), picked at run time from what the processor has.
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

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <type_traits>
#include <vector>

#include "pipeline/cluster/WideBounds.h"

// Run-time dispatch to AVX2 code (GCC and Clang on x86-64; elsewhere only the baseline).
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define HLOD_WIDE_AVX2 1
#else
#define HLOD_WIDE_AVX2 0
#endif

namespace hlod {

class MergeBvh {
public:
    struct alignas(64) Node {
        WideRegions slots{};
        // (16-byte aligned for the SSE2 lane masks, laterThan and nodeLanes.)
        alignas(16) std::uint32_t child[4] = {}; // kItem | the item's position, or a node index
        alignas(16) std::uint32_t end[4] = {};   // one past the last item position below; 0: unused
    };
    static constexpr std::uint32_t kItem = 0x80000000u;

    // Builds the hierarchy over items 0..n-1 with their regions and size classes, for the
    // bounds of `model` (which must outlive the queries). `codes`: the items' Morton codes
    // (Morton.h) where the caller has them already (any codes do: only the shape depends on
    // them); otherwise those of the regions' centres.
    void build(const std::vector<Region>& items, const std::vector<int>& sizeClass,
               const CostModel& model, const std::vector<std::uint64_t>* codes = nullptr);

    // The vector width the queries run with: Baseline (two lanes per vector, any x86-64 or
    // other target) or Avx2 (four lanes, x86-64 processors that have AVX2; the functions are
    // compiled for it separately and chosen at run time). Both give the same answers.
    enum class Simd { Baseline, Avx2 };
    // Avx2 when this build can dispatch to it and the processor has it.
    static Simd bestSimd();

    // Cheapest-partner search for item `self`: nearest slots first, skipping every slot whose
    // lower bound exceeds `threshold`; `visit(item)` sees every other item not skipped (and
    // may see `self`) and may lower `threshold` (a reference the visitor updates).
    template <class Visit>
    void search(std::uint32_t self, const double& threshold, Visit&& visit,
                Simd simd = bestSimd()) const;

    // Self-join: calls visit(i, j) once for every unordered pair of distinct items whose
    // pair bound (and those of the slots holding them) does not exceed `threshold` (for the
    // box model with k = 0 the node test runs in single precision with a margin, WideBounds.h,
    // so a pair whose bound exceeds the threshold by less than 2.4e-4 of it may be reported
    // too; the visitor decides on the exact cost).
    // Dual-tree: the hierarchy's own nodes are the query groups. A group tests the target
    // lanes its parent kept, opens the target nodes at least as large as itself and keeps the
    // rest for its parts; an item finally descends what its group kept. Only slots holding
    // items after the query's first item (in the hierarchy's order) are tested, so each pair
    // is met once, from its first item. Both walk the targets breadth first (sweep), testing
    // two nodes at a time.
    template <class Visit> void join(double threshold, Visit&& visit, Simd simd = bestSimd()) const;

private:
    // A target node and the lanes of it still to test.
    struct Entry {
        std::uint32_t node;
        unsigned mask;
    };

    // The queries for one vector width W and bound kind K (WideBounds.h): search() and
    // join() pick the kind of the model (kind_) and the width, so each combination is its
    // own code with only its bound's arithmetic.
    template <int W, BoundKind K, class Visit>
    [[gnu::always_inline]] void searchWith(std::uint32_t self, const double& threshold,
                                           Visit& visit) const;
    template <int W, BoundKind K, class Visit>
    [[gnu::always_inline]] void joinWith(double threshold, Visit& visit) const;
    class Wave;
    template <int W, BoundKind K, class Visit>
    [[gnu::always_inline]] void joinItem(std::uint32_t p, const Entry* targets, std::size_t count,
                                         double threshold, Wave (&waves)[2], Visit& visit) const;
    template <BoundKind K, class Visit>
    void searchKind(std::uint32_t self, const double& threshold, Visit& visit, Simd simd) const {
#if HLOD_WIDE_AVX2
        if (simd == Simd::Avx2) {
            searchAvx2<K>(self, threshold, visit);
            return;
        }
#endif
        (void)simd;
        searchWith<2, K>(self, threshold, visit);
    }
    template <BoundKind K, class Visit>
    void joinKind(double threshold, Visit& visit, Simd simd) const {
#if HLOD_WIDE_AVX2
        if (simd == Simd::Avx2) {
            joinAvx2<K>(threshold, visit);
            return;
        }
#endif
        (void)simd;
        joinWith<2, K>(threshold, visit);
    }
#if HLOD_WIDE_AVX2
    template <BoundKind K, class Visit>
    [[gnu::target("avx2")]] void searchAvx2(std::uint32_t self, const double& threshold,
                                            Visit& visit) const {
        searchWith<4, K>(self, threshold, visit);
    }
    template <BoundKind K, class Visit>
    [[gnu::target("avx2")]] void joinAvx2(double threshold, Visit& visit) const {
        joinWith<4, K>(threshold, visit);
    }
#endif
    // Entries of one breadth-first wave, with room for what the next wave may add (at most
    // four per entry tested), written without a branch per entry.
    class Wave {
    public:
        Entry* reserve(std::size_t n) {
            if (n > capacity_) {
                capacity_ = std::max(n, 2 * capacity_);
                data_ = std::make_unique<Entry[]>(capacity_);
            }
            return data_.get();
        }

    private:
        std::unique_ptr<Entry[]> data_;
        std::size_t capacity_ = 0;
    };
    // Breadth first from the target entries: test(a, b) tests two nodes (a's lanes that
    // exceed in bits 0-3, b's in bits 4-7), use(entry, node, exceeding, out) writes what to
    // descend into at out (at most four entries) and returns how many. The tests of a wave do
    // not depend on each other, so the processor overlaps them (a depth-first walk waits on
    // each test's outcome to know the next node: the join was bound by that latency, not by
    // its arithmetic); they run two at a time (WideQueryT::exceeds2).
    template <class Test, class Use>
    [[gnu::always_inline]] void sweep(const Entry* targets, std::size_t count, Wave (&waves)[2],
                                      Test&& test, Use&& use) const {
        const Entry* in = targets;
        for (int w = 0; count != 0; w ^= 1) {
            Entry* out = waves[w].reserve(4 * count);
            std::size_t next = 0;
            std::size_t i = 0;
            for (; i + 1 < count; i += 2) {
                // A few entries ahead: their cache lines load while these are tested.
                if (i + 5 < count) {
                    prefetchNode(in[i + 4].node);
                    prefetchNode(in[i + 5].node);
                }
                const Node& a = nodes_[in[i].node];
                const Node& b = nodes_[in[i + 1].node];
                const unsigned exceeding = test(a, b);
                next += use(in[i], a, exceeding & 0xfu, out + next);
                next += use(in[i + 1], b, exceeding >> 4, out + next);
            }
            if (i < count) {
                const Node& a = nodes_[in[i].node];
                next += use(in[i], a, test(a, a) & 0xfu, out + next);
            }
            in = out;
            count = next;
        }
    }
    // Writes an entry for each lane in `lanes` (a full mask each) at out, without branches;
    // returns how many. Unrolled by hand, each entry one 64-bit store (node in the low half).
    [[gnu::always_inline]] static std::size_t appendLanes(const Node& node, unsigned lanes,
                                                          Entry* out) {
        static_assert(sizeof(Entry) == 8 && offsetof(Entry, node) == 0);
        std::size_t m = 0;
        const auto put = [&](int l) __attribute__((always_inline)) {
            const std::uint64_t entry = node.child[l] | std::uint64_t{0xfu} << 32;
            std::memcpy(out + m, &entry, sizeof entry);
            m += (lanes >> l) & 1u;
        };
        put(0);
        put(1);
        put(2);
        put(3);
        return m;
    }
    // Lanes holding an item after position p (each pair is met from its first item only).
    // (SSE2: one compare of the four ends; they are below 2^31, so a signed compare does.)
    [[gnu::always_inline]] static unsigned laterThan(const Node& node, std::uint32_t p) {
#if defined(__SSE2__)
        const __m128i end = _mm_load_si128(reinterpret_cast<const __m128i*>(node.end));
        const __m128i later = _mm_cmpgt_epi32(end, _mm_set1_epi32(static_cast<int>(p + 1)));
        return static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(later)));
#else
        unsigned out = 0;
        for (int l = 0; l < 4; ++l)
            out |= node.end[l] > p + 1 ? 1u << l : 0u;
        return out;
#endif
    }
    static double diagonal2(const PackedRegion& r) {
        double d = 0.0;
        for (int i = 0; i < 3; ++i) {
            const double x = static_cast<double>(r.hi[i]) - r.lo[i];
            d += x * x;
        }
        return d;
    }
    [[gnu::always_inline]] void prefetchNode(std::uint32_t node) const {
        const char* at = reinterpret_cast<const char*>(nodes_.data() + node);
        for (int line = 0; line < 4; ++line)
            __builtin_prefetch(at + 64 * line);
    }
    // Lanes holding a child node (not an item, not unused).
    // (SSE2: kItem is the sign bit of child, and unused lanes have end 0.)
    [[gnu::always_inline]] static unsigned nodeLanes(const Node& node) {
#if defined(__SSE2__)
        const __m128i child = _mm_load_si128(reinterpret_cast<const __m128i*>(node.child));
        const __m128i end = _mm_load_si128(reinterpret_cast<const __m128i*>(node.end));
        const __m128i unused = _mm_cmpeq_epi32(end, _mm_setzero_si128());
        const auto items = static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(child)));
        const auto none = static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(unused)));
        return ~(items | none) & 0xfu;
#else
        unsigned out = 0;
        for (int l = 0; l < 4; ++l)
            out |= node.end[l] != 0 && (node.child[l] & kItem) == 0 ? 1u << l : 0u;
        return out;
#endif
    }

    struct Slot {
        std::uint32_t child;
        std::uint32_t end;
        Region region;
    };

    template <int W, BoundKind K>
    [[gnu::always_inline]] WideQueryT<W, K> queryOf(std::uint32_t position) const {
        return WideQueryT<W, K>(*model_, packed_[position], packedExtra_[position]);
    }
    Slot buildRange(std::uint32_t begin, std::uint32_t end, const std::vector<Region>& items);
    Slot makeNode(const Slot* parts, std::size_t count);
    std::uint32_t split(std::uint32_t begin, std::uint32_t end) const;
    void groupByClass(const std::vector<int>& sizeClass);

    const CostModel* model_ = nullptr;
    BoundKind kind_ = BoundKind::Any; // boundKindOf(*model_)
    std::vector<Node> nodes_;
    std::uint32_t root_ = 0;    // valid when nodes_ is not empty
    PackedRegion rootRegion_{}; // the region of everything
    PackedExtra rootExtra_{};
    std::vector<std::uint32_t> order_;     // position -> item; leaf ranges contiguous
    std::vector<std::uint32_t> position_;  // item -> position
    std::vector<PackedRegion> packed_;     // by position
    std::vector<PackedExtra> packedExtra_; // by position (box model)
    // Build scratch, kept so that rebuilding level after level reuses the memory.
    std::vector<std::uint64_t> codes_; // by item
    std::vector<std::uint64_t> keys_;  // by position: the item's code
    std::vector<std::uint32_t> classStart_;
};

// Depth: along a path from a class hierarchy's top each split lowers the highest bit in which
// the range's codes differ (63 bits) or, once they are equal, halves the range (at most 32
// times below 2^32 items); a node makes two splits of the path, so a class hierarchy is at
// most 49 nodes deep with the item, and the tops above add log4 of the class count (at most
// 6 for the 2,100 binary exponents of a double). A descent's stack holds at most three
// pending slots per level above the node popped and its four, so 3 * 55 + 4 < 256 entries.
// (The join walks breadth first, in growing buffers.)
template <class Visit>
void MergeBvh::search(std::uint32_t self, const double& threshold, Visit&& visit, Simd simd) const {
    withKind(kind_, [&](auto kind) {
        // (kind_ is never BoxK0Single, which only tests and has no bounds to order a search.)
        constexpr BoundKind fixed =
            kind.value == BoundKind::BoxK0Single ? BoundKind::BoxK0 : kind.value;
        searchKind<fixed>(self, threshold, visit, simd);
    });
}

template <class Visit> void MergeBvh::join(double threshold, Visit&& visit, Simd simd) const {
    // (k = 0: the node test in single precision where the threshold allows, WideBounds.h.)
    const BoundKind kind =
        kind_ == BoundKind::BoxK0 && singleUsable(threshold) ? BoundKind::BoxK0Single : kind_;
    withKind(kind, [&](auto fixed) { joinKind<fixed.value>(threshold, visit, simd); });
}

template <int W, BoundKind K, class Visit>
inline void MergeBvh::searchWith(std::uint32_t self, const double& threshold, Visit& visit) const {
    if (nodes_.empty()) return;
    const WideQueryT<W, K> q = queryOf<W, K>(position_[self]);
    struct Pending {
        std::uint32_t node;
        double lb;
    };
    std::array<Pending, 256> stack;
    std::size_t top = 0;
    stack[top++] = Pending{root_, 0.0};
    while (top > 0) {
        const Pending e = stack[--top];
        if (e.lb > threshold) continue;
        const Node& n = nodes_[e.node];
        double lb[4];
        q.bounds(n.slots, lb);
        // Lanes in ascending bound order, without branches (which order the bounds come in is
        // a coin toss for the branch predictor): a key per lane, the bound's bits (bounds are
        // not negative, so their bit patterns order as they do; the sign bit is cleared, so a
        // used lane's key stays below an unused lane's) with the lane in the two lowest bits,
        // sorted by a network of five compare-exchanges. The order only decides which slot is
        // tried first; the tests below read the exact bounds.
        constexpr std::uint64_t kUnused = ~std::uint64_t{0};
        constexpr std::uint64_t kKeyBits = 0x7ffffffffffffffcu;
        std::uint64_t key[4];
        int used = 0;
        for (int l = 0; l < 4; ++l) {
            const std::uint64_t bits =
                (std::bit_cast<std::uint64_t>(lb[l]) & kKeyBits) | static_cast<std::uint64_t>(l);
            key[l] = n.end[l] == 0 ? kUnused : bits;
            used += n.end[l] != 0 ? 1 : 0;
        }
        const auto order = [&](int i, int j) __attribute__((always_inline)) {
            const std::uint64_t lo = std::min(key[i], key[j]);
            key[j] = std::max(key[i], key[j]);
            key[i] = lo;
        };
        order(0, 1);
        order(2, 3);
        order(0, 2);
        order(1, 3);
        order(1, 2);
        int lane[4];
        for (int i = 0; i < 4; ++i)
            lane[i] = static_cast<int>(key[i] & 3u);
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

template <int W, BoundKind K, class Visit>
inline void MergeBvh::joinWith(double threshold, Visit& visit) const {
    if (nodes_.empty()) return;
    // The query groups depth first, without recursion (so the whole join is one function,
    // compiled for the chosen vector width). A frame is a query node, its region being lane
    // `lane` of node `parent` (the root's for the first frame); a frame of depth d tests the
    // target lanes kept at depth d - 1 and keeps its own at depth d. Siblings are popped
    // after the whole subtree of the one before, which writes only deeper lists.
    struct Frame {
        std::uint32_t q;
        std::uint32_t begin; // first item position below q
        std::uint32_t depth;
        std::uint32_t parent;
        int lane;
    };
    constexpr std::uint32_t kNoParent = 0xffffffffu;
    // Kept lists by depth: kept[d][0, keptSize[d]) (the buffers only grow, so they are not
    // cleared or refilled with zeros frame after frame).
    std::vector<std::vector<Entry>> kept(2);
    std::vector<std::size_t> keptSize(2, 0);
    kept[0].push_back(Entry{root_, 0xfu});
    keptSize[0] = 1;
    Wave waves[2];
    std::vector<Frame> frames{Frame{root_, 0, 1, kNoParent, 0}};
    while (!frames.empty()) {
        const Frame f = frames.back();
        frames.pop_back();
        PackedRegion region = rootRegion_;
        PackedExtra extra = rootExtra_;
        if (f.parent != kNoParent) getLane(nodes_[f.parent].slots, f.lane, region, extra);
        const WideQueryT<W, K> query(*model_, region, extra);
        const auto size = static_cast<float>(diagonal2(region));
        if (kept.size() <= f.depth) {
            kept.resize(f.depth + 1);
            keptSize.resize(f.depth + 1, 0);
        }
        // The targets' lanes this group may still pair with; a node lane at least as large as
        // the group is opened here, a smaller one is left for the group's parts to test. The
        // list grows by at most one entry per test.
        std::vector<Entry>& out = kept[f.depth];
        std::size_t kept0 = 0;
        const auto test = [&](const Node& a, const Node& b) __attribute__((always_inline)) {
            return query.exceeds2(a.slots, b.slots, threshold);
        };
        sweep(
            kept[f.depth - 1].data(), keptSize[f.depth - 1], waves, test,
            [&](const Entry& e, const Node& node, unsigned exceeding, Entry* children)
                __attribute__((always_inline)) {
                    const unsigned keep = e.mask & laterThan(node, f.begin) & ~exceeding;
                    const unsigned open = keep & nodeLanes(node) & diagonalAbove(node.slots, size);
                    if (out.size() <= kept0) out.resize(2 * kept0 + 64);
                    out[kept0] = Entry{e.node, keep & ~open};
                    kept0 += (keep & ~open) != 0;
                    return appendLanes(node, open, children);
                });
        keptSize[f.depth] = kept0;
        const Node& group = nodes_[f.q];
        for (int l = 0; l < 4 && group.end[l] != 0; ++l) {
            const std::uint32_t c = group.child[l];
            if ((c & kItem) != 0) {
                joinItem<W, K>(c & ~kItem, out.data(), kept0, threshold, waves, visit);
            }
        }
        for (int l = 3; l >= 0; --l) {
            const std::uint32_t c = group.child[l];
            if (group.end[l] == 0 || (c & kItem) != 0) continue;
            frames.push_back(Frame{c, l == 0 ? f.begin : group.end[l - 1], f.depth + 1, f.q, l});
        }
    }
}

template <int W, BoundKind K, class Visit>
inline void MergeBvh::joinItem(std::uint32_t p, const Entry* targets, std::size_t count,
                               double threshold, Wave (&waves)[2], Visit& visit) const {
    const WideQueryT<W, K> query = queryOf<W, K>(p);
    const auto test = [&](const Node& a, const Node& b) __attribute__((always_inline)) {
        return query.exceeds2(a.slots, b.slots, threshold);
    };
    sweep(
        targets, count, waves, test,
        [&](const Entry& e, const Node& node, unsigned exceeding, Entry* children)
            __attribute__((always_inline)) {
                const unsigned keep = e.mask & laterThan(node, p) & ~exceeding;
                const unsigned nodes = nodeLanes(node);
                // Items are rare (a few pairs per item against tens of nodes tested): a
                // branch.
                for (unsigned items = keep & ~nodes; items != 0; items &= items - 1)
                    visit(order_[p], order_[node.child[__builtin_ctz(items)] & ~kItem]);
                return appendLanes(node, keep & nodes, children);
            });
}

} // namespace hlod
