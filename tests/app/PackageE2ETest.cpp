// End to end, as a user would: `hlod build` writes a package, every GLB passes the Khronos
// glTF validator, a real 3D Tiles runtime (three.js + 3d-tiles-renderer in Debian's headless
// Chromium) loads and draws it without errors, and `hlod info` reads it back with the counts
// of the source scene.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "RunCli.h"

namespace fs = std::filesystem;
using hlod::test::runCli;
using hlod::test::runProcess;

namespace {

struct TempDir {
    fs::path path = fs::temp_directory_path() /
                    ("hlod-e2e-" + std::to_string(::getpid()) + "-" + std::to_string(std::rand()));
    TempDir() { fs::create_directories(path); }
    ~TempDir() { fs::remove_all(path); }
};

std::string webScript(const char* name) {
    return std::string(HLOD_TEST_SOURCE_DIR) + "/web/" + name;
}

void buildValidateRender(const std::vector<std::string>& scene, int expectedTriangles) {
    TempDir tmp;
    const std::string pkg = (tmp.path / "pkg").string();
    std::vector<std::string> args{"build"};
    args.insert(args.end(), scene.begin(), scene.end());
    args.insert(args.end(), {"-o", pkg, "--threads", "2"});
    const auto b = runCli(args, 600);
    ASSERT_EQ(b.exitCode, 0) << b.err;
    ASSERT_TRUE(fs::exists(fs::path(pkg) / "tileset.json"));

    const auto v = runProcess({"node", webScript("validate-glb.mjs"), pkg}, 300);
    EXPECT_EQ(v.exitCode, 0) << v.out << v.err;

    const auto r = runProcess(
        {"node", webScript("render-tileset.mjs"), pkg, (tmp.path / "render.png").string()}, 300);
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    if (r.exitCode == 0) {
        const auto report = nlohmann::json::parse(r.out);
        EXPECT_GT(report["tilesLoaded"].get<int>(), 0);
        EXPECT_EQ(report["tilesFailed"], 0);
        EXPECT_TRUE(report["consoleErrors"].empty());
        EXPECT_GT(report["nonBackgroundPixelShare"].get<double>(), 0.01);
    }

    const auto i = runCli({"info", pkg, "--json"});
    ASSERT_EQ(i.exitCode, 0) << i.err;
    const auto info = nlohmann::json::parse(i.out);
    EXPECT_EQ(info["counts"]["triangles"], expectedTriangles); // the leaves are the originals
    EXPECT_GT(info["package"]["proxy_triangles"].get<int>(), 0);
}

} // namespace

TEST(PackageE2E, SampleScenePackageValidatesAndRendersInABrowser) {
    buildValidateRender({}, 10020); // hlod info of the sample: 10,020 triangles
}

TEST(PackageE2E, RoomPackageValidatesAndRendersInABrowser) {
    buildValidateRender({std::string(HLOD_TEST_DATA_DIR) + "/scenes/godot-room/room.glb"}, 63720);
}
