// Fast level-by-level merging (rule and complexity in LevelMerger.h).
#include "pipeline/cluster/LevelMerger.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <queue>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "pipeline/cluster/MergeBvh.h"
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
    std::uint32_t group = kNone;   // whose cheapest partner this is
    std::uint32_t partner = kNone; // that partner
};

bool keyLess(double cost, Id lo, Id hi, const Candidate& c) {
    return cost < c.cost || (cost == c.cost && (lo < c.lo || (lo == c.lo && hi < c.hi)));
}

struct LaterFirst {
    bool operator()(const Candidate& a, const Candidate& b) const {
        return keyLess(b.cost, b.lo, b.hi, a);
    }
};

struct Group {
    ClusterUnit unit;
    Id key = kNoId;
    std::uint32_t head = kNone; // member items as a linked list through Level::next
    std::uint32_t tail = kNone;
    std::uint32_t size = 0;
    bool alive = true;
};

class Level {
public:
    Level(TreeBuilder& builder, const std::vector<Id>& units, int maxChildren)
        : builder_(builder), model_(builder.model()), units_(units),
          cap_(static_cast<std::uint32_t>(maxChildren)) {
        const std::size_t n = units.size();
        groupOf_.resize(n);
        next_.assign(n, kNone);
        groups_.resize(n);
        std::vector<Region> regions(n);
        std::vector<int> sizeClass(n);
        for (std::uint32_t i = 0; i < n; ++i) {
            Group& g = groups_[i];
            g.unit = builder.unit(units[i]);
            g.key = units[i];
            g.head = g.tail = i;
            g.size = 1;
            groupOf_[i] = i;
            regions[i] = model_.regionOf(g.unit);
            sizeClass[i] = model_.sizeClass(g.unit);
        }
        bvh_.build(regions, sizeClass);
        seen_.assign(n, 0);
    }

    // Cheapest partner of every unit in `which` (indices into the level's units) with cost
    // <= budget, in parallel; the result is aligned with `which`.
    std::vector<Candidate> cheapestPartners(const std::vector<std::uint32_t>& which,
                                            double budget) const {
        std::vector<Candidate> out(which.size());
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, which.size(), 64),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                              for (std::size_t i = r.begin(); i < r.end(); ++i) {
                                  out[i] = cheapestPartner(which[i], budget, nullptr);
                              }
                          });
        return out;
    }

    // Runs the level with budget `budget`, starting from the candidates; returns the merges.
    std::size_t run(const std::vector<Candidate>& initial, double budget,
                    const Progress& progress) {
        std::priority_queue<Candidate, std::vector<Candidate>, LaterFirst> heap;
        for (const Candidate& c : initial) {
            if (c.partner != kNone && c.cost <= budget) heap.push(c);
        }
        std::size_t merges = 0;
        while (!heap.empty()) {
            const Candidate top = heap.top();
            heap.pop();
            if (!groups_[top.group].alive) continue;
            if (!groups_[top.partner].alive) {
                // The partner merged since: recompute (a lower bound no longer exact).
                const Candidate c = cheapestPartner(top.group, budget, &seen_);
                if (c.partner != kNone) heap.push(c);
                continue;
            }
            const std::uint32_t z = merge(top.group, top.partner);
            const Candidate c = cheapestPartner(z, budget, &seen_);
            if (c.partner != kNone) heap.push(c);
            if (++merges % 4096 == 0) progress.throwIfCancelled();
        }
        return merges;
    }

    // Next level's units: new nodes (ascending key) and carried singletons.
    std::vector<Id> finish() {
        std::vector<std::uint32_t> formed;
        std::vector<Id> next;
        for (std::uint32_t g = 0; g < groups_.size(); ++g) {
            if (!groups_[g].alive) continue;
            if (groups_[g].size == 1) {
                next.push_back(units_[groups_[g].head]);
            } else {
                formed.push_back(g);
            }
        }
        std::sort(formed.begin(), formed.end(), [&](std::uint32_t a, std::uint32_t b) {
            return groups_[a].key < groups_[b].key;
        });
        for (std::uint32_t g : formed) {
            std::vector<Id> children;
            children.reserve(groups_[g].size);
            for (std::uint32_t i = groups_[g].head; i != kNone; i = next_[i]) {
                children.push_back(units_[i]);
            }
            next.push_back(builder_.addNode(std::move(children), groups_[g].unit));
        }
        return next;
    }

