// Fast level-by-level merging (rule and complexity in LevelMerger.h).
#include "pipeline/cluster/LevelMerger.h"

#include <algorithm>
#include <limits>
#include <memory>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "pipeline/cluster/MergeBvh.h"
#include "pipeline/cluster/Morton.h"
#include "pipeline/core/Error.h"

namespace hlod {

namespace {

constexpr std::uint32_t kNone = 0xffffffffu;
constexpr double kInf = std::numeric_limits<double>::infinity();

// A candidate merge ordered by (cost, lower key, higher key): the rule's total order.
struct Candidate {
    double cost = kInf;
    Id lo = kNoId;
    Id hi = kNoId;
    std::uint32_t group = kNone;   // whose candidate this is
    std::uint32_t partner = kNone; // the other group
};

bool keyLess(const Candidate& a, const Candidate& b) {
    return a.cost < b.cost || (a.cost == b.cost && (a.lo < b.lo || (a.lo == b.lo && a.hi < b.hi)));
}

struct LaterFirst {
    bool operator()(const Candidate& a, const Candidate& b) const { return keyLess(b, a); }
};

// An entry of a unit's neighbour list: the cost and the other unit; the pair's key follows from
// the two units' ids.
struct Near {
    double cost;
    std::uint32_t unit;
};

// Undirected neighbour graph over a level's units (their internal indices, Level), in CSR
// form; each edge appears in both endpoints' ranges (duplicates allowed).
struct Graph {
    std::vector<std::uint32_t> start{0};
    std::vector<std::uint32_t> adj;
};

struct Group {
    ClusterUnit unit;
    Id key = kNoId;
    std::uint32_t head = kNone; // member units as a linked list through Level::next_
    std::uint32_t tail = kNone;
    std::uint32_t size = 0;
    bool alive = true;
};

// Positions 0..n-1 of `units` in Morton (Z-curve) order of their centres (Morton.h), ties by
// position, into `order`, and their codes in that order into `codes`.
void spatialOrder(const TreeBuilder& builder, const std::vector<Id>& units,
                  std::vector<std::uint32_t>& order, std::vector<std::uint64_t>& codes) {
    const bool box = builder.model().volume() == VolumeType::Aabb;
    mortonCodes(
        units.size(),
        [&](std::size_t i) {
            const ClusterUnit& u = builder.unit(units[i]);
            return box ? u.box.center() : u.sphere.center;
        },
        codes);
    sortMorton(codes, order);
}

// What the next level needs to inherit this level's graph (rule step 3, the contracted
// graph): the graph over this level's units and the next position of each unit (the group
// holding it). Kept rather than contracted at once, since most levels rebuild.
struct Contraction {
    Graph graph;                       // rows: this level's internal indices
    std::vector<std::uint32_t> nextOf; // internal index -> next position
};

template <class T> void release(std::vector<T>& v) {
    v.clear();
    v.shrink_to_fit();
}

class Level {
public:
    // One object serves several levels (start() begins one), so that its buffers are reused
    // instead of allocated and faulted in level after level.
    Level(TreeBuilder& builder, int maxChildren, std::size_t neighbours, MergeBvh::Simd simd)
        : builder_(builder), model_(builder.model()), cap_(static_cast<std::uint32_t>(maxChildren)),
          k_(neighbours), simd_(simd) {}

