// Bottom-up hierarchical clustering by levels with a growing cost budget: thesis section 3.2.3
// (Sappa & Garcia 2004, algorithm 4) with the bounding volumes and costs of sections 4.1-4.2
// (CostModel.h). This file states the rule; LevelMerger.cpp is the fast implementation and
// tests/pipeline/cluster/NaiveClusterer.h the all-pairs reference that must build the same
// tree.
//
// The rule. Input: a set U of units (tree nodes with a ClusterUnit), maxChildren >= 2, and
// four constants: S = 256 (budget sample), K = 8 (neighbours), R = 2 (graph rebuild ratio)
// and G = 2 (graph budget factor), see LevelMergeOptions.
// cost(A, B) = CostModel::mergeCost(lower-key operand, higher-key operand); the key of a pair
// is (cost, lower key, higher key), a total order (ties in cost broken by ids).
// 1. Levels. While |U| > 1, run one level over U (thesis algorithm 4: one ADDLEVEL per loop).
// 2. Budget. With U in ascending id order u_0 < ... < u_{m-1} and s = min(m, S), the sample is
//    u_floor(i m / s) for i = 0..s-1 (all of U when m <= S). best(u) = min over v in U, v != u,
//    of cost(u, v); Q = lower median of best() over the sample (element floor((s - 1) / 2) in
//    ascending order); the level's budget is B = max(B_previous, Q), B_previous = 0 at first.
//    The thesis merges cheapest first along the MST of each level but leaves open when a
//    level stops; UE4's implementation of the same algorithm stops at a fixed cost per level.
//    A fixed schedule either wastes levels or merges half the scene at once depending on its
//    scale, so the budget follows the data: about half the units find a partner within it and
//    the unit count shrinks geometrically (O(log n) levels). It never shrinks, and it always
//    admits the globally cheapest pair (whose cost is below every best()), so every level
//    merges at least once. The sample keeps its price independent of |U|.
// 3. Neighbour graph (the thesis' adjacency graph, kept sparse). Rebuilt at the first level,
//    whenever B exceeds the budget of the last build, and whenever |U| * R <= |U at the last
//    build| (R = 2: each time the unit count halves): N(u) = the K smallest pair keys of u
//    among the pairs (u, v) with cost <= G * B (G = 2, the graph budget); u and v are
//    neighbours when v is in N(u) or u in N(v). At the other levels the graph is inherited:
//    the previous level's graph contracted by its groups (two units are neighbours when a
//    member of one neighboured a member of the other). This is the thesis' update "the new
//    bounding sphere is added to the MST, and any potential clusters that overlap are
//    updated": a new cluster's candidates are its members' neighbours. If an inherited graph
//    yields no merge in a level, the graph is rebuilt and the level rerun.
// 4. Groups. A level starts with every unit as its own group. Repeatedly take the pair of
//    groups (G, H) with the smallest key among the pairs with a member of G neighbouring a
//    member of H, cost(G + H) <= B and |G| + |H| <= maxChildren members, and merge the two
//    groups into one; key(group) = smallest node id among its members; the merged group's
//    bounds, fill and cost are CostModel::merge(lower-key group, higher-key group), so a group
//    that absorbs a third member gets F_(AB)C from F_AB and F_C by eq. 3.1 as a pair would.
//    The level ends when no pair qualifies. This is how a node gets more than two children: a
//    cluster created in this level keeps absorbing neighbouring units (or another cluster of
//    this level) while the result stays within the budget and within maxChildren.
// 5. Nodes. Each group with >= 2 members becomes a new node whose children are its members
//    (ascending id); new nodes take ids in ascending key order. A group of one member carries
//    its unit to the next level unchanged (no single-child nodes). The next level runs on the
//    new nodes and the carried units.
//
// Choices the thesis leaves open, where they are decided:
// - Budget growth: rule 2 (lower median of a fixed sample of best partners, never shrinking).
// - Tie-breaking: the pair key (cost, lower id, higher id) above; new nodes take ids in
//   ascending key order (rule 5), so equal costs always resolve the same way.
// - Children cap: rule 4; a pair qualifies only while the merged group has at most
//   maxChildren members, so no node built here has more (the root over excluded leaves in
//   ClusterDriver.h is the one exception), and a group at the cap stops absorbing.
// - Flat boxes with a zero extent: padded to a minimum extent before clustering (CostModel.h,
//   ClusterDriver.h), so every volume and proportion ratio is finite.
//
// Complexity (fast implementation): per level, a 4-wide BVH over the units (MergeBvh.h) gives
// the sampled best() by branch and bound (the pair bound of CostBounds.h, four slots per
// vector test, WideBounds.h); at rebuilds the neighbour lists come from one dual-tree
// self-join pruned with the same bound (groups of units descend together, each unit finishes
// alone; breadth first, two nodes per test; for k = 0 in single precision with a margin, so it
// may report a few pairs just above the graph budget, which the exact cost then drops). The
// units are numbered in Morton order of their centres inside a level, so a unit's
// neighbours lie close in memory. An inherited graph is contracted only at a level that
// inherits it (the previous level keeps its graph and each unit's next position; most levels
// rebuild), and the level's buffers are reused until the unit count halves.
// Merging then only touches the graph: a priority queue (heapified at once from every unit's
// cheapest neighbour; just after a rebuild that is the head of the unit's own list) holds each
// group's cheapest neighbour pair and is invalidated lazily (an entry whose partner has since
// merged is recomputed when it reaches the top; the adjacent groups are gathered and prefetched
// before they are costed). A popped entry whose two groups are alive is the global minimum: every
// live qualifying pair is covered by an entry of one of its groups with a key no larger than its
// own. Every pair cost that only has to be compared with a limit (the budget, the best found so
// far) goes through CostModel::mergeCostWithin, which stops at the cheap r^3 or V bound before the
// exact overlap volume. None of this changes which pairs are found or their order, so the tree is
// the reference's (the property tests compare them). Near n log n for spatially coherent scenes,
// memory linear in n (K edges per unit). The sampled searches run in parallel (TBB), each writing
// its own slot, so the tree does not depend on the thread count.
#pragma once

#include <vector>

#include "pipeline/cluster/TreeBuilder.h"
#include "pipeline/core/Progress.h"

namespace hlod {

// The constants of the rule (tests vary them; production uses the defaults).
struct LevelMergeOptions {
    std::size_t budgetSample = 256; // S of rule 2, >= 1
    std::size_t neighbours = 8;     // K of rule 3, 1..255
    std::size_t rebuildRatio = 2;   // R of rule 3, >= 1 (1: rebuild at every level)
    double graphBudgetFactor = 2.0; // G of rule 3, >= 1
    // Not a rule constant: run the spatial queries with the baseline vector width even where
    // AVX2 code could run (MergeBvh.h; the tests compare both, the tree is the same).
    bool baselineSimd = false;
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
