// Naive reference of the level-merging rule stated in pipeline/cluster/LevelMerger.h, for the
// property test (the fast mergeLevels must build the same tree) and the benchmark ratio.
//
// Written straight from the rule, with no spatial structure and no lazy queue: at the start of
// each level the sampled units are costed against every other unit to find their cheapest
// partners and the budget; then every step scans all pairs of live groups for the smallest (cost, lower key,
// higher key) within the budget and the children cap. Pair costs are kept in a matrix and a
// merged group's row is recomputed (the other entries cannot change: a pair's cost depends on
// its two groups only). O(n^2) memory and O(n^3) time: only for a few thousand units.
// Header-only so that bench/ (which does not compile test sources) can use it.
#pragma once

#include <algorithm>
#include <limits>
#include <vector>

#include "pipeline/cluster/TreeBuilder.h"
#include "pipeline/core/Progress.h"

namespace hlod::test {

namespace naive {

struct Group {
    ClusterUnit unit;
    Id key = kNoId;
    std::vector<Id> members; // node ids
    bool alive = true;
};

inline double pairCost(const CostModel& model, const Group& a, const Group& b) {
    return a.key < b.key ? model.mergeCost(a.unit, b.unit) : model.mergeCost(b.unit, a.unit);
}

// One level over `units` with `budget`; returns the next level's units.
inline std::vector<Id> runLevel(TreeBuilder& builder, const std::vector<Id>& units,
                                double budget, std::size_t maxChildren) {
    const CostModel& model = builder.model();
    const std::size_t n = units.size();
    std::vector<Group> g(n);
    for (std::size_t i = 0; i < n; ++i) g[i] = Group{builder.unit(units[i]), units[i], {units[i]}};
    std::vector<double> cost(n * n, 0.0);
    auto recomputeRow = [&](std::size_t i) {
        for (std::size_t j = 0; j < n; ++j) {
            if (j != i && g[j].alive) cost[i * n + j] = cost[j * n + i] = pairCost(model, g[i], g[j]);
        }
    };
    for (std::size_t i = 0; i < n; ++i) recomputeRow(i);
    while (true) {
        std::size_t bi = n, bj = n;
        double bc = 0.0;
        Id blo = kNoId, bhi = kNoId;
        for (std::size_t i = 0; i < n; ++i) {
            if (!g[i].alive) continue;
            for (std::size_t j = i + 1; j < n; ++j) {
                if (!g[j].alive || g[i].members.size() + g[j].members.size() > maxChildren) {
                    continue;
                }
                const double c = cost[i * n + j];
                if (c > budget) continue;
                const Id lo = std::min(g[i].key, g[j].key), hi = std::max(g[i].key, g[j].key);
                if (bi == n || c < bc || (c == bc && (lo < blo || (lo == blo && hi < bhi)))) {
                    bi = i, bj = j, bc = c, blo = lo, bhi = hi;
                }
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
    std::vector<Id> next;
    for (const Group& x : g) {
        if (!x.alive) continue;
        if (x.members.size() == 1) {
            next.push_back(x.members[0]);
        } else {
            formed.push_back(&x);
        }
    }
    std::sort(formed.begin(), formed.end(),
              [](const Group* a, const Group* b) { return a->key < b->key; });
    for (const Group* x : formed) next.push_back(builder.addNode(x->members, x->unit));
    return next;
}

} // namespace naive

// Same contract as hlod::mergeLevels (a UnitMerger); `budgetSample` is S of the rule.
inline Id naiveMergeLevels(TreeBuilder& builder, std::vector<Id> units, int maxChildren,
                           const Progress& progress = {}, std::size_t budgetSample = 1024) {
    if (units.empty()) return kNoId;
    const CostModel& model = builder.model();
    double budget = 0.0;
    while (units.size() > 1) {
        progress.throwIfCancelled();
        std::sort(units.begin(), units.end());
        const std::size_t m = units.size();
        const std::size_t s = std::min(m, budgetSample);
        std::vector<double> best;
        for (std::size_t i = 0; i < s; ++i) {
            const Id u = units[i * m / s];
            double b = std::numeric_limits<double>::infinity();
            for (Id v : units) {
                if (v == u) continue;
                b = std::min(b, model.mergeCost(builder.unit(std::min(u, v)),
                                                builder.unit(std::max(u, v))));
            }
            best.push_back(b);
        }
        std::sort(best.begin(), best.end());
        budget = std::max(budget, best[(s - 1) / 2]);
        units = naive::runLevel(builder, units, budget, static_cast<std::size_t>(maxChildren));
    }
    return units[0];
}

} // namespace hlod::test