    // Begins a level over `units` (ascending id). Internally the units are numbered in
    // space-filling-curve order of their centres (spatialOrder), so the groups, lists and
    // graph rows that one unit's neighbours touch lie close together in memory; the rule only
    // ever compares ids, so the numbering changes no result.
    void start(const std::vector<Id>& units) {
        const std::size_t n = units.size();
        spatialOrder(builder_, units, positionOf_, codes_);
        units_.resize(n);
        internalOf_.resize(n);
        groupOf_.resize(n);
        next_.assign(n, kNone);
        groups_.resize(n);
        groups_.reserve(2 * n); // one more per merge: at most n - 1 (no reallocation)
        // Only the BVH build needs the regions and size classes (freed after it).
        std::vector<Region> regions(n);
        std::vector<int> classes(n);
        for (std::uint32_t i = 0; i < n; ++i) {
            units_[i] = units[positionOf_[i]];
            internalOf_[positionOf_[i]] = i;
        }
        // The builder's units read in ascending id (in memory order) and scattered: the
        // writes do not wait on each other as scattered reads would.
        for (std::uint32_t p = 0; p < n; ++p)
            groups_[internalOf_[p]].unit = builder_.unit(units[p]);
        for (std::uint32_t i = 0; i < n; ++i) {
            Group& g = groups_[i];
            g.key = units_[i];
            g.head = g.tail = i;
            g.size = 1;
            g.alive = true;
            groupOf_[i] = i;
            regions[i] = regionOf(model_, g.unit);
            classes[i] = sizeClass(model_, g.unit);
        }
        listsValid_ = false;
        bvh_.build(regions, classes, model_, &codes_);
        seen_.assign(n, 0);
        stamp_ = 0;
    }

