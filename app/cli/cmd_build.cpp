// `hlod build SCENE... -o DIR [--volume V] [--k K] [--max-children N]
// [--proxy decimate|remesh|sloppy] [--screen-size PX] [--pixel-error PX] [--fov DEG]
// [--viewport-height PX] [--threads N] [--cache DIR] [--no-cache] [--no-dlod] [--geo LAT,LON,H]
// [--deflection R] [--brep-unit M] [--compression meshopt|none] [--json]` and `hlod build
// PROJECT.hlodproj [-o DIR] [--export ID|NAME] [flags]`: runs the pipeline graph
// (pipeline/graph/PipelineGraph.h) headless — import, cluster, bake every inner node's proxy,
// write the package — then prints the thesis-style statistics table.
//
// Branches: every Export node of a project runs (each path Import -> Cluster -> Bake -> Export
// is a variant; a shared Import is read once), each writing its package to its own output folder
// (relative folders in the project are the project's, ProjectFile.h), and a table is printed per
// branch (--json: one object, or {"branches": [...]} for several). --export picks one Export by
// id or name; -o sets the output folder of the one Export that runs (refused when several run).
// A graph the runner cannot run (an input not connected, an Export without a folder, two Exports
// writing one folder) is refused before anything runs, in one line naming the node.
// The flags are generated from the parameter declarations (pipeline/graph/Parameters.h); only
// --json, --export and --shard are this command's own. Flags given on the command line override
// the project's values on every node of their kind. Without a project the default graph
// Import -> Cluster -> Bake -> Export runs over the SCENE files.
// The proxies line is followed by the bake's throughput (the scene's original triangles per
// CPU second of the bake, every thread's time counted) and the process's peak memory.
// The summary ends with the package's bytes on disk (allocated blocks) and file count next to
// the source's (the scene files and every file they reference), and their ratio.
//
// Distributed bake (issue 21, pipeline/graph/BakePlan.h): `hlod build --shard I/N --cache DIR`
// (or `auto/N`: I from SLURM_ARRAY_TASK_ID, JOB_COMPLETION_INDEX or AWS_BATCH_JOB_ARRAY_INDEX)
// bakes shard I of the plan `hlod plan` wrote into DIR and exits; it takes the scene and the
// parameters from the plan (only --threads may be given). A plain build whose cache folder
// holds the plan for its scene and parameters is the final step: it first checks that every
// shard has finished (else it fails naming the missing ones), then bakes the nodes above the
// cut, finds the rest in the cache, and writes the package a single machine writes.
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <malloc.h>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "Args.h"
#include "Commands.h"
#include "DocumentInput.h"
#include "ProgressBar.h"
#include "pipeline/core/Error.h"
#include "pipeline/export/Geo.h"
#include "pipeline/graph/BakePlan.h"
#include "pipeline/graph/LeanFinal.h"
#include "pipeline/proxy/BakeStats.h"

