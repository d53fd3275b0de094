// The lean final step of a distributed bake (issue 30; BakePlan.h, README "Baking on a farm"):
// the shards lay out and encode the tiles of their own subtrees, and the final build bakes only
// the nodes above the cut and writes the package from the plan and the shards' tiles, without
// importing or clustering the scene again. Its memory is the tree, the meshes of the leaves that
// hang from nodes above the cut and the proxies they are baked from, not the scene.
// Code: the plan's and the shards' part in ShardTiles.cpp, the final build's in LeanFinal.cpp,
// what they share (file names, JSON) in LeanParts.h.
//
// Files (in CACHE/plan/ unless said):
//   plan.json "lean"  what the final build recognises its plan by without importing (the scene
//                     files as given, absolute, with their sizes and content hashes, and those of
//                     the files they reference; the Import and Cluster parameters; the hlod
//                     version) and what it writes with: the compression, the placement
//                     (Placement.h, of the whole scene). Absent (null) when the lean step cannot
//                     serve the scene: one with textures (a proxy's atlas and the stacked pages
//                     read every original below a node), or a root that is not above the cut.
//   top.scene         the scene without geometry but the meshes of the leaves whose parent is
//                     above the cut (SceneBinary.h, checksummed): nodes, instances, materials
//   sizes.bin         per scene mesh: triangles, vertices, geometry bytes (3 x uint64, checksummed)
//   shard-I.tiles     written by shard I before shard-I.done (JSON, checksummed): per node of its
//                     subtrees the bake's decision (key, frame, budget, dissolved, proxy size);
//                     per subtree root what it hands to the nodes above (itself, or a dissolved
//                     root's inputs) and their look sums (ProxyLook.h); the leaves the final step
//                     needs (those handed up, and those of handed-up subtrees too small for tiles
//                     of their own, PackageLayout.h); and per handed-up subtree with tiles of its
//                     own its layout (planSubtree) and its contents' URIs and leaf ranges.
//   CACHE/tiles/HASH.glb  the contents the shards encoded, named by their bytes' hash (the
//                     package's own names), hard-linked (or copied) into the package.
// Exact: a shard lays its subtrees out with its own dissolved nodes removed, which is how the
// whole tree lays them out (a node's layout reads only its subtree and its proxies); ids are
// stored as the plan tree's and renumbered into the final tree's. So the package is the plain
// build's, byte for byte (tests/app/DistributedBakeTest.cpp, the farm benchmark).
// Failure: Error naming the file: Malformed for a damaged or foreign file, FileNotFound for a
// missing tile or proxy ("run the shard again").
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipeline/cluster/Cluster.h"
#include "pipeline/core/Progress.h"
#include "pipeline/export/Geo.h"
#include "pipeline/graph/ExportStep.h"
#include "pipeline/graph/Parameters.h"
#include "pipeline/io/GlbWriter.h"
#include "pipeline/proxy/ShardPlan.h"

namespace hlod {

// What a build was given, besides the bake parameters: how the plan and the final build are
// matched without importing.
struct LeanInputs {
    std::vector<std::filesystem::path> sources; // scene files, absolute; empty: the sample
    nlohmann::json importParams, clusterParams; // paramsToJson of the Import and Cluster nodes
    GlbCompression compression = GlbCompression::Meshopt;
};

// The plan side: writes top.scene and sizes.bin into `folder` and returns plan.json's "lean"
// entry (null, nothing written, when the lean step cannot serve the scene, see above).
nlohmann::json writeLeanPlan(const std::filesystem::path& folder, const Scene& scene,
                             const ClusterTree& tree, const ShardPlan& shards,
                             const LeanInputs& in);

// The shard side, after its bake: lays out and encodes its subtrees' tiles into CACHE/tiles/
// and writes plan/shard-I.tiles. Nothing when the plan has no "lean" entry.
// The bake's proxies move into the layout (no second copy in memory).
void writeShardTiles(const std::filesystem::path& cacheDir, const nlohmann::json& planJson,
                     int index, const Scene& slice, const ClusterTree& tree,
                     const std::vector<Id>& roots, BakeResult bake);

struct LeanFinalRequest {
    std::filesystem::path cacheDir, output;
    LeanInputs given;
    ParamValues bakeValues;
    ClusterParams cluster;
    std::vector<std::string> inputs; // the scene paths as given (the manifest's "inputs")
    std::optional<GeoLocation> geo;
    int threads = 0;
};

struct LeanCheck {
    bool lean = false; // the plan in the cache folder is this build's and can be used lean
    std::string id;    // the plan's
    int shards = 0;
    std::vector<int> missing; // shards that have not finished (BakePlan.h markers)
    std::size_t aboveCut = 0;
};

// Whether the cache folder holds a lean plan made from exactly these inputs (files by content,
// parameters, hlod version). Never throws for a missing or foreign plan (lean false).
LeanCheck checkLeanPlan(const LeanFinalRequest& request);

struct LeanFinalResult {
    ClusterTree tree;     // the tree the package belongs to (dissolved nodes removed)
    BakeResult bake;      // every node's decision; proxies only above the cut; counts: the
                          // whole bake's, baked and reused this step's
    ExportResult export_; // statistics, package written, source footprint
    std::size_t shardBaked = 0, shardReused = 0;
    double seconds = 0.0;
};

// The final step (checkLeanPlan said lean and no shard is missing).
LeanFinalResult runLeanFinal(const LeanFinalRequest& request, const Progress& progress = {});

} // namespace hlod