    // Cheapest partner cost of each unit in `which` (positions in ascending id), in parallel.
    std::vector<double> cheapestCosts(const std::vector<std::uint32_t>& which) const {
        std::vector<double> out(which.size());
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, which.size(), 16),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                              for (std::size_t i = r.begin(); i < r.end(); ++i) {
                                  out[i] = cheapestUnitCost(internalOf_[which[i]]);
                              }
                          });
        return out;
    }

    // Rule step 3: every unit's K cheapest pairs within `budget` (the graph budget), from one
    // spatial self-join, made symmetric into the level's neighbour graph.
    void buildGraph(double budget) {
        const std::size_t n = units_.size();
        lists_.assign(n * k_, Near{kInf, kNone});
        listSize_.assign(n, 0);
        // The join has already tested the bound of the two items themselves.
        auto visit = [&](std::uint32_t i, std::uint32_t j) {
            const bool iLow = units_[i] < units_[j];
            const Group& lo = groups_[iLow ? i : j];
            const Group& hi = groups_[iLow ? j : i];
            const double cost = model_.mergeCostWithin(lo.unit, hi.unit, budget);
            if (cost > budget) return;
            offer(i, Near{cost, j});
            offer(j, Near{cost, i});
        };
        bvh_.join(budget, visit, simd_);
        // Symmetric adjacency in CSR form: u ~ v when either lists the other.
        Graph& g = graph_;
        g.start.assign(n + 1, 0);
        for (std::uint32_t u = 0; u < n; ++u) {
            for (std::size_t k = 0; k < listSize_[u]; ++k) {
                ++g.start[u + 1];
                ++g.start[lists_[u * k_ + k].unit + 1];
            }
        }
        for (std::size_t u = 0; u < n; ++u)
            g.start[u + 1] += g.start[u];
        g.adj.resize(g.start[n]);
        std::vector<std::uint32_t>& fill = scratch_;
        fill.assign(g.start.begin(), g.start.end() - 1);
        for (std::uint32_t u = 0; u < n; ++u) {
            for (std::size_t k = 0; k < listSize_[u]; ++k) {
                const std::uint32_t v = lists_[u * k_ + k].unit;
                g.adj[fill[u]++] = v;
                g.adj[fill[v]++] = u;
            }
        }
        listsValid_ = true;
    }

    // Rule step 3, inherited: the previous level's graph contracted by its groups (two units
    // are neighbours when a member of one neighboured a member of the other), in this level's
    // numbering.
    void setGraph(const Contraction& c) {
        const std::size_t n = units_.size();
        // The previous level's units by next position (counting sort: ascending within one).
        std::vector<std::uint32_t>& memberStart = scratch_;
        memberStart.assign(n + 1, 0);
        for (const std::uint32_t p : c.nextOf)
            ++memberStart[p + 1];
        for (std::size_t p = 0; p < n; ++p)
            memberStart[p + 1] += memberStart[p];
        std::vector<std::uint32_t>& members = members_;
        members.resize(c.nextOf.size());
        {
            std::vector<std::uint32_t>& fill = mark_;
            fill.assign(memberStart.begin(), memberStart.end() - 1);
            for (std::uint32_t m = 0; m < c.nextOf.size(); ++m)
                members[fill[c.nextOf[m]]++] = m;
        }
        graph_.start.assign(1, 0);
        graph_.adj.clear();
        std::vector<std::uint32_t>& mark = mark_;
        mark.assign(n, kNone);
        for (std::uint32_t i = 0; i < n; ++i) {
            const std::uint32_t p = positionOf_[i];
            for (std::uint32_t k = memberStart[p]; k < memberStart[p + 1]; ++k) {
                const std::uint32_t m = members[k];
                for (std::uint32_t e = c.graph.start[m]; e < c.graph.start[m + 1]; ++e) {
                    const std::uint32_t q = c.nextOf[c.graph.adj[e]];
                    if (q == p || mark[q] == i) continue;
                    mark[q] = i;
                    graph_.adj.push_back(internalOf_[q]);
                }
            }
            graph_.start.push_back(static_cast<std::uint32_t>(graph_.adj.size()));
        }
    }

    // Rule step 4: cheapest adjacent pair first until none is within budget and cap.
    std::size_t run(double budget, const Progress& progress) {
        std::vector<Candidate>& heap = heap_;
        heap.clear();
        if (listsValid_) {
            // Just after a rebuild every group is one unit, and a unit's cheapest neighbour
            // heads its own list: a neighbour that is not in the list (it listed the unit)
            // comes after every listed pair, or the list holds all of the unit's pairs within
            // the graph budget. The list's cost is the one cheapestNeighbour would compute.
            for (std::uint32_t g = 0; g < units_.size(); ++g) {
                if (listSize_[g] == 0) continue;
                const Near& first = lists_[g * k_];
                if (first.cost > budget) continue;
                heap.push_back(candidate(g, first.unit, first.cost));
            }
            release(lists_);
            listsValid_ = false;
        } else {
            for (std::uint32_t g = 0; g < units_.size(); ++g) {
                const Candidate c = cheapestNeighbour(g, budget);
                if (c.partner != kNone) heap.push_back(c);
            }
        }
        // Heapified at once (linear); pops follow the total key order whatever the layout.
        std::make_heap(heap.begin(), heap.end(), LaterFirst{});
        std::size_t merges = 0;
        while (!heap.empty()) {
            std::pop_heap(heap.begin(), heap.end(), LaterFirst{});
            const Candidate top = heap.back();
            heap.pop_back();
            if (!groups_[top.group].alive) continue;
            // A live entry whose partner also lives is exact and, being the smallest lower
            // bound, the global minimum. One whose partner merged is replaced.
            std::uint32_t g = top.group;
            if (groups_[top.partner].alive) {
                g = merge(top.group, top.partner);
                if (++merges % 4096 == 0) progress.throwIfCancelled();
            }
            const Candidate c = cheapestNeighbour(g, budget);
            if (c.partner != kNone) {
                heap.push_back(c);
                std::push_heap(heap.begin(), heap.end(), LaterFirst{});
            }
        }
        return merges;
    }

    // Rule step 5: the next level's units in ascending id (carried singletons and new nodes,
    // which take ids in ascending key order), and in `inherit` what the next level needs to
    // contract this level's graph by its groups (setGraph).
    std::vector<Id> finish(Contraction& inherit) {
        // Walking the units in ascending id meets every group first at its key (its smallest
        // member id): carried units come out in ascending id and formed groups in ascending
        // key, with no sort. New nodes take ids above every existing one, so the next level's
        // units, in ascending id, are the carried units followed by the new nodes.
        const auto n = static_cast<std::uint32_t>(units_.size());
        std::vector<std::uint32_t>& positionOfGroup = scratch_;
        positionOfGroup.resize(groups_.size());
        std::vector<Id> units;
        std::vector<std::uint32_t>& formed = members_;
        formed.clear();
        // A unit that never merged is still in its own group (its index); the live groups
        // formed in this level are the live ones after the first n, each headed by its key
        // unit (merge() keeps the lower key's head), so neither test reads the groups in
        // ascending-id order, which is scattered in memory.
        std::vector<std::uint32_t>& formedAt = mark_; // position of a key -> its group
        formedAt.assign(n, kNone);
        for (auto g = static_cast<std::uint32_t>(n); g < groups_.size(); ++g) {
            if (groups_[g].alive) formedAt[positionOf_[groups_[g].head]] = g;
        }
        for (std::uint32_t p = 0; p < n; ++p) {
            const std::uint32_t i = internalOf_[p];
            if (groupOf_[i] == i) {
                positionOfGroup[i] = static_cast<std::uint32_t>(units.size());
                units.push_back(units_[i]);
            } else if (formedAt[p] != kNone) {
                formed.push_back(formedAt[p]);
            }
        }
        for (const std::uint32_t g : formed) {
            std::vector<Id> children;
            children.reserve(groups_[g].size);
            for (std::uint32_t i = groups_[g].head; i != kNone; i = next_[i]) {
                children.push_back(units_[i]);
            }
            positionOfGroup[g] = static_cast<std::uint32_t>(units.size());
            units.push_back(builder_.addNode(std::move(children), groups_[g].unit));
        }
        inherit.graph.start.swap(graph_.start);
        inherit.graph.adj.swap(graph_.adj);
        inherit.nextOf.resize(n);
        for (std::uint32_t m = 0; m < n; ++m)
            inherit.nextOf[m] = positionOfGroup[groupOf_[m]];
        return units;
    }