namespace hlod::cli {

namespace {

const std::vector<NodeKind> kAllKinds{NodeKind::Import, NodeKind::Cluster, NodeKind::Bake,
                                      NodeKind::Export};

void printTable(const std::vector<GeometryStats>& rows) {
    std::printf("%-20s %12s %12s %8s %12s\n", "version", "triangles", "vertices", "meshes",
                "space (MB)");
    for (const GeometryStats& r : rows) {
        std::printf("%-20s %12zu %12zu %8zu %12.2f\n", r.version.c_str(), r.triangles, r.vertices,
                    r.meshes, static_cast<double>(r.bytes) / 1.0e6);
    }
}

void printLevels(const std::vector<LevelRow>& rows, const BakeResult& bake, double ratio) {
    std::printf("levels:       %5s %7s %9s %21s %11s %7s\n", "level", "nodes", "children",
                "error budget (m)", "triangles", "share");
    for (const LevelRow& r : rows) {
        if (r.level == 0) {
            std::printf("              %5d %7zu %9s %21s %11zu %6.1f%%  (original meshes)\n",
                        r.level, r.nodes, "-", "-", r.triangles, r.share * 100.0);
            continue;
        }
        char budget[64];
        std::snprintf(budget, sizeof(budget), "%.3g - %.3g", r.budgetMin, r.budgetMax);
        std::printf("              %5d %7zu %9.1f %21s %11zu %6.1f%%\n", r.level, r.nodes,
                    r.meanChildren, budget, r.triangles, r.share * 100.0);
    }
    std::printf("dissolved:    %zu clusters whose proxy did not pay for itself (more than %g x "
                "the triangles it replaces)\n",
                bake.dissolved, ratio);
}

// Bytes on disk (allocated blocks) of the package next to the source's (DiskUsage.h).
void printDisk(const ExportResult& ex) {
    const PackageSummary& p = ex.written;
    std::printf("on disk:      package %.2f MB in %zu files (%zu tiles; %zu written, %zu "
                "unchanged), source %.2f MB in %zu files",
                static_cast<double>(p.bytesOnDisk) / 1.0e6, p.files, p.tiles, p.written, p.reused,
                static_cast<double>(ex.source.bytesOnDisk) / 1.0e6, ex.source.files);
    if (ex.source.bytesOnDisk > 0)
        std::printf(": %.2fx the source", static_cast<double>(p.bytesOnDisk) /
                                              static_cast<double>(ex.source.bytesOnDisk));
    std::printf("\n");
}

// The branch that made an Export node's package: "Import #1 -> Cluster #5 -> Bake #6 -> Export
// #7 'pkg-b'".
std::string branchText(const PipelineGraph& graph, NodeId exportNode) {
    std::string text;
    for (NodeId id : graph.branchOf(exportNode))
        text += (text.empty() ? "" : " -> ") + describeNode(graph.node(id));
    return text;
}

nlohmann::json branchJson(const PipelineGraph& graph, NodeId exportNode) {
    const GraphNode& n = graph.node(exportNode);
    return {{"export", exportNode}, {"name", n.name}, {"nodes", graph.branchOf(exportNode)}};
}

// Original triangles of the scene per CPU second of the bake (0 when the bake took no time,
// e.g. everything came from the cache within the clock's resolution).
double bakeThroughput(const NodeOutput& out) {
    const double cpu = out.bake->cpuSeconds;
    return cpu > 0.0 ? static_cast<double>(out.scene->stats().triangles) / cpu : 0.0;
}

nlohmann::json resultJson(const PipelineGraph& graph, NodeId exportNode, const PlanCheck& plan) {
    const NodeOutput& out = *graph.output(exportNode);
    const ExportResult& ex = *out.exported;
    nlohmann::json j = buildTreeJson(*out.scene, *out.tree, *out.bake, ex.info);
    j.erase("nodes");
    j["branch"] = branchJson(graph, exportNode);
    j["output"] = ex.output.string();
    j["output_bytes"] = ex.written.bytes;
    j["package"] = {{"files", ex.written.files},
                    {"bytes", ex.written.bytes},
                    {"bytes_on_disk", ex.written.bytesOnDisk},
                    {"tiles", ex.written.tiles},
                    {"written", ex.written.written},
                    {"unchanged", ex.written.reused}};
    j["source"] = {{"files", ex.source.files},
                   {"bytes", ex.source.bytes},
                   {"bytes_on_disk", ex.source.bytesOnDisk}};
    j["disk_ratio"] = ex.source.bytesOnDisk
                          ? static_cast<double>(ex.written.bytesOnDisk) / ex.source.bytesOnDisk
                          : 0.0;
    if (plan.matches) {
        j["plan"] = {{"id", plan.id},
                     {"shards", plan.shards},
                     {"above_cut", plan.aboveCut},
                     {"baked_here", out.bake->baked},
                     {"damaged", out.bake->damaged}};
    }
    j["seconds"] = {{"cluster", out.clusterSeconds},
                    {"bake", out.bake->seconds},
                    {"bake_cpu", out.bake->cpuSeconds},
                    {"dlod", ex.dlodSeconds},
                    {"write", ex.writeSeconds}};
    j["bake_triangles_per_cpu_second"] = bakeThroughput(out);
    j["peak_bytes"] = processUsage().peakBytes;
    return j;
}

void printSummary(const PipelineGraph& graph, NodeId exportNode, const PlanCheck& plan) {
    const NodeOutput& out = *graph.output(exportNode);
    const ExportResult& ex = *out.exported;
    const BakeResult& bake = *out.bake;
    const ClusterTree& tree = *out.tree;
    const BakeParams& bp = out.bakeParams;
    std::printf("branch:       %s\n", branchText(graph, exportNode).c_str());
    std::printf("scene:        ");
    for (const auto& in : out.inputs)
        std::printf("%s ", in.c_str());
    std::printf("\nclusters:     %s, %zu nodes (%zu inner), height %d, %.2f s\n",
                hlodVersionName(tree).c_str(), tree.nodes.size(), bake.innerNodes, tree.height(),
                out.clusterSeconds);
    if (!out.edits.empty()) {
        std::printf("hand edits:   %zu locked groups, %zu excluded, %zu split\n",
                    out.edits.locked.size(), out.edits.excluded.size(), out.edits.dissolved.size());
    }
    std::printf("proxies:      %s at %g px / %g px: baked %zu, reused %zu in %.2f s "
                "(%zu input triangles)\n",
                toString(bp.method), bp.screen.screenSize, bp.screen.pixelError, bake.baked,
                bake.reused, bake.seconds, bake.inputTriangles);
    const ProcessUsage use = processUsage();
    std::printf("throughput:   %.0f k original triangles per CPU second of the bake (%.2f CPU s); "
                "peak memory %.0f MB\n",
                bakeThroughput(out) / 1e3, bake.cpuSeconds,
                static_cast<double>(use.peakBytes) / 1e6);
    if (plan.matches) {
        std::printf("plan:         %s: all %d shards finished; baked here %zu (%zu nodes above the "
                    "cut), the rest from the shards\n",
                    plan.id.c_str(), plan.shards, bake.baked, plan.aboveCut);
    }
    std::printf("proxy share:  all proxies %.1f%% of the original triangles, root proxy %.2f%%, "
                "a proxy %.1f%% of what it replaces\n",
                ex.info.share.allProxies * 100.0, ex.info.share.rootProxy * 100.0,
                ex.info.share.replaced * 100.0);
    printLevels(ex.info.levels, bake, bp.proxyRatio);
    printTable(ex.info.statistics);
    std::printf("output:       %s (%.2f MB)\n", ex.output.string().c_str(),
                static_cast<double>(ex.written.bytes) / 1.0e6);
    printDisk(ex);
}

// `--shard I/N` or `auto/N`: the index and the count.
std::pair<int, int> parseShard(const std::string& text) {
    const auto slash = text.find('/');
    auto number = [&](const std::string& part) {
        int v = -1;
        const auto [ptr, ec] = std::from_chars(part.data(), part.data() + part.size(), v);
        return ec == std::errc() && ptr == part.data() + part.size() ? v : -1;
    };
    const int n = slash == std::string::npos ? -1 : number(text.substr(slash + 1));
    const std::string first = slash == std::string::npos ? "" : text.substr(0, slash);
    const int i = first == "auto" ? shardIndexFromEnvironment(std::getenv) : number(first);
    if (n < 1 || i < 0 || i >= n) {
        throw Error(ErrorCode::InvalidArgument,
                    "--shard expects I/N with 0 <= I < N, or auto/N, got '" + text + "'");
    }
    return {i, n};
}

// Farm steps run on machines sized by their peak memory: blocks of 1 MB and more are given back
// to the system as soon as they are freed (glibc otherwise raises the threshold after such a
// free and keeps later blocks in its arenas). Engine tiled 100x: shard 344 -> 313 MB, lean final
// step 328 -> 285 MB, for about 3 % more CPU (docs/benchmarks.md, "Distributed bake").
void returnLargeBlocksAtOnce() {
    mallopt(M_MMAP_THRESHOLD, 1 << 20);
    // One heap for every thread: glibc's per-thread arenas each keep their own freed memory
    // (shard of the engine tiled 100x alone: 217 -> 202 MB, no measurable CPU change).
    mallopt(M_ARENA_MAX, 1);
}

// `hlod build --shard I/N --cache DIR`: one shard of the plan in DIR.
int runShardBuild(const Args& args, const ParamFlags& flags) {
    returnLargeBlocksAtOnce();
    if (!args.positionals().empty()) {
        throw Error(ErrorCode::InvalidArgument,
                    "a shard takes its scene from the plan: hlod build --shard I/N --cache DIR (no "
                    "SCENE)");
    }
    std::filesystem::path cache;
    int threads = 0;
    for (const auto& [decl, value] : flags) {
        if (decl->key == "cache_dir") {
            cache = std::get<std::string>(value);
        } else if (decl->key == "threads") {
            threads = std::get<int>(value);
        } else {
            throw Error(ErrorCode::InvalidArgument,
                        decl->cliFlag + " cannot be given with --shard: a shard takes its "
                                        "parameters from the plan (hlod plan; only --cache and "
                                        "--threads go here)");
        }
    }
    if (cache.empty()) throw Error(ErrorCode::InvalidArgument, "--shard needs --cache DIR");
    const auto [index, shards] = parseShard(*args.value("--shard"));
    ProgressBar bar;
    const ShardResult r = runBakeShard(cache, index, shards, threads, bar.progress());
    bar.finish();
    const ProcessUsage use = processUsage();
    if (args.has("--json")) {
        const nlohmann::json j = {{"shard", r.index},
                                  {"shards", r.shards},
                                  {"subtrees", r.subtrees},
                                  {"inner_nodes", r.innerNodes},
                                  {"baked", r.baked},
                                  {"reused", r.reused},
                                  {"damaged", r.corrupt},
                                  {"meshes", r.meshes},
                                  {"triangles", r.triangles},
                                  {"seconds", r.seconds},
                                  {"cpu_seconds", use.cpuSeconds},
                                  {"peak_bytes", use.peakBytes},
                                  {"marker", r.marker.string()}};
        std::cout << j.dump(2) << "\n";
        return 0;
    }
    std::printf("shard:        %d/%d of the plan in %s\n", r.index, r.shards,
                planFolder(cache).string().c_str());
    std::printf("subtrees:     %zu (%zu inner nodes); slice %zu meshes, %zu triangles\n",
                r.subtrees, r.innerNodes, r.meshes, r.triangles);
    std::printf("proxies:      baked %zu, reused %zu in %.2f s (cpu %.2f s, peak memory %.0f MB)\n",
                r.baked, r.reused, r.seconds, use.cpuSeconds,
                static_cast<double>(use.peakBytes) / 1e6);
    if (r.corrupt > 0)
        std::printf("damaged:      %zu cache files were damaged and baked again\n", r.corrupt);
    std::printf("done:         %s\n", r.marker.string().c_str());
    return 0;
}

// The final step of a distributed bake: when the cache folder holds the plan of this very
// build, every shard must have finished. Returns the check (found false without a plan).
PlanCheck checkPlanBeforeBake(PipelineGraph& graph, NodeId exportNode, const Progress& progress) {
    const NodeId bakeNode = graph.upstreamOf(exportNode);
    if (bakeNode == kNoNode || graph.node(bakeNode).kind != NodeKind::Bake) return {};
    const BakeParams params = bakeParamsFrom(graph.node(bakeNode).params);
    std::error_code ec;
    if (params.cacheDir.empty() ||
        !std::filesystem::exists(planFolder(params.cacheDir) / "plan.json", ec))
        return {};
    const NodeId clusterNode = graph.upstreamOf(bakeNode);
    if (clusterNode == kNoNode) return {};
    graph.run({clusterNode}, progress);
    const NodeOutput& out = *graph.output(clusterNode);
    PlanCheck check = checkBakePlan(params.cacheDir, *out.scene, *out.tree, params);
    if (check.found && !check.matches) {
        std::fprintf(stderr,
                     "hlod build: warning: %s holds a plan for another scene or other parameters; "
                     "baking everything here\n",
                     planFolder(params.cacheDir).string().c_str());
    } else if (check.matches && !check.missing.empty()) {
        throw Error(ErrorCode::FileNotFound, planFolder(params.cacheDir),
                    describeMissingShards(check) + ": run hlod build --shard I/" +
                        std::to_string(check.shards) + " --cache " + params.cacheDir.string() +
                        " for them, or wait for their jobs");
    }
    return check;
}

// The final step of a distributed bake without importing (pipeline/graph/LeanFinal.h), when the
// cache folder holds a lean plan made from exactly this build's inputs; nullopt otherwise (the
// build runs its graph, and a classic plan is checked there).
std::optional<int> runLeanFinalStep(const PipelineGraph& graph, NodeId exportNode, bool json) {
    const GraphNode& exportGraphNode = graph.node(exportNode);
    const NodeId bakeNode = graph.upstreamOf(exportNode);
    if (bakeNode == kNoNode || graph.node(bakeNode).kind != NodeKind::Bake) return std::nullopt;
    const NodeId clusterNode = graph.upstreamOf(bakeNode);
    if (clusterNode == kNoNode || graph.node(clusterNode).kind != NodeKind::Cluster)
        return std::nullopt;
    const GlbCompression compression =
        glbCompressionFromString(paramText(exportGraphNode.params, "compression"));
    const std::optional<LeanInputs> given = leanInputsOf(graph, clusterNode, compression);
    if (!given) return std::nullopt;
    LeanFinalRequest request;
    request.given = *given;
    request.bakeValues = graph.node(bakeNode).params;
    const BakeParams bp = bakeParamsFrom(request.bakeValues);
    request.cacheDir = bp.cacheDir;
    request.threads = bp.threads;
    request.output = paramText(exportGraphNode.params, "output");
    request.cluster = clusterParamsFrom(graph.node(clusterNode).params);
    const GraphNode& importNode = graph.node(graph.upstreamOf(clusterNode));
    for (const auto& p : importNode.sources)
        request.inputs.push_back(p.string());
    if (request.inputs.empty()) request.inputs = {"sample:plant"};
    if (const std::string geo = paramText(exportGraphNode.params, "geo"); !geo.empty())
        request.geo = parseGeoLocation(geo);
    const LeanCheck check = checkLeanPlan(request);
    if (!check.lean) return std::nullopt;
    if (paramBool(exportGraphNode.params, "dlod")) {
        std::fprintf(stderr, "hlod build: note: the DLOD statistics row needs the whole scene: "
                             "importing it for the final step (--no-dlod reads only the plan "
                             "and the shards' tiles)\n");
        return std::nullopt;
    }
    if (!check.missing.empty()) {
        PlanCheck missing;
        missing.shards = check.shards;
        missing.missing = check.missing;
        throw Error(ErrorCode::FileNotFound, planFolder(request.cacheDir),
                    describeMissingShards(missing) + ": run hlod build --shard I/" +
                        std::to_string(check.shards) + " --cache " + request.cacheDir.string() +
                        " for them, or wait for their jobs");
    }
    returnLargeBlocksAtOnce();
    ProgressBar bar;
    const LeanFinalResult r = runLeanFinal(request, bar.progress());
    bar.finish();
    const ExportResult& ex = r.export_;
    const ProcessUsage use = processUsage();
    if (json) {
        nlohmann::json j = {{"branch", branchJson(graph, exportNode)},
                            {"output", ex.output.string()},
                            {"output_bytes", ex.written.bytes},
                            {"package",
                             {{"files", ex.written.files},
                              {"bytes", ex.written.bytes},
                              {"bytes_on_disk", ex.written.bytesOnDisk},
                              {"tiles", ex.written.tiles},
                              {"written", ex.written.written},
                              {"unchanged", ex.written.reused}}},
                            {"source",
                             {{"files", ex.source.files},
                              {"bytes", ex.source.bytes},
                              {"bytes_on_disk", ex.source.bytesOnDisk}}},
                            {"plan",
                             {{"id", check.id},
                              {"shards", check.shards},
                              {"above_cut", check.aboveCut},
                              {"baked_here", r.bake.baked},
                              {"damaged", r.bake.damaged},
                              {"lean", true}}},
                            {"proxy_share",
                             {{"all_proxies", ex.info.share.allProxies},
                              {"root_proxy", ex.info.share.rootProxy},
                              {"replaced", ex.info.share.replaced}}},
                            {"seconds",
                             {{"final", r.seconds},
                              {"bake", r.bake.seconds},
                              {"bake_cpu", r.bake.cpuSeconds},
                              {"write", ex.writeSeconds}}},
                            {"peak_bytes", use.peakBytes}};
        std::cout << j.dump(2) << "\n";
        return 0;
    }
    const BakeParams& params = ex.info.bake;
    std::printf("branch:       %s\n", branchText(graph, exportNode).c_str());
    std::printf("scene:        ");
    for (const auto& in : request.inputs)
        std::printf("%s ", in.c_str());
    std::printf("(not imported: the plan and the shards' tiles hold what the final step needs)\n");
    std::printf("clusters:     %s, %zu nodes (%zu inner), height %d, from the plan\n",
                hlodVersionName(r.tree).c_str(), r.tree.nodes.size(), r.bake.innerNodes,
                r.tree.height());
    std::printf("proxies:      %s at %g px / %g px: baked %zu, reused %zu above the cut in %.2f s; "
                "the shards baked %zu, reused %zu\n",
                toString(params.method), params.screen.screenSize, params.screen.pixelError,
                r.bake.baked, r.bake.reused, r.bake.seconds, r.shardBaked, r.shardReused);
    std::printf("plan:         %s: all %d shards finished; lean final step (%zu nodes above the "
                "cut) in %.2f s, %.2f CPU s, peak memory %.0f MB\n",
                check.id.c_str(), check.shards, check.aboveCut, r.seconds, use.cpuSeconds,
                static_cast<double>(use.peakBytes) / 1e6);
    std::printf("proxy share:  all proxies %.1f%% of the original triangles, root proxy %.2f%%, "
                "a proxy %.1f%% of what it replaces\n",
                ex.info.share.allProxies * 100.0, ex.info.share.rootProxy * 100.0,
                ex.info.share.replaced * 100.0);
    printLevels(ex.info.levels, r.bake, params.proxyRatio);
    printTable(ex.info.statistics);
    std::printf("output:       %s (%.2f MB)\n", ex.output.string().c_str(),
                static_cast<double>(ex.written.bytes) / 1.0e6);
    printDisk(ex);
    return 0;
}

void warnDamaged(const NodeOutput& out) {
    if (const std::size_t n = out.bake->damaged; n > 0) {
        std::fprintf(stderr,
                     "hlod build: warning: %zu damaged proxy %s in the cache %s not trusted and "
                     "%s baked again\n",
                     n, n == 1 ? "file" : "files", n == 1 ? "was" : "were",
                     n == 1 ? "was" : "were");
    }
}

} // namespace

int runBuild(const CommandArgs& argv) {
    const Args args(argv, command("build"));
    ParamFlags flags = paramsFromArgs(args, kAllKinds); // usage errors before any work
    if (args.has("--shard")) return runShardBuild(args, flags);
    const std::optional<std::string> output = takeOutputFlag(flags);
    Document doc = documentFromArgs(args.positionals(), flags);
    PipelineGraph& graph = doc.graph();
    const std::vector<NodeId> exports = pickExports(graph, args.value("--export"), output);
    graph.checkRunnable(exports); // a graph that cannot run is refused before any work

    if (exports.size() == 1) {
        if (const std::optional<int> lean = runLeanFinalStep(graph, exports[0], args.has("--json")))
            return *lean;
    }
    ProgressBar bar;
    std::vector<PlanCheck> plans;
    for (NodeId exportNode : exports)
        plans.push_back(checkPlanBeforeBake(graph, exportNode, bar.progress()));
    graph.run(exports, bar.progress());
    bar.finish();
    for (NodeId exportNode : exports)
        warnDamaged(*graph.output(exportNode));
    if (args.has("--json")) {
        if (exports.size() == 1) {
            std::cout << resultJson(graph, exports[0], plans[0]).dump(2) << "\n";
        } else {
            nlohmann::json branches = nlohmann::json::array();
            for (std::size_t i = 0; i < exports.size(); ++i)
                branches.push_back(resultJson(graph, exports[i], plans[i]));
            std::cout << nlohmann::json{{"branches", branches}}.dump(2) << "\n";
        }
        return 0;
    }
    for (std::size_t i = 0; i < exports.size(); ++i) {
        if (i > 0) std::printf("\n");
        printSummary(graph, exports[i], plans[i]);
    }
    return 0;
}

} // namespace hlod::cli
