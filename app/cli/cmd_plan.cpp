// `hlod plan SCENE... --shards N --cache DIR [import, cluster and bake flags] [--json]` and
// `hlod plan PROJECT.hlodproj [--export ID|NAME] --shards N --cache DIR`: the first step of a
// distributed bake (issue 21). Imports once, clusters, cuts the tree into N cost-balanced shards
// and writes the plan into the shared cache folder (pipeline/graph/BakePlan.h): the tree, every
// shard's slice of the scene and the bake parameters. Then `hlod build --shard I/N --cache DIR` on
// each machine, and the final `hlod build SCENE... -o PKG --cache DIR` with the same flags.
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "Commands.h"
#include "DocumentInput.h"
#include "ProgressBar.h"
#include "pipeline/core/Error.h"
#include "pipeline/graph/BakePlan.h"

namespace hlod::cli {

namespace {

const std::vector<NodeKind> kPlanKinds{NodeKind::Import, NodeKind::Cluster, NodeKind::Bake};

// The Bake node whose package the final build writes (the branch of the one Export node, or of
// the one --export picks), and the Cluster node feeding it.
std::pair<NodeId, NodeId> bakeChain(PipelineGraph& graph, const std::optional<std::string>& pick) {
    const std::vector<NodeId> exports = pickExports(graph, pick, std::nullopt);
    if (exports.size() != 1) {
        throw Error(ErrorCode::InvalidArgument,
                    "a plan bakes one branch, and the project has " +
                        std::to_string(exports.size()) +
                        " Export nodes: pick one with --export ID|NAME");
    }
    const NodeId bake = graph.upstreamOfKind(exports[0], NodeKind::Bake);
    const NodeId cluster = graph.upstreamOfKind(exports[0], NodeKind::Cluster);
    if (bake == kNoNode || cluster == kNoNode) {
        throw Error(ErrorCode::InvalidArgument,
                    describeNode(graph.node(exports[0])) +
                        " has no Cluster -> Bake chain upstream to plan");
    }
    return {bake, cluster};
}

void printPlan(const PlanSummary& s, const std::filesystem::path& cache, double clusterSeconds) {
    const double total = s.shards.totalCost > 0.0 ? s.shards.totalCost : 1.0;
    std::printf("plan:         %s (id %s): %d shards over %zu inner nodes (%zu nodes), "
                "clustered in %.2f s, written in %.2f s\n",
                s.folder.string().c_str(), s.id.c_str(), s.shards.shards, s.innerNodes, s.nodes,
                clusterSeconds, s.seconds);
    if (s.shards.secondsPerTriangle > 0.0) {
        std::printf("cost:         CPU seconds, each distinct proxy once: %.1f in all (%zu inner "
                    "nodes measured by an earlier run, the others estimated at %.3g s per input "
                    "triangle)\n",
                    s.shards.totalCost, s.shards.measuredNodes, s.shards.secondsPerTriangle);
    } else {
        std::printf("cost:         estimated input triangles, each distinct proxy once: %.0f in "
                    "all (no measured costs in the cache)\n",
                    s.shards.totalCost);
    }
    for (int i = 0; i < s.shards.shards; ++i) {
        const auto k = static_cast<std::size_t>(i);
        std::printf("shard %-6d  %4zu subtrees, %6zu inner nodes, cost %12.6g (%5.1f%%), slice "
                    "%zu meshes, %zu triangles, %.2f MB\n",
                    i, s.shards.roots[k].size(), s.shardInnerNodes[k], s.shards.cost[k],
                    100.0 * s.shards.cost[k] / total, s.shardMeshes[k], s.shardTriangles[k],
                    static_cast<double>(s.shardBytes[k]) / 1e6);
    }
    std::printf("above cut:    %zu nodes baked by the final step, cost %.6g (%.1f%%)\n",
                s.shards.top.size(), s.shards.topCost, 100.0 * s.shards.topCost / total);
    std::printf("balance:      largest shard %.2fx the mean; predicted speed-up of the bake on %d "
                "machines %.2fx (Amdahl: all / (above cut + largest shard))\n",
                s.shards.largestOverMean(), s.shards.shards, s.shards.predictedSpeedup());
    std::printf("final step:   %s\n",
                s.lean ? "lean: the final build reads the plan and the shards' tiles, not the scene"
                       : "imports the scene again (a textured scene, hand edits, or the root below "
                         "the cut)");
    std::printf("next:         hlod build --shard I/%d --cache %s   (I = 0..%d, or auto/%d in a "
                "job array)\n"
                "              hlod build SCENE... -o PKG --cache %s   (same flags as this plan)\n",
                s.shards.shards, cache.string().c_str(), s.shards.shards - 1, s.shards.shards,
                cache.string().c_str());
}

nlohmann::json planJson(const PlanSummary& s) {
    nlohmann::json shards = nlohmann::json::array();
    for (int i = 0; i < s.shards.shards; ++i) {
        const auto k = static_cast<std::size_t>(i);
        shards.push_back({{"index", i},
                          {"subtrees", s.shards.roots[k].size()},
                          {"inner_nodes", s.shardInnerNodes[k]},
                          {"cost", s.shards.cost[k]},
                          {"meshes", s.shardMeshes[k]},
                          {"triangles", s.shardTriangles[k]},
                          {"bytes", s.shardBytes[k]}});
    }
    return {{"plan", s.folder.string()},
            {"id", s.id},
            {"shards", s.shards.shards},
            {"nodes", s.nodes},
            {"inner_nodes", s.innerNodes},
            {"cost",
             {{"total", s.shards.totalCost},
              {"above_cut", s.shards.topCost},
              {"unit", s.shards.secondsPerTriangle > 0.0 ? "cpu_seconds" : "triangles"},
              {"measured_nodes", s.shards.measuredNodes}}},
            {"balance",
             {{"largest_over_mean", s.shards.largestOverMean()},
              {"predicted_speedup", s.shards.predictedSpeedup()}}},
            {"above_cut_nodes", s.shards.top.size()},
            {"lean_final", s.lean},
            {"shard_list", shards},
            {"seconds", s.seconds}};
}

} // namespace

int runPlan(const CommandArgs& argv) {
    const Args args(argv, command("plan"));
    const ParamFlags flags = paramsFromArgs(args, kPlanKinds); // usage errors before any work
    if (!args.has("--shards")) throw Error(ErrorCode::InvalidArgument, "missing --shards N");
    const int shards = args.integer("--shards", 1, 1, 100000);
    Document doc = documentFromArgs(args.positionals(), flags);
    PipelineGraph& graph = doc.graph();
    const auto [bakeNode, clusterNode] = bakeChain(graph, args.value("--export"));
    const ParamValues& bakeValues = graph.node(bakeNode).params;
    if (!paramBool(bakeValues, "cache"))
        throw Error(ErrorCode::InvalidArgument, "a plan needs the proxy cache (drop --no-cache)");
    if (paramText(bakeValues, "cache_dir").empty())
        throw Error(ErrorCode::InvalidArgument,
                    "missing --cache DIR (the folder every shard and the final build share)");
    const std::filesystem::path cache = paramText(bakeValues, "cache_dir");

    ProgressBar bar;
    graph.run({clusterNode}, bar.progress());
    const NodeOutput& out = *graph.output(clusterNode);
    const GlbCompression compression =
        glbCompressionFromString(args.value("--compression").value_or("meshopt"));
    const std::optional<LeanInputs> lean = leanInputsOf(graph, clusterNode, compression);
    const PlanSummary s = writeBakePlan(cache, *out.scene, *out.tree, bakeValues, shards,
                                        bar.progress(), lean ? &*lean : nullptr);
    bar.finish();
    if (args.has("--json")) {
        std::cout << planJson(s).dump(2) << "\n";
    } else {
        printPlan(s, cache, out.clusterSeconds);
    }
    return 0;
}

} // namespace hlod::cli
