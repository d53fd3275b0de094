// `hlod build SCENE... -o DIR [--volume V] [--k K] [--max-children N]
// [--proxy decimate|remesh|sloppy] [--screen-size PX] [--pixel-error PX] [--fov DEG]
// [--viewport-height PX] [--threads N] [--cache DIR] [--no-cache] [--no-dlod] [--geo LAT,LON,H]
// [--deflection R] [--brep-unit M] [--compression meshopt|none] [--json]` and `hlod build
// PROJECT.hlodproj [-o DIR] [flags]`: runs the pipeline graph (pipeline/graph/PipelineGraph.h)
// headless — import, cluster, bake every inner node's proxy, write the package — then prints the
// thesis-style statistics table.
//
// The flags are generated from the parameter declarations (pipeline/graph/Parameters.h); only
// --json is this command's own. With a project file the project's graph runs as saved, hand
// edits included; flags given on the command line override the project's values on every
// node of their kind, and -o overrides the Export node's output folder. Without a project the
// default graph Import -> Cluster -> Bake -> Export runs over the SCENE files.
// The summary ends with the package's bytes on disk (allocated blocks) and file count next to
// the source's (the scene files and every file they reference), and their ratio.
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "Args.h"
#include "Commands.h"
#include "ProgressBar.h"
#include "pipeline/core/Error.h"
#include "pipeline/doc/ProjectFile.h"
#include "pipeline/proxy/BakeStats.h"

namespace hlod::cli {

namespace {

const std::vector<NodeKind> kAllKinds{NodeKind::Import, NodeKind::Cluster, NodeKind::Bake,
                                      NodeKind::Export};

bool isProjectFile(const std::string& arg) {
    const std::string ext = kProjectExtension;
    return arg.size() > ext.size() && arg.compare(arg.size() - ext.size(), ext.size(), ext) == 0;
}

// The project's document, or the default graph over the SCENE arguments.
Document loadDocument(const std::vector<std::string>& positionals) {
    for (const std::string& p : positionals) {
        if (!isProjectFile(p)) continue;
        if (positionals.size() != 1) {
            throw Error(ErrorCode::InvalidArgument,
                        "a project file is built on its own (its scenes are in the project)");
        }
        return openProject(p);
    }
    return Document(std::vector<std::filesystem::path>(positionals.begin(), positionals.end()));
}

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

void printJson(const NodeOutput& out) {
    const ExportResult& ex = *out.exported;
    nlohmann::json j = buildTreeJson(*out.scene, *out.tree, *out.bake, ex.info);
    j.erase("nodes");
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
    j["seconds"] = {{"cluster", out.clusterSeconds},
                    {"bake", out.bake->seconds},
                    {"dlod", ex.dlodSeconds},
                    {"write", ex.writeSeconds}};
    std::cout << j.dump(2) << "\n";
}

void printSummary(const NodeOutput& out) {
    const ExportResult& ex = *out.exported;
    const BakeResult& bake = *out.bake;
    const ClusterTree& tree = *out.tree;
    const BakeParams& bp = out.bakeParams;
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

} // namespace

int runBuild(const CommandArgs& argv) {
    const Args args(argv, command("build"));
    const auto flags = paramsFromArgs(args, kAllKinds); // usage errors before any work
    Document doc = loadDocument(args.positionals());
    PipelineGraph& graph = doc.graph();
    for (const auto& [decl, value] : flags) {
        for (NodeId id : graph.nodeIds()) {
            if (graph.node(id).kind == decl->node) graph.setParam(id, decl->key, value);
        }
    }
    const NodeId exportNode = graph.firstOf(NodeKind::Export);
    if (exportNode == kNoNode)
        throw Error(ErrorCode::InvalidArgument, "the project has no export node");
    if (paramText(graph.node(exportNode).params, "output").empty())
        throw Error(ErrorCode::InvalidArgument, "missing -o DIR (output folder)");

    ProgressBar bar;
    graph.run({exportNode}, bar.progress());
    bar.finish();
    const NodeOutput& out = *graph.output(exportNode);
    if (args.has("--json")) {
        printJson(out);
    } else {
        printSummary(out);
    }
    return 0;
}

} // namespace hlod::cli