private:
    // Whether (a.cost, pair ids of (i, a.unit)) < (b.cost, pair ids of (i, b.unit)).
    bool nearLess(std::uint32_t i, const Near& a, const Near& b) const {
        if (a.cost != b.cost) return a.cost < b.cost;
        const Id u = units_[i], x = units_[a.unit], y = units_[b.unit];
        const Id loA = std::min(u, x), hiA = std::max(u, x);
        const Id loB = std::min(u, y), hiB = std::max(u, y);
        return loA < loB || (loA == loB && hiA < hiB);
    }

    // Keeps c in unit i's list if it is among its K cheapest.
    void offer(std::uint32_t i, const Near& c) {
        Near* list = &lists_[i * k_];
        std::uint8_t& size = listSize_[i];
        if (size == k_) {
            if (!nearLess(i, c, list[k_ - 1])) return;
            --size;
        }
        std::size_t at = size;
        while (at > 0 && nearLess(i, c, list[at - 1])) {
            list[at] = list[at - 1];
            --at;
        }
        list[at] = c;
        ++size;
    }

    // Cheapest pair of unit u with any other unit (level start: every group is one unit).
    // Branch and bound over the BVH; thread-safe (reads only).
    double cheapestUnitCost(std::uint32_t u) const {
        const Group& G = groups_[u];
        double best = kInf;
        auto visit = [&](std::uint32_t v) {
            if (v == u) return;
            const Group& H = groups_[v];
            const double cost = G.key < H.key ? model_.mergeCostWithin(G.unit, H.unit, best)
                                              : model_.mergeCostWithin(H.unit, G.unit, best);
            best = std::min(best, cost);
        };
        // Neighbours on the Morton curve first: a near partner's cost prunes from the start.
        if (u > 0) visit(u - 1);
        if (u + 1 < units_.size()) visit(u + 1);
        bvh_.search(u, best, visit, simd_);
        return best;
    }

    // Cheapest valid pair of live group g with a group adjacent to it in the graph (an edge
    // between a member of each), within the budget; no partner when there is none.
    Candidate cheapestNeighbour(std::uint32_t g, double budget) {
        const Group& G = groups_[g];
        Candidate best;
        best.cost = budget;
        best.group = g;
        const std::uint32_t stamp = ++stamp_;
        // First the distinct adjacent groups, with their (scattered) units prefetched, then
        // the costs: the loads overlap instead of each waiting on the previous test.
        candidates_.clear();
        for (std::uint32_t m = G.head; m != kNone; m = next_[m]) {
            for (std::uint32_t e = graph_.start[m]; e < graph_.start[m + 1]; ++e) {
                const std::uint32_t h = groupOf_[graph_.adj[e]];
                if (h == g || seen_[h] == stamp) continue;
                seen_[h] = stamp;
                __builtin_prefetch(&groups_[h]);
                candidates_.push_back(h);
            }
        }
        for (const std::uint32_t h : candidates_) {
            const Group& H = groups_[h];
            if (G.size + H.size > cap_) continue;
            // Above best.cost (or the budget) the pair cannot win: stop at the cheap bound.
            const double limit = best.cost;
            const Candidate c =
                candidate(g, h,
                          G.key < H.key ? model_.mergeCostWithin(G.unit, H.unit, limit)
                                        : model_.mergeCostWithin(H.unit, G.unit, limit));
            if (c.cost > budget || (best.partner != kNone && !keyLess(c, best))) continue;
            best = c;
        }
        return best;
    }

    // Group g's candidate of merging with group h at `cost`, keyed by the two groups' keys.
    Candidate candidate(std::uint32_t g, std::uint32_t h, double cost) const {
        const Id a = groups_[g].key, b = groups_[h].key;
        return Candidate{cost, std::min(a, b), std::max(a, b), g, h};
    }

    std::uint32_t merge(std::uint32_t a, std::uint32_t b) {
        const bool aLow = groups_[a].key < groups_[b].key;
        const std::uint32_t lo = aLow ? a : b;
        const std::uint32_t hi = aLow ? b : a;
        Group z;
        z.unit = model_.merge(groups_[lo].unit, groups_[hi].unit);
        z.key = groups_[lo].key;
        z.head = groups_[lo].head;
        z.tail = groups_[hi].tail;
        next_[groups_[lo].tail] = groups_[hi].head;
        z.size = groups_[lo].size + groups_[hi].size;
        groups_[lo].alive = false;
        groups_[hi].alive = false;
        const auto id = static_cast<std::uint32_t>(groups_.size());
        groups_.push_back(z);
        seen_.push_back(0);
        for (std::uint32_t i = z.head; i != kNone; i = next_[i])
            groupOf_[i] = id;
        return id;
    }

    TreeBuilder& builder_;
    const CostModel& model_;
    std::vector<Id> units_;                 // internal index -> unit id (spatial order)
    std::vector<std::uint32_t> internalOf_; // position in ascending id -> internal index
    std::vector<std::uint32_t> positionOf_; // internal index -> position in ascending id
    std::vector<std::uint64_t> codes_;      // internal index -> Morton code (spatialOrder)
    std::uint32_t cap_;
    std::size_t k_; // neighbours kept per unit (rule step 3)
    MergeBvh::Simd simd_;
    std::vector<std::uint32_t> groupOf_; // unit -> live group holding it
    std::vector<std::uint32_t> next_;
    std::vector<Group> groups_; // 0..n-1: the units; then one per merge
    MergeBvh bvh_;
    std::vector<Near> lists_; // K per unit while the graph is built
    std::vector<std::uint8_t> listSize_;
    bool listsValid_ = false; // lists_ hold this level's lists and no group has merged yet
    Graph graph_;             // neighbour graph over the units
    std::vector<std::uint32_t> seen_;
    std::uint32_t stamp_ = 0;
    std::vector<std::uint32_t> candidates_; // cheapestNeighbour's scratch
    // Buffers kept from level to level (their contents are per call).
    std::vector<Candidate> heap_;
    std::vector<std::uint32_t> scratch_;
    std::vector<std::uint32_t> members_;
    std::vector<std::uint32_t> mark_;
};

