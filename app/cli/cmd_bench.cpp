// `hlod bench [SCENE...] --out DIR [--frames N] [--size WxH] [--configs LIST]
// [--screen-size PX] [--path FILE.json] [--threads N] [--shading geometry|colour|textured]
// [--proxy-textures on|off] [--draw package|nodes] [--frame-images]`:
// the thesis' evaluation on one scene (see bench/BenchRun.h for what is measured and how).
// The scene is read by the pipeline graph's Import step and every HLOD configuration is a
// branch of that graph; the pipeline flags (--screen-size, --proxy-ratio, --level-growth,
// --threads, --proxy-textures, --no-cache, --cache and the import options) are the parameter
// declarations' (CommandTable.cpp), so their ranges and defaults are those of `hlod build`.
// Writes DIR/summary.json (last), frames.csv, tables.md, camera_path.json, plot_*.png and
// side_by_side_*.png (and frames/*.png with --frame-images). Needs an X display (xvfb-run -a on a
// headless machine).
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "Args.h"
#include "Commands.h"
#include "ProgressBar.h"
#include "pipeline/core/Error.h"
#include "pipeline/core/OnDemand.h"

#ifdef HLOD_HAVE_VTK
#include "bench/BenchRun.h"
#endif

namespace hlod::cli {

#ifdef HLOD_HAVE_VTK
namespace {

std::vector<std::string> parseConfigs(const std::string& list) {
    std::vector<std::string> out;
    std::stringstream ss(list);
    std::string item;
    while (std::getline(ss, item, ',')) {
        if (item.empty()) continue;
        if (item == "all") return kBenchConfigs;
        bool known = false;
        for (const std::string& k : kBenchConfigs)
            known = known || k == item;
        if (!known)
            throw Error(ErrorCode::InvalidArgument,
                        "unknown configuration '" + item +
                            "' in --configs (use original,dlod,sphere,aabb0,aabb1,aabb2,octree)");
        out.push_back(item);
    }
    if (out.empty()) throw Error(ErrorCode::InvalidArgument, "--configs is empty");
    return out;
}

void parseSize(const std::string& text, int& w, int& h) {
    const auto x = text.find('x');
    try {
        if (x == std::string::npos) throw std::invalid_argument("x");
        std::size_t a = 0, b = 0;
        w = std::stoi(text.substr(0, x), &a);
        h = std::stoi(text.substr(x + 1), &b);
        if (a != x || b != text.size() - x - 1) throw std::invalid_argument("x");
    } catch (const std::exception&) {
        throw Error(ErrorCode::InvalidArgument, "--size must be WxH, e.g. 640x360: " + text);
    }
    if (w < 64 || h < 64 || w > 8192 || h > 8192)
        throw Error(ErrorCode::InvalidArgument, "--size must be within 64x64 .. 8192x8192");
}

} // namespace
#endif

#ifndef HLOD_HAVE_VTK
namespace {

// hlod-bench, the build of this CLI with the VTK renderer (app/CMakeLists.txt), where the
// modules are (OnDemand.h programFolders); empty when there is none.
std::filesystem::path benchProgram() {
    for (const std::filesystem::path& folder : programFolders()) {
        const std::filesystem::path p = folder / "hlod-bench";
        if (::access(p.c_str(), X_OK) == 0) return p;
    }
    return {};
}

} // namespace
#endif

int runBench(const CommandArgs& argv) {
    const Args args(argv, command("bench"));
#ifndef HLOD_HAVE_VTK
    // The renderer's libraries (VTK, OpenGL) load only in the program that renders.
    const std::filesystem::path program = benchProgram();
    if (program.empty())
        throw Error(ErrorCode::InvalidArgument,
                    "bench cannot render: hlod-bench (hlod built with VTK, HLOD_BUILD_GUI=ON) is "
                    "neither next to hlod nor in ../lib/hlod-studio");
    std::vector<std::string> all{"hlod", "bench"};
    all.insert(all.end(), argv.begin(), argv.end());
    std::vector<char*> cargs;
    for (std::string& a : all)
        cargs.push_back(a.data());
    cargs.push_back(nullptr);
    std::fflush(stdout);
    std::fflush(stderr);
    ::execv(program.c_str(), cargs.data());
    throw Error(ErrorCode::FileUnreadable, program,
                std::string("cannot run it: ") + std::strerror(errno));
#else
    const CommandSpec& spec = command("bench");
    const auto flags = paramsFromArgs(args, spec.kinds, spec.params); // usage errors first
    BenchOptions o;
    const auto out = args.value("--out") ? args.value("--out") : args.value("-o");
    if (!out || out->empty())
        throw Error(ErrorCode::InvalidArgument, "missing --out DIR (output folder)");
    o.out = *out;
    o.frames = args.integer("--frames", o.frames, 2, 100000);
    parseSize(args.value("--size", "640x360"), o.width, o.height);
    o.configs = parseConfigs(args.value("--configs", "all"));
    if (auto p = args.value("--path")) o.pathFile = *p;
    const std::string shading = args.value("--shading", "geometry");
    if (shading == "geometry")
        o.shading = Shading::Geometry;
    else if (shading == "colour" || shading == "color")
        o.shading = Shading::Colour;
    else if (shading == "textured")
        o.shading = Shading::Textured;
    else
        throw Error(ErrorCode::InvalidArgument,
                    "--shading must be geometry, colour or textured, not '" + shading + "'");
    o.frameImages = args.has("--frame-images");
    const std::string draw = args.value("--draw", "package");
    if (draw != "package" && draw != "nodes")
        throw Error(ErrorCode::InvalidArgument,
                    "--draw must be package or nodes, not '" + draw + "'");
    o.draw = draw == "package" ? HlodDraw::Package : HlodDraw::Nodes;
    o.frameImages = args.has("--frame-images");
    PipelineGraph graph;
    const NodeId import = graph.addNode(NodeKind::Import);
    graph.setSources(import, std::vector<std::filesystem::path>(args.positionals().begin(),
                                                                args.positionals().end()));
    for (const auto& [decl, value] : flags) {
        if (decl->node == NodeKind::Cluster) o.cluster[decl->key] = value;
        if (decl->node == NodeKind::Bake) o.bake[decl->key] = value;
        if (decl->node == NodeKind::Import) graph.setParam(import, decl->key, value);
    }
    if (const char* d = std::getenv("DISPLAY"); !d || !*d)
        throw Error(ErrorCode::InvalidArgument,
                    "bench renders with VTK, which needs an X display here (Debian's VTK has no "
                    "EGL/OSMesa): DISPLAY is unset; run it under xvfb-run -a");
    ProgressBar bar;
    graph.run({import}, bar.progress());
    bar.finish();
    hlod::cli::runBench(graph, import, o);
    return 0;
#endif
}

} // namespace hlod::cli
