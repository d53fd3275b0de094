// The distributed bake's plan (issue 21; README "Baking on a farm", docs/architecture.md): what
// `hlod plan` writes into the shared cache folder, what `hlod build --shard I/N` reads, and what
// the final `hlod build` checks before it bakes the nodes above the cut and writes the package.
//
// Folder CACHE/plan/ (the proxies stay in CACHE/, content-addressed, ProxyCache.h):
//   plan.json      {"format": 2, "id": hex, "shards": N, "bake": Bake parameters (JSON of
//                  Parameters.h), "nodes", "inner_nodes", "cost": {"total", "above_cut"},
//                  "above_cut": [node ids], "shard_list": [{"index", "file", "roots": [node
//                  ids], "cost", "meshes", "triangles"}]}
//   tree.bin       the cluster tree, exact (ClusterTreeBinary.h)
//   keys.bin       per tree node its structural key (structuralKeys, 64-bit little-endian):
//                  under these a shard records what its nodes cost (BakeCosts.h), and the next
//                  plan in this cache folder balances its shards by those measured costs
//   shard-I.scene  shard I's slice of the scene: only the meshes and textures its subtrees
//                  read (sliceScene, SceneBinary.h), so a shard's memory is about its share
//   shard-I.done   written by shard I once all its proxies are in the cache: {"plan", "shard",
//                  "shards", "inner_nodes", "baked", "reused", "seconds"}
//   top.scene, sizes.bin, shard-I.tiles, and plan.json "lean": the lean final step (issue 30,
//                  LeanFinal.h): the shards also write their subtrees' finished tiles, and a
//                  final build made from the plan's very inputs (files by content, parameters)
//                  reads the plan and those tiles instead of importing the scene.
// Format 2 (issue 30) added keys.bin, format 3 the lean final step; a plan of another format is
// refused with "run hlod plan again". tree.bin, keys.bin and the slices end in a 64-bit checksum of
// the bytes before it. The plan is written into a temporary folder that then replaces CACHE/plan,
// so readers see a whole plan or the previous one; a new plan has no shard-I.done files. The id is
// a hash of the scene's content, the tree and the bake parameters (bakeParamsKey): the final build
// finds the plan it belongs to by recomputing it. Paths inside are relative to the plan folder, so
// the cache folder may be mounted at another path on every machine. Failure: Error naming the file:
// FileNotFound for a missing plan or slice ("run hlod plan"), Malformed for a damaged or foreign
// file (bad checksum, bad JSON, wrong format), Io when the folder cannot be written,
// InvalidArgument for a shard index outside the plan.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "pipeline/core/Progress.h"
#include "pipeline/graph/LeanFinal.h"
#include "pipeline/graph/Parameters.h"
#include "pipeline/proxy/ShardPlan.h"

namespace hlod {

// The folder of the plan inside a cache folder.
std::filesystem::path planFolder(const std::filesystem::path& cacheDir);

// Identity of what a plan bakes: the scene's content (not its file paths), the tree, the
// parameters the proxies depend on.
std::uint64_t bakePlanId(const Scene& scene, const ClusterTree& tree, const BakeParams& params);

struct PlanSummary {
    std::filesystem::path folder;
    std::string id; // 16 hex digits
    ShardPlan shards;
    std::size_t nodes = 0, innerNodes = 0;
    std::vector<std::size_t> shardInnerNodes, shardMeshes, shardTriangles; // per shard
    std::vector<std::uint64_t> shardBytes;                                 // slice file sizes
    double seconds = 0.0;
    bool lean = false; // the final step can run lean (LeanFinal.h)
};

// Cuts `tree` into `shards` (planShards) and writes the plan for `bakeValues` (the Bake node's
// parameters; its cache folder and threads are not used) under cacheDir.
// `lean` (LeanFinal.h): what the final build recognises the plan by without importing; given,
// the plan also holds what the lean final step needs (when it can serve the scene).
PlanSummary writeBakePlan(const std::filesystem::path& cacheDir, const Scene& scene,
                          const ClusterTree& tree, const ParamValues& bakeValues, int shards,
                          const Progress& progress = {}, const LeanInputs* lean = nullptr);

struct ShardResult {
    int index = 0, shards = 0;
    std::size_t subtrees = 0, innerNodes = 0, baked = 0, reused = 0, corrupt = 0;
    std::size_t meshes = 0, triangles = 0; // what its slice holds
    double seconds = 0.0;                  // whole run: reading the plan and baking
    std::filesystem::path marker;          // shard-I.done
};

// Shard `index` of the plan in cacheDir: reads the plan, the tree and its slice, bakes its
// subtrees into cacheDir with `threads` workers (0 = all), then writes shard-I.done. Run again
// after a kill it reuses every proxy already in the cache. `shards` must be the plan's count.
ShardResult runBakeShard(const std::filesystem::path& cacheDir, int index, int shards, int threads,
                         const Progress& progress = {});

struct PlanCheck {
    bool found = false;   // cacheDir holds a plan
    bool matches = false; // for this scene, tree and parameters
    int shards = 0;
    std::vector<int> missing; // shards without a (valid) shard-I.done for this plan
    std::size_t aboveCut = 0; // nodes the final step bakes
    std::string id;           // the plan's
};

// What the final build needs to know before baking: whether cacheDir's plan is this build's
// and which of its shards have not finished. Never throws for a missing plan (found false); a
// damaged plan.json is Malformed.
PlanCheck checkBakePlan(const std::filesystem::path& cacheDir, const Scene& scene,
                        const ClusterTree& tree, const BakeParams& params);

// "shards 1 and 3 of 4 have not finished (no shard-1.done, shard-3.done)".
std::string describeMissingShards(const PlanCheck& check);

// The shard index of `--shard auto/N`: the first of SLURM_ARRAY_TASK_ID (Slurm job arrays),
// JOB_COMPLETION_INDEX (Kubernetes Indexed Jobs) and AWS_BATCH_JOB_ARRAY_INDEX (AWS Batch array
// jobs) that is set. `getenv` is injectable for tests. Throws InvalidArgument when none is set
// or the value is not an index.
int shardIndexFromEnvironment(const std::function<const char*(const char*)>& getenv);

} // namespace hlod
