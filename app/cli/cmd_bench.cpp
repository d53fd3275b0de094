// `hlod bench [SCENE...] --out DIR [--frames N] [--size WxH] [--configs LIST]
// [--screen-size PX] [--path FILE.json] [--threads N] [--shading geometry|colour|textured]
// [--proxy-textures on|off] [--draw package|nodes] [--frame-images]`:
// the thesis' evaluation on one scene (see bench/BenchRun.h for what is measured and how).
// Writes DIR/summary.json (last), frames.csv, tables.md, camera_path.json, plot_*.png and
// side_by_side_*.png (and frames/*.png with --frame-images). Needs an X display (xvfb-run -a on a
// headless machine).
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "Args.h"
#include "Commands.h"
#include "SceneInput.h"
#include "pipeline/core/Error.h"

#ifdef HLOD_HAVE_VTK
#include "bench/BenchRun.h"
#endif

namespace hlod::cli {

#ifdef HLOD_HAVE_VTK
namespace {

// Same user-level proxy cache as `hlod build`.
std::filesystem::path benchCacheDir() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        return std::filesystem::path(xdg) / "hlod" / "proxies";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "hlod" / "proxies";
    return {};
}

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

int runBench(const CommandArgs& argv) {
    const Args args(argv, command("bench"));
#ifndef HLOD_HAVE_VTK
    throw Error(ErrorCode::InvalidArgument,
                "this hlod was built without VTK (HLOD_BUILD_GUI=OFF): bench cannot render");
#else
    BenchOptions o;
    const auto out = args.value("--out") ? args.value("--out") : args.value("-o");
    if (!out || out->empty())
        throw Error(ErrorCode::InvalidArgument, "missing --out DIR (output folder)");
    o.out = *out;
    o.frames = args.integer("--frames", o.frames, 2, 100000);
    parseSize(args.value("--size", "640x360"), o.width, o.height);
    o.configs = parseConfigs(args.value("--configs", "all"));
    o.screenSize = args.number("--screen-size", o.screenSize, 1.0, 100000.0);
    o.proxyRatio = args.number("--proxy-ratio", o.proxyRatio, 0.05, 1.0);
    o.levelGrowth = args.number("--level-growth", o.levelGrowth, 1.0, 16.0);
    if (auto p = args.value("--path")) o.pathFile = *p;
    o.threads = args.integer("--threads", 0, 0, 1024);
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
    if (!args.has("--no-cache")) o.cacheDir = benchCacheDir();
    if (auto cache = args.value("--cache"); cache && !args.has("--no-cache")) o.cacheDir = *cache;
    const std::string textures = args.value("--proxy-textures", "on");
    if (textures != "on" && textures != "off")
        throw Error(ErrorCode::InvalidArgument,
                    "--proxy-textures must be on or off, not '" + textures + "'");
    o.proxyTextures = textures == "on";
    const std::string draw = args.value("--draw", "package");
    if (draw != "package" && draw != "nodes")
        throw Error(ErrorCode::InvalidArgument,
                    "--draw must be package or nodes, not '" + draw + "'");
    o.draw = draw == "package" ? HlodDraw::Package : HlodDraw::Nodes;
    o.frameImages = args.has("--frame-images");
    if (const char* d = std::getenv("DISPLAY"); !d || !*d)
        throw Error(ErrorCode::InvalidArgument,
                    "bench renders with VTK, which needs an X display here (Debian's VTK has no "
                    "EGL/OSMesa): DISPLAY is unset; run it under xvfb-run -a");
    const LoadedScene loaded = loadSceneArgs(args.positionals(), importOptionsFromArgs(args));
    o.inputs = loaded.inputs;
    hlod::cli::runBench(loaded.scene, o);
    return 0;
#endif
}

} // namespace hlod::cli
