// `hlod build SCENE... -o DIR [--volume V] [--k K] [--max-children N]
// [--proxy decimate|remesh|sloppy] [--screen-size PX] [--pixel-error PX] [--fov DEG]
// [--viewport-height PX] [--threads N] [--cache DIR] [--no-cache] [--no-dlod] [--json]`:
// import, cluster, bake every inner node's proxy and write the build folder (BuildOutput.h),
// then print the thesis-style statistics table (BakeStats.h).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipeline/export/Package.h"

#include "Args.h"
#include "Commands.h"
#include "ProgressBar.h"
#include "SceneInput.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/core/Error.h"
#include "pipeline/proxy/BakeStats.h"
#include "pipeline/proxy/BuildOutput.h"
#include "pipeline/proxy/DlodChain.h"
#include "pipeline/proxy/ProxyBaker.h"

namespace hlod::cli {

namespace {

// A user-level cache shared by all builds, like ccache: $XDG_CACHE_HOME/hlod/proxies, else
// ~/.cache/hlod/proxies; none when neither is known.
std::filesystem::path defaultCacheDir() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) {
        return std::filesystem::path(xdg) / "hlod" / "proxies";
    }
    if (const char* home = std::getenv("HOME"); home && *home) {
        return std::filesystem::path(home) / ".cache" / "hlod" / "proxies";
    }
    return {};
}

struct BuildOptions {
    ClusterParams cluster;
    BakeParams bake;
    std::filesystem::path output;
    bool dlod = true;
    bool json = false;
    ImportOptions import;
    std::optional<GeoLocation> geo; // --geo lat,lon,height: root transform on the globe
};

BuildOptions parseOptions(const Args& args) {
    BuildOptions o;
    const auto out = args.value("-o") ? args.value("-o") : args.value("--output");
    if (!out || out->empty())
        throw Error(ErrorCode::InvalidArgument, "missing -o DIR (output folder)");
    o.output = *out;
    o.cluster.volume = volumeTypeFromString(args.value("--volume", "sphere"));
    o.cluster.k = args.number("--k", o.cluster.k, 0.0, 16.0);
    o.cluster.maxChildren = args.integer("--max-children", o.cluster.maxChildren, 2, 1024);
    o.bake.method = proxyMethodFromString(args.value("--proxy", "decimate"));
    ScreenParams& s = o.bake.screen;
    s.screenSize = args.number("--screen-size", s.screenSize, 1.0, 100000.0);
    s.pixelError = args.number("--pixel-error", s.pixelError, 0.01, 1000.0);
    s.fovYDegrees = args.number("--fov", s.fovYDegrees, 1.0, 179.0);
    s.viewportHeight = args.number("--viewport-height", s.viewportHeight, 1.0, 100000.0);
    o.bake.threads = args.integer("--threads", 0, 0, 1024);
    if (!args.has("--no-cache"))
        o.bake.cacheDir = args.value("--cache", defaultCacheDir().string());
    o.dlod = !args.has("--no-dlod");
    o.json = args.has("--json");
    o.import = importOptionsFromArgs(args);
    if (auto geo = args.value("--geo")) o.geo = parseGeoLocation(*geo);
    return o;
}

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

void printTable(const std::vector<GeometryStats>& rows) {
    std::printf("%-20s %12s %12s %8s %12s\n", "version", "triangles", "vertices", "meshes",
                "space (MB)");
    for (const GeometryStats& r : rows) {
        std::printf("%-20s %12zu %12zu %8zu %12.2f\n", r.version.c_str(), r.triangles, r.vertices,
                    r.meshes, static_cast<double>(r.bytes) / 1.0e6);
    }
}

} // namespace

int runBuild(const CommandArgs& argv) {
    const Args args(argv,
                    {"-o", "--output", "--volume", "--k", "--max-children", "--proxy",
                     "--screen-size", "--pixel-error", "--fov", "--viewport-height", "--threads",
                     "--cache", "--deflection", "--brep-unit", "--geo"},
                    {"--json", "--no-cache", "--no-dlod"});
    const BuildOptions o = parseOptions(args);
    validate(o.bake.screen);
    const LoadedScene loaded = loadSceneArgs(args.positionals(), o.import);
    const Scene& scene = loaded.scene;

    ProgressBar bar;
    auto t = std::chrono::steady_clock::now();
    const ClusterTree tree = buildClusterTree(scene, o.cluster, bar.progress());
    const double clusterSeconds = seconds(t);
    const BakeResult bake = bakeProxies(scene, tree, o.bake, bar.progress());
    bar.finish();

    BuildInfo info;
    info.inputs = loaded.inputs;
    info.bake = o.bake;
    info.clusterParameters = {{"volume", toString(o.cluster.volume)},
                              {"k", o.cluster.k},
                              {"max_children", o.cluster.maxChildren}};
    info.statistics.push_back(originalStats(scene));
    double dlodSeconds = 0.0;
    if (o.dlod) {
        const DlodSummary dlod = summarizeDlodChains(scene, DlodParams{}, o.bake.threads);
        dlodSeconds = dlod.seconds;
        info.statistics.push_back(dlodStats(dlod));
    }
    info.statistics.push_back(hlodStats(scene, tree, bake, hlodVersionName(tree)));
    info.share = proxyShare(scene, tree, bake);
    t = std::chrono::steady_clock::now();
    PackageOptions package;
    package.inputs = loaded.inputs;
    package.geo = o.geo;
    nlohmann::json summary = buildTreeJson(scene, tree, bake, info);
    summary.erase("nodes"); // the package manifest has its own node list
    package.parameters = summary.value("parameters", nlohmann::json::object());
    package.statistics = summary;
    const PackageSummary written =
        writePackage(o.output, scene, tree, bake, o.bake, package, bar.progress());
    bar.finish();
    const std::uintmax_t bytes = written.bytes;
    const double writeSeconds = seconds(t);

    if (o.json) {
        nlohmann::json j = buildTreeJson(scene, tree, bake, info);
        j.erase("nodes");
        j["output"] = o.output.string();
        j["output_bytes"] = bytes;
        j["seconds"] = {{"cluster", clusterSeconds},
                        {"bake", bake.seconds},
                        {"dlod", dlodSeconds},
                        {"write", writeSeconds}};
        std::cout << j.dump(2) << "\n";
        return 0;
    }
    std::printf("scene:        ");
    for (const auto& in : loaded.inputs)
        std::printf("%s ", in.c_str());
    std::printf("\nclusters:     %s, %zu nodes (%zu inner), height %d, %.2f s\n",
                hlodVersionName(tree).c_str(), tree.nodes.size(), bake.innerNodes, tree.height(),
                clusterSeconds);
    std::printf("proxies:      %s at %g px / %g px: baked %zu, reused %zu in %.2f s "
                "(%zu input triangles)\n",
                toString(o.bake.method), o.bake.screen.screenSize, o.bake.screen.pixelError,
                bake.baked, bake.reused, bake.seconds, bake.inputTriangles);
    std::printf("proxy share:  all proxies %.1f%% of the original triangles, root proxy %.2f%%\n",
                info.share.allProxies * 100.0, info.share.rootProxy * 100.0);
    printTable(info.statistics);
    std::printf("output:       %s (%.2f MB)\n", o.output.string().c_str(),
                static_cast<double>(bytes) / 1.0e6);
    return 0;
}

} // namespace hlod::cli
