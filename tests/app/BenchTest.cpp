// `hlod bench` end to end on the embedded sample scene: every output exists, frames.csv has one
// row per frame and configuration, summary.json lists every configuration, Original against
// itself is the PSNR cap, and HLOD draws fewer meshes than Original. Renders with VTK, so it
// needs the X server the test runner provides (scripts/test.sh runs ctest under xvfb-run).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "RunCli.h"

using hlod::test::runCli;
namespace fs = std::filesystem;

namespace {

struct TempOut {
    fs::path path;
    TempOut() {
        std::random_device rd;
        path = fs::temp_directory_path() / ("hlod-bench-" + std::to_string(rd()));
    }
    ~TempOut() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

bool haveDisplay() {
    const char* d = std::getenv("DISPLAY");
    return d && *d;
}

} // namespace

TEST(Bench, SampleSceneWritesEveryOutput) {
    if (!haveDisplay()) GTEST_SKIP() << "needs an X display (run under xvfb-run)";
    TempOut out;
    const int frames = 12;
    const auto r = runCli({"bench", "--out", out.path.string(), "--frames", std::to_string(frames),
                           "--size", "320x180", "--threads", "2", "--no-cache"},
                          600, 8ull << 30);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* name : {"summary.json", "frames.csv", "tables.md", "camera_path.json",
                             "plot_frame_ms.png", "plot_draw_calls.png", "plot_triangles.png",
                             "plot_psnr.png", "plot_flip.png", "plot_pop.png"}) {
        EXPECT_TRUE(fs::exists(out.path / name)) << name;
        EXPECT_GT(fs::file_size(out.path / name), 100u) << name;
    }
    int sideBySide = 0;
    for (const auto& e : fs::directory_iterator(out.path)) {
        const std::string n = e.path().filename().string();
        if (n.rfind("side_by_side_", 0) == 0 && e.path().extension() == ".png") ++sideBySide;
        EXPECT_NE(e.path().extension(), ".tmp") << n;
    }
    EXPECT_EQ(sideBySide, 3);

    const std::vector<std::string> names{"Original",       "DLOD chain",     "HLOD, sphere",
                                         "HLOD, AABB k=0", "HLOD, AABB k=1", "HLOD, AABB k=2",
                                         "HLOD, octree"};
    std::ifstream csv(out.path / "frames.csv");
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line, "frame,time_s,config,draw_calls,triangles,nodes_visited,frame_ms,psnr_db,"
                    "diff_pixels,flip,lod_switch,pop");
    int rows = 0;
    while (std::getline(csv, line))
        if (!line.empty()) ++rows;
    EXPECT_EQ(rows, frames * static_cast<int>(names.size()));

    std::ifstream in(out.path / "summary.json");
    const auto j = nlohmann::json::parse(in);
    ASSERT_EQ(j["configs"].size(), names.size());
    std::set<std::string> seen;
    double originalDraws = 0.0;
    for (const auto& c : j["configs"]) {
        seen.insert(c["config"].get<std::string>());
        EXPECT_EQ(c["frames"], frames);
        EXPECT_GT(c["frame_ms"]["mean"].get<double>(), 0.0);
        EXPECT_GE(c["frame_ms"]["p95"].get<double>(), 0.0);
        EXPECT_GE(c["selection_us"]["mean"].get<double>(), 0.0);
        if (c["config"] == "Original") {
            EXPECT_EQ(c["psnr_db"]["mean"].get<double>(), 100.0); // the documented cap
            EXPECT_EQ(c["psnr_db"]["min"].get<double>(), 100.0);
            EXPECT_EQ(c["flip"]["max"].get<double>(), 0.0); // against itself
            EXPECT_EQ(c["pop"]["switches"].get<int>(), 0);  // never switches
            originalDraws = c["draw_calls"]["mean"].get<double>();
        }
    }
    for (const std::string& n : names)
        EXPECT_TRUE(seen.count(n)) << n;
    EXPECT_GT(originalDraws, 0.0);
    for (const auto& c : j["configs"]) {
        const std::string n = c["config"];
        if (n.rfind("HLOD", 0) == 0) {
            EXPECT_LT(c["draw_calls"]["mean"].get<double>(), originalDraws) << n;
            EXPECT_GT(c["psnr_db"]["mean"].get<double>(), 20.0) << n;
            // The fly-in switches levels; each switch's pop and each frame's FLIP are in [0, 1].
            EXPECT_GT(c["pop"]["switches"].get<int>(), 0) << n;
            EXPECT_GE(c["pop"]["max"].get<double>(), c["pop"]["mean"].get<double>()) << n;
            EXPECT_LE(c["pop"]["max"].get<double>(), 1.0) << n;
            EXPECT_GT(c["flip"]["mean"].get<double>(), 0.0) << n;
            EXPECT_LT(c["flip"]["max"].get<double>(), 0.5) << n;
        }
    }
    EXPECT_EQ(j["psnr_cap_db"], 100.0);
    // 180 px over the path's 60 degrees: 90 / tan(30°) x pi / 180 = 2.72 px per degree.
    EXPECT_NEAR(j["flip_pixels_per_degree"].get<double>(), 2.7207, 1e-3);
}

