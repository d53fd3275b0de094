// Bottom-up hierarchical clustering by levels with a growing cost budget: thesis section 3.2.3
// (Sappa & Garcia 2004, algorithm 4) with the bounding volumes and costs of sections 4.1-4.2
// (CostModel.h). This file states the rule; LevelMerger.cpp is the fast implementation and
// tests/pipeline/cluster/NaiveClusterer.cpp the all-pairs reference that must build the same
// tree.
//
// The rule. Input: a set U of units (tree nodes with a ClusterUnit), maxChildren >= 2.
// 1. Levels. While |U| > 1, run one level over U (thesis: one ADDLEVEL per iteration).
// 2. Budget. For each u in U, best(u) = min over v in U, v != u, of cost(u, v). Take the
//    sample of U: with U in ascending id order u_0 < ... < u_{m-1} and s = min(m, S) (S =
//    LevelMergeOptions::budgetSample, 1024), the units u_floor(i m / s) for i = 0..s-1 (all of
//    U when m <= S). Q is the lower median of best() over the sample (element floor((s-1)/2)
//    in ascending order) and the level's budget is B = max(B_previous, Q), B_previous = 0
//    before the first level. (The sample keeps the budget's cost independent of |U|: only the
//    sampled units need an unbounded cheapest-partner search; the others search within B.) The thesis merges
//    "cheapest first" along the MST of each level but leaves open when a level stops; UE4's
//    implementation of the same algorithm stops each level at a fixed cost per level. A fixed
//    schedule either wastes levels or merges half the scene at once depending on the scene's
//    scale, so the budget follows the data: about half the units find a partner within it, so
//    the unit count shrinks geometrically and the tree has O(log n) levels. It never shrinks,
//    and it always admits the globally cheapest pair, so every level merges at least once.
// 3. Groups. A level starts with every unit as its own group. Repeatedly take the pair of
//    groups (G, H) with the smallest (cost(G + H), min(key G, key H), max(key G, key H)) among
//    the pairs with cost <= B and |G| + |H| <= maxChildren members, and merge the two groups
//    into one. The level ends when no pair qualifies.
//    - key(group) = smallest node id among its members: unique, so ties in cost are broken
//      deterministically by id.
//    - the merged group's bounds, fill and cost are CostModel::merge(lower-key group,
//      higher-key group): a group that absorbs a third member gets F_(AB)C from F_AB and F_C by
//      eq. 3.1, exactly as a pair would.
//    This is how a node gets more than two children: a cluster created in this level keeps
//    absorbing units (or another cluster of this level) while the result stays within the
//    budget and within maxChildren children.
// 4. Nodes. At the end of the level each group with >= 2 members becomes a new node whose
//    children are its members (ascending id); new nodes take ids in ascending key order. A
//    group of one member carries its unit to the next level unchanged (no single-child nodes).
//    The next level runs on the new nodes and the carried units.
//
// Complexity (fast implementation): per level, a BVH over the units (MergeBvh.h) answers
// "cheapest partner of X" by branch and bound with CostModel::lowerBound; a priority queue
// holds each group's cheapest partner and is invalidated lazily (an entry whose partner has
// since merged is recomputed when it reaches the top). A popped entry whose two groups are
// both alive is the global minimum: every live pair is covered by an entry of one of its
// groups with a key no larger than its own. Near n log n for spatially coherent scenes; memory
// linear in the number of units. The per-unit cheapest-partner queries at the start of a level
// run in parallel (TBB); each writes its own slot, so the tree does not depend on the thread
// count.
#pragma once

#include <vector>

#include "pipeline/cluster/TreeBuilder.h"
#include "pipeline/core/Progress.h"

namespace hlod {

struct LevelMergeOptions {
    std::size_t budgetSample = 1024; // S of rule 2 (>= 1; tests use small values)
};

// Clusters `units` (node ids of `builder`, each unit once) into one tree and returns its root
// (the unit itself when there is one; kNoId when there are none). New inner nodes are appended
// to `builder`. `maxChildren` >= 2. Reports progress as stage "cluster" and throws
// Error(Cancelled) when the cancel flag is raised.
Id mergeLevels(TreeBuilder& builder, std::vector<Id> units, int maxChildren,
               const Progress& progress = {});
Id mergeLevelsWith(TreeBuilder& builder, std::vector<Id> units, int maxChildren,
                   const Progress& progress, const LevelMergeOptions& options);

// Positions (into units sorted by id) of the budget sample of rule 2.
std::vector<std::size_t> budgetSample(std::size_t units, std::size_t sampleSize);

} // namespace hlod
