// Naive reference of the level-merging rule stated in pipeline/cluster/LevelMerger.h, for the
// property test (the fast mergeLevels must build the same tree) and the benchmark ratio.
//
// Written straight from the rule, with no spatial structure, no graph lists and no lazy queue:
// at the start of each level every pair of units is costed (the sample's best partners, the
// budget and, at rebuilds, each unit's K cheapest pairs within it come from that matrix); the
// neighbour graph is a boolean matrix, contracted member by member between levels; every step
// scans all pairs of live groups, checks the neighbour condition member by member, and takes
// the smallest key within the budget and the children cap. Group pair costs are memoised and a
// merged group's row recomputed (a pair's cost depends on its two groups only).
// O(n^2) memory and O(n^3) time: only for a few thousand units.
// Header-only so that bench/ (which does not compile test sources) can use it.
#pragma once

#include <algorithm>
#include <limits>
#include <tuple>
#include <vector>

#include "pipeline/cluster/LevelMerger.h"
#include "pipeline/cluster/TreeBuilder.h"
#include "pipeline/core/Progress.h"

namespace hlod::test {

namespace naive {

struct Group {
    ClusterUnit unit;
    Id key = kNoId;
    std::vector<std::size_t> members; // indices into the level's units
    bool alive = true;
};

using Key = std::tuple<double, Id, Id>;

inline Key pairKey(const CostModel& model, const ClusterUnit& a, Id ka, const ClusterUnit& b,
                   Id kb) {
    return ka < kb ? Key{model.mergeCost(a, b), ka, kb} : Key{model.mergeCost(b, a), kb, ka};
}

// Rule step 3 from the full cost matrix of the level's units: symmetric neighbour matrix.
inline std::vector<char> neighbourMatrix(const std::vector<Key>& unitKeys, std::size_t n,
                                         double budget, std::size_t k) {
    std::vector<char> adj(n * n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        std::vector<std::pair<Key, std::size_t>> within;
        for (std::size_t j = 0; j < n; ++j) {
            if (j != i && std::get<0>(unitKeys[i * n + j]) <= budget) {
                within.push_back({unitKeys[i * n + j], j});
            }
        }
        std::sort(within.begin(), within.end());
        for (std::size_t r = 0; r < within.size() && r < k; ++r) {
            adj[i * n + within[r].second] = adj[within[r].second * n + i] = 1;
        }
    }
    return adj;
}

// The units formed by one level: member positions (into the level's units) per next unit.
struct LevelResult {
    std::vector<Id> units;                         // ascending ids
    std::vector<std::vector<std::size_t>> members; // aligned with units
};

// One level over `units` (ascending ids) with `budget` and the neighbour matrix `adj`.
inline LevelResult runLevel(TreeBuilder& builder, const std::vector<Id>& units,
                            const std::vector<Key>& unitKeys, const std::vector<char>& adj,
                            double budget, std::size_t maxChildren) {
    const CostModel& model = builder.model();
    const std::size_t n = units.size();
    std::vector<Group> g(n);
    for (std::size_t i = 0; i < n; ++i)
        g[i] = Group{builder.unit(units[i]), units[i], {i}};
    std::vector<Key> cost(unitKeys);
    auto recomputeRow = [&](std::size_t i) {
        for (std::size_t j = 0; j < n; ++j) {
            if (j == i || !g[j].alive) continue;
            cost[i * n + j] = cost[j * n + i] =
                pairKey(model, g[i].unit, g[i].key, g[j].unit, g[j].key);
        }
    };
    auto neighbours = [&](const Group& a, const Group& b) {
        for (std::size_t x : a.members) {
            for (std::size_t y : b.members) {
                if (adj[x * n + y]) return true;
            }
        }
        return false;
    };
    while (true) {
        std::size_t bi = n, bj = n;
        for (std::size_t i = 0; i < n; ++i) {
            if (!g[i].alive) continue;
            for (std::size_t j = i + 1; j < n; ++j) {
                if (!g[j].alive || g[i].members.size() + g[j].members.size() > maxChildren) {
                    continue;
                }
                const Key& c = cost[i * n + j];
                if (std::get<0>(c) > budget || (bi != n && !(c < cost[bi * n + bj]))) continue;
                if (neighbours(g[i], g[j])) bi = i, bj = j;
            }
        }
        if (bi == n) break;
        Group& a = g[bi].key < g[bj].key ? g[bi] : g[bj];
        Group& b = g[bi].key < g[bj].key ? g[bj] : g[bi];
        Group merged{model.merge(a.unit, b.unit), a.key, a.members};
        merged.members.insert(merged.members.end(), b.members.begin(), b.members.end());
        g[bj].alive = false;
        g[bi] = std::move(merged);
        recomputeRow(bi);
    }
    std::vector<const Group*> formed;
    std::vector<std::pair<Id, const Group*>> next;
    for (const Group& x : g) {
        if (!x.alive) continue;
        if (x.members.size() == 1) {
            next.push_back({units[x.members[0]], &x});
        } else {
            formed.push_back(&x);
        }
    }
    std::sort(formed.begin(), formed.end(),
              [](const Group* a, const Group* b) { return a->key < b->key; });
    for (const Group* x : formed) {
        std::vector<Id> children;
        for (std::size_t m : x->members)
            children.push_back(units[m]);
        next.push_back({builder.addNode(std::move(children), x->unit), x});
    }
    std::sort(next.begin(), next.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    LevelResult out;
    for (const auto& [id, group] : next) {
        out.units.push_back(id);
        out.members.push_back(group->members);
    }
    return out;
}

// Rule step 3, inherited: next units are neighbours when members were.
inline std::vector<char> contract(const std::vector<char>& adj, std::size_t n,
                                  const LevelResult& r) {
    const std::size_t m = r.units.size();
    std::vector<char> out(m * m, 0);
    for (std::size_t a = 0; a < m; ++a) {
        for (std::size_t b = 0; b < m; ++b) {
            if (a == b) continue;
            for (std::size_t x : r.members[a]) {
                for (std::size_t y : r.members[b]) {
                    if (adj[x * n + y]) out[a * m + b] = 1;
                }
            }
        }
    }
    return out;
}

} // namespace naive

// Same contract as hlod::mergeLevelsWith (wrap it in a lambda to use it as a UnitMerger).
inline Id naiveMergeLevels(TreeBuilder& builder, std::vector<Id> units, int maxChildren,
                           const Progress& progress = {}, const LevelMergeOptions& options = {}) {
    if (units.empty()) return kNoId;
    const CostModel& model = builder.model();
    const auto cap = static_cast<std::size_t>(maxChildren);
    std::sort(units.begin(), units.end());
    double budget = 0.0;
    std::vector<char> adj;
    std::size_t unitsAtRebuild = 0;
    double graphBudget = 0.0;
    while (units.size() > 1) {
        progress.throwIfCancelled();
        const std::size_t m = units.size();
        std::vector<naive::Key> keys(m * m);
        for (std::size_t i = 0; i < m; ++i) {
            for (std::size_t j = i + 1; j < m; ++j) {
                keys[i * m + j] = keys[j * m + i] = naive::pairKey(
                    model, builder.unit(units[i]), units[i], builder.unit(units[j]), units[j]);
            }
        }
        const std::size_t s = std::min(m, options.budgetSample);
        std::vector<double> best;
        for (std::size_t i = 0; i < s; ++i) {
            const std::size_t u = i * m / s;
            double b = std::numeric_limits<double>::infinity();
            for (std::size_t v = 0; v < m; ++v) {
                if (v != u) b = std::min(b, std::get<0>(keys[u * m + v]));
            }
            best.push_back(b);
        }
        std::sort(best.begin(), best.end());
        budget = std::max(budget, best[(s - 1) / 2]);
        const bool rebuild =
            adj.empty() || budget > graphBudget || m * options.rebuildRatio <= unitsAtRebuild;
        if (rebuild) {
            graphBudget = budget * options.graphBudgetFactor;
            adj = naive::neighbourMatrix(keys, m, graphBudget, options.neighbours);
            unitsAtRebuild = m;
        }
        const std::size_t nodesBefore = builder.size();
        naive::LevelResult r = naive::runLevel(builder, units, keys, adj, budget, cap);
        if (r.units.size() == m && !rebuild) {
            // No merge with the inherited graph: rebuild it and rerun the level (the failed
            // run created no nodes).
            (void)nodesBefore;
            graphBudget = budget * options.graphBudgetFactor;
            adj = naive::neighbourMatrix(keys, m, graphBudget, options.neighbours);
            unitsAtRebuild = m;
            r = naive::runLevel(builder, units, keys, adj, budget, cap);
        }
        adj = naive::contract(adj, m, r);
        units = std::move(r.units);
    }
    return units[0];
}

} // namespace hlod::test