double lowerMedian(std::vector<double> costs) {
    const auto mid = costs.begin() + static_cast<std::ptrdiff_t>((costs.size() - 1) / 2);
    std::nth_element(costs.begin(), mid, costs.end());
    return *mid;
}

} // namespace

std::vector<std::size_t> budgetSample(std::size_t units, std::size_t sampleSize) {
    const std::size_t s = std::min(units, std::max<std::size_t>(sampleSize, 1));
    std::vector<std::size_t> out(s);
    for (std::size_t i = 0; i < s; ++i)
        out[i] = i * units / s;
    return out;
}

Id mergeLevelsWith(TreeBuilder& builder, std::vector<Id> units, int maxChildren,
                   const Progress& progress, const LevelMergeOptions& options) {
    if (maxChildren < 2) {
        throw Error(ErrorCode::InvalidArgument, "max children must be at least 2");
    }
    if (options.neighbours < 1 || options.neighbours > 255 || options.budgetSample < 1 ||
        options.rebuildRatio < 1 || !(options.graphBudgetFactor >= 1.0)) {
        throw Error(ErrorCode::InvalidArgument, "level merge options out of range");
    }
    if (units.empty()) return kNoId;
    const MergeBvh::Simd simd =
        options.baselineSimd ? MergeBvh::Simd::Baseline : MergeBvh::bestSimd();
    const std::size_t total = units.size() - 1;
    std::sort(units.begin(), units.end());
    double budget = 0.0;
    Contraction inherit;
    bool haveGraph = false;
    std::size_t unitsAtRebuild = 0;
    double graphBudget = 0.0;
    // One Level serves the levels until the unit count halves; then a fresh one, so that the
    // buffers kept for reuse never hold more than twice what the current level needs.
    std::unique_ptr<Level> current;
    std::size_t levelCapacity = 0;
    while (units.size() > 1) {
        progress.throwIfCancelled();
        if (!current || units.size() * 2 < levelCapacity) {
            current.reset();
            current = std::make_unique<Level>(builder, maxChildren, options.neighbours, simd);
            levelCapacity = units.size();
        }
        Level& level = *current;
        level.start(units);
        std::vector<std::uint32_t> sample;
        for (std::size_t i : budgetSample(units.size(), options.budgetSample)) {
            sample.push_back(static_cast<std::uint32_t>(i));
        }
        budget = std::max(budget, lowerMedian(level.cheapestCosts(sample)));
        const bool rebuilt = !haveGraph || budget > graphBudget ||
                             units.size() * options.rebuildRatio <= unitsAtRebuild;
        if (rebuilt) {
            graphBudget = budget * options.graphBudgetFactor;
            level.buildGraph(graphBudget);
            unitsAtRebuild = units.size();
        } else {
            level.setGraph(inherit);
        }
        if (level.run(budget, progress) == 0 && !rebuilt) {
            // The inherited graph has no pair within the budget: rebuild and rerun (nothing
            // merged yet, so the level starts over from the same units).
            graphBudget = budget * options.graphBudgetFactor;
            level.buildGraph(graphBudget);
            unitsAtRebuild = units.size();
            level.run(budget, progress);
        }
        units = level.finish(inherit);
        haveGraph = true;
        progress.emit(ProgressInfo{"cluster", total - (units.size() - 1), total, ""});
    }
    return units[0];
}

Id mergeLevels(TreeBuilder& builder, std::vector<Id> units, int maxChildren,
               const Progress& progress) {
    return mergeLevelsWith(builder, std::move(units), maxChildren, progress, LevelMergeOptions{});
}

} // namespace hlod