private:
    // Cheapest valid partner of group g with cost <= budget (kNone partner when none).
    // `seen` dedups groups met through several member items; null when every group is a
    // single item (level start), which also makes the call safe to run concurrently.
    Candidate cheapestPartner(std::uint32_t g, double budget,
                              std::vector<std::uint32_t>* seen) const {
        const Group& G = groups_[g];
        Candidate best;
        best.cost = budget;
        best.group = g;
        std::uint32_t stamp = 0;
        if (seen) stamp = ++stamp_;
        const BoundQuery bound(model_, G.unit);
        auto visit = [&](std::uint32_t item) {
            const std::uint32_t h = groupOf_[item];
            if (h == g) return;
            if (seen) {
                if ((*seen)[h] == stamp) return;
                (*seen)[h] = stamp;
            }
            const Group& H = groups_[h];
            if (G.size + H.size > cap_) return;
            // The bound of H alone is much cheaper than the exact cost (no overlap volume).
            if (bound(model_.regionOf(H.unit)) > best.cost) return;
            const bool gLow = G.key < H.key;
            const Id lo = gLow ? G.key : H.key;
            const Id hi = gLow ? H.key : G.key;
            const double cost =
                gLow ? model_.mergeCost(G.unit, H.unit) : model_.mergeCost(H.unit, G.unit);
            if (cost > budget) return;
            // Before the first hit anything within the budget qualifies.
            if (best.partner != kNone && !keyLess(cost, lo, hi, best)) return;
            best.cost = cost;
            best.lo = lo;
            best.hi = hi;
            best.partner = h;
        };
        bvh_.search(bound, visit, best.cost);
        return best;
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
        const Aabb box = model_.regionOf(z.unit).box;
        for (std::uint32_t i = z.head; i != kNone; i = next_[i]) {
            groupOf_[i] = id;
            bvh_.grow(i, box, z.unit.fv);
        }
        return id;
    }

    TreeBuilder& builder_;
    const CostModel& model_;
    const std::vector<Id>& units_;
    std::uint32_t cap_;
    std::vector<std::uint32_t> groupOf_;
    std::vector<std::uint32_t> next_;
    std::vector<Group> groups_;
    MergeBvh bvh_;
    mutable std::vector<std::uint32_t> seen_;
    mutable std::uint32_t stamp_ = 0;
};

double lowerMedian(const std::vector<Candidate>& candidates) {
    std::vector<double> costs;
    costs.reserve(candidates.size());
    for (const Candidate& c : candidates) costs.push_back(c.cost);
    const auto mid = costs.begin() + static_cast<std::ptrdiff_t>((costs.size() - 1) / 2);
    std::nth_element(costs.begin(), mid, costs.end());
    return *mid;
}

} // namespace

std::vector<std::size_t> budgetSample(std::size_t units, std::size_t sampleSize) {
    const std::size_t s = std::min(units, std::max<std::size_t>(sampleSize, 1));
    std::vector<std::size_t> out(s);
    for (std::size_t i = 0; i < s; ++i) out[i] = i * units / s;
    return out;
}

Id mergeLevelsWith(TreeBuilder& builder, std::vector<Id> units, int maxChildren,
                   const Progress& progress, const LevelMergeOptions& options) {
    if (maxChildren < 2) {
        throw Error(ErrorCode::InvalidArgument, "max children must be at least 2");
    }
    if (units.empty()) return kNoId;
    const std::size_t total = units.size() - 1;
    double budget = 0.0;
    while (units.size() > 1) {
        progress.throwIfCancelled();
        std::sort(units.begin(), units.end());
        Level level(builder, units, maxChildren);
        // Budget from the sample's cheapest partners, then every unit's cheapest partner
        // within the budget (a bounded search: units without one are discarded quickly).
        std::vector<std::uint32_t> which;
        for (std::size_t i : budgetSample(units.size(), options.budgetSample)) {
            which.push_back(static_cast<std::uint32_t>(i));
        }
        budget = std::max(budget, lowerMedian(level.cheapestPartners(which, kInf)));
        which.resize(units.size());
        std::iota(which.begin(), which.end(), 0u);
        level.run(level.cheapestPartners(which, budget), budget, progress);
        units = level.finish();
        progress.emit(ProgressInfo{"cluster", total - (units.size() - 1), total, ""});
    }
    return units[0];
}

Id mergeLevels(TreeBuilder& builder, std::vector<Id> units, int maxChildren,
               const Progress& progress) {
    return mergeLevelsWith(builder, std::move(units), maxChildren, progress, LevelMergeOptions{});
}

} // namespace hlod
