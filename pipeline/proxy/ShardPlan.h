// Cutting a cluster tree into the shards of a distributed bake (issue 21, docs/architecture.md
// "Distributed bake"). A shard bakes whole subtrees (bakeSubtrees, ProxyBaker.h) into the
// shared cache; the final step bakes the nodes above the cut, finding everything below in the
// cache (a proxy is a pure function of its subtree, so the package is the single machine's).
//
// Cost: a node's bake is estimated by its input triangles: its leaf children's triangles plus
// rho (BakeParams::proxyRatio, the most a kept proxy holds of its inputs) times the estimated
// input of each inner child. Translated copies of a cluster bake once (equal structuralKeys):
// subtrees with equal root keys go to one shard, where the first is baked and the others
// reused. Shared work: a key shared deeper down (the same part under different subtrees) is
// baked once too. Two groups of subtrees sharing at least half of the smaller one's cost are
// merged and go to one shard (apart, whichever shard reached the shared nodes first would bake
// them all, and the loads would depend on timing); smaller overlaps are left to the cache's
// claims (ProxyCache.h: one bakes, the others wait and reuse), each group charged its share of
// such a key's cost. A key held by more than 16 groups merges nothing.
// Measured costs (issue 30): a shard records each node it baked, its CPU seconds under the
// node's structural key (BakeCosts.h); when the cache holds such records from an earlier run,
// a node found there costs its measured seconds and every other node its estimate times the
// measured seconds per estimated triangle (the ratio over the nodes found), so costs are in
// CPU seconds; without records, in estimated triangles.
// Cut: best-first search. Starting from the root as the only unit, one unit is split at a time
// (its inner children become units, it moves above the cut): of the 8 costliest units, the one
// whose split gives the lowest estimated makespan, the cost above the cut (the final step,
// serial) plus the largest shard's. The search goes on past splits that do not lower the
// makespan (a heavy shard made of several units only gets lighter after several splits) and
// keeps the best cut seen; it stops when no cut can beat that one any more: the cost above the
// cut only grows, and a makespan is at least total / N + above * (1 - 1/N). So a shard may
// take many small subtrees, and one heavy subtree is split below its root. Units are put into
// shards largest first, each into the least loaded shard (LPT), so the shards' costs are
// balanced, not their numbers of subtrees. A shard may get nothing when there are fewer units
// than shards.
// Determinism: a pure function of its inputs.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/proxy/ProxyBaker.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

struct ShardPlan {
    int shards = 0;
    std::vector<std::vector<Id>> roots; // per shard: its subtree roots (inner nodes), ascending
    std::vector<double> cost;           // per shard: estimated input triangles it bakes (its
                                        // share of what it has in common with other shards)
    std::vector<Id> top;                // inner nodes above the cut (the final step's), ascending
    double topCost = 0.0;               // their estimated input triangles
    double totalCost = 0.0;             // every distinct node's (the single machine's work)
    std::size_t measuredNodes = 0;      // inner nodes costed by a measurement (see "Measured")
    double secondsPerTriangle = 0.0;    // > 0: costs are CPU seconds, estimates scaled by it

    // Predicted balance: the largest shard's cost over the mean shard's (1 = perfect).
    double largestOverMean() const;
    // Amdahl's speed-up of the bake on `shards` machines: every distinct node's cost over the
    // serial part's (above the cut) plus the largest shard's.
    double predictedSpeedup() const;
};

// CPU seconds of a node's bake by its structural key (structuralKeys), measured earlier.
using MeasuredCosts = std::unordered_map<std::uint64_t, double>;

// Throws Error(InvalidArgument) unless 1 <= shards <= 100000.
ShardPlan planShards(const Scene& scene, const ClusterTree& tree, const BakeParams& params,
                     int shards, const MeasuredCosts& measured = {});
// The same from the structural keys already computed.
ShardPlan planShards(const Scene& scene, const ClusterTree& tree, const BakeParams& params,
                     int shards, const std::vector<std::uint64_t>& keys,
                     const MeasuredCosts& measured);

// What the bake of the subtrees under `roots` reads of `scene`: the meshes of their leaves
// (every other mesh emptied: no vertices, no indices) and the textures of those meshes'
// materials (every other texture without its image). Nodes, materials and instances are kept,
// so every id is unchanged and the bake's keys are those of the whole scene.
Scene sliceScene(const Scene& scene, const ClusterTree& tree, const std::vector<Id>& roots);
// The same keeping the meshes with `meshUsed[m]` != 0 (one entry per scene mesh).
Scene sliceScene(const Scene& scene, const std::vector<char>& meshUsed);

} // namespace hlod