TEST(Bench, BadArgumentsAreOneLineUsageErrors) {
    const auto noOut = runCli({"bench"});
    EXPECT_EQ(noOut.exitCode, 2);
    EXPECT_NE(noOut.err.find("--out"), std::string::npos) << noOut.err;
    const auto badConfig = runCli({"bench", "--out", "/tmp/x", "--configs", "original,lod9"});
    EXPECT_EQ(badConfig.exitCode, 2);
    EXPECT_NE(badConfig.err.find("lod9"), std::string::npos) << badConfig.err;
    const auto badSize = runCli({"bench", "--out", "/tmp/x", "--size", "12"});
    EXPECT_EQ(badSize.exitCode, 2);
    const auto badDraw = runCli({"bench", "--out", "/tmp/x", "--draw", "tiles"});
    EXPECT_NE(badDraw.exitCode, 0);
    EXPECT_NE(badDraw.err.find("--draw must be package or nodes, not 'tiles'"), std::string::npos)
        << badDraw.err;
}

namespace {

// Draw calls a runtime issues when it draws every tile of a package: glTF primitives of the
// mesh nodes in every tile GLB (read from the GLB's JSON chunk).
std::size_t packagePrimitives(const fs::path& package) {
    std::size_t primitives = 0;
    for (const auto& e : fs::directory_iterator(package / "tiles")) {
        if (e.path().extension() != ".glb") continue;
        std::ifstream in(e.path(), std::ios::binary);
        std::vector<char> bytes((std::istreambuf_iterator<char>(in)), {});
        if (bytes.size() < 20) continue;
        std::uint32_t length = 0;
        std::memcpy(&length, bytes.data() + 12, 4);
        const auto j = nlohmann::json::parse(bytes.begin() + 20, bytes.begin() + 20 + length);
        for (const auto& node : j.value("nodes", nlohmann::json::array()))
            if (node.contains("mesh"))
                primitives += j["meshes"][node["mesh"].get<std::size_t>()]["primitives"].size();
    }
    return primitives;
}

double hlodDrawsMax(const fs::path& out) {
    std::ifstream in(out / "summary.json");
    const auto j = nlohmann::json::parse(in);
    for (const auto& c : j["configs"])
        if (c["config"] == "HLOD, sphere") return c["draw_calls"]["max"].get<double>();
    ADD_FAILURE() << "no HLOD, sphere in " << out;
    return 0.0;
}

} // namespace

TEST(Bench, PackageDrawCountsWhatThePackageHolds) {
    // --draw package (the default) draws the exported tiles: never more draws in a frame than
    // the package has primitives (a proxy tile is one draw, a leaf group one per look), and
    // the summary says which count it is. --draw nodes draws one per selected node.
    if (!haveDisplay()) GTEST_SKIP() << "needs an X display (run under xvfb-run)";
    TempOut out;
    const auto built =
        runCli({"build", "-o", (out.path / "pkg").string(), "--threads", "2", "--no-cache"}, 600,
               8ull << 30);
    ASSERT_EQ(built.exitCode, 0) << built.err;
    const std::size_t primitives = packagePrimitives(out.path / "pkg");
    ASSERT_GT(primitives, 0u);
    for (const char* draw : {"package", "nodes"}) {
        const fs::path o = out.path / draw;
        const auto r =
            runCli({"bench", "--out", o.string(), "--frames", "6", "--size", "320x180", "--threads",
                    "2", "--no-cache", "--configs", "original,sphere", "--draw", draw},
                   600, 8ull << 30);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        std::ifstream in(o / "summary.json");
        EXPECT_EQ(nlohmann::json::parse(in)["hlod_draw"], draw);
        if (std::string(draw) == "package") {
            EXPECT_GT(hlodDrawsMax(o), 0.0);
            EXPECT_LE(hlodDrawsMax(o), static_cast<double>(primitives));
        }
    }
}

TEST(Bench, BadCameraPathNamesTheFile) {
    if (!haveDisplay()) GTEST_SKIP() << "needs an X display (run under xvfb-run)";
    TempOut out;
    fs::create_directories(out.path);
    const fs::path bad = out.path / "path.json";
    std::ofstream(bad) << "{\"keys\": [1, 2";
    const auto r = runCli({"bench", "--out", (out.path / "o").string(), "--path", bad.string(),
                           "--frames", "2", "--configs", "original"});
    EXPECT_EQ(r.exitCode, 1);
    // Progress lines may come first; the error is the last line and names the file.
    const std::string last = r.err.substr(r.err.rfind('\n', r.err.size() - 2) + 1);
    EXPECT_EQ(last.rfind("hlod bench: error: ", 0), 0u) << r.err;
    EXPECT_NE(last.find("path.json"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out.path / "o" / "summary.json"));
}
