// End to end, as a user would: `hlod build` writes a package, every GLB passes the Khronos
// glTF validator, a real 3D Tiles runtime (three.js + 3d-tiles-renderer in Debian's headless
// Chromium) loads and draws it without errors, and `hlod info` reads it back with the counts
// of the source scene.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "../TilesetRules.h"
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

namespace {

struct SharedScene {
    const char* folder;
    std::vector<std::string> extraArgs; // import options the scene needs
};

// Every scene of ../shared/data/scenes (see its README). The kitchen's BREP files are in
// centimetres while OCCT assumes millimetres.
const SharedScene kScenes[] = {
    {"as1-assembly", {}},
    {"cg57-cruiser", {}},
    {"engine-2cylinder", {}},
    {"godot-room", {}},
    {"occt-kitchen", {"--brep-unit", "0.01"}},
    {"torcs-spring", {}},
};

void PrintTo(const SharedScene& s, std::ostream* os) { *os << s.folder; }

class ScenePackage : public ::testing::TestWithParam<SharedScene> {};

std::string sceneName(const ::testing::TestParamInfo<SharedScene>& info) {
    std::string n = info.param.folder;
    for (char& c : n)
        if (c == '-') c = '_';
    return n;
}

} // namespace

// Build the package of a real scene, validate every GLB with the Khronos validator, check the
// tileset rules tile by tile, and read it back with `hlod info`: the leaves are the original
// meshes, so the package must count exactly what the source counts.
TEST_P(ScenePackage, ValidatesAndReadsBackWithTheSourceCounts) {
    const SharedScene& sc = GetParam();
    std::vector<std::string> source{std::string(HLOD_TEST_DATA_DIR) + "/scenes/" + sc.folder};
    source.insert(source.end(), sc.extraArgs.begin(), sc.extraArgs.end());

    std::vector<std::string> info{"info"};
    info.insert(info.end(), source.begin(), source.end());
    info.push_back("--json");
    const auto src = runCli(info, 600);
    ASSERT_EQ(src.exitCode, 0) << src.err;
    const auto srcCounts = nlohmann::json::parse(src.out)["counts"];

    TempDir tmp;
    const fs::path pkg = tmp.path / "pkg";
    std::vector<std::string> build{"build"};
    build.insert(build.end(), source.begin(), source.end());
    build.insert(build.end(), {"-o", pkg.string(), "--threads", "2", "--no-dlod", "--no-cache"});
    const auto b = runCli(build, 900);
    ASSERT_EQ(b.exitCode, 0) << b.err;

    std::ifstream in(pkg / "tileset.json");
    const auto ts = nlohmann::json::parse(in);
    EXPECT_EQ(ts["asset"]["version"], "1.1");
    EXPECT_EQ(ts["root"]["refine"], "REPLACE");
    std::size_t tiles = 0, contents = 0;
    hlod::test::checkTile(ts["root"], pkg, tiles, &contents);
    std::size_t glbs = 0;
    for (const auto& e : fs::recursive_directory_iterator(pkg))
        glbs += e.path().extension() == ".glb" ? 1 : 0;
    EXPECT_EQ(glbs, contents); // every GLB is some tile's content, every content exists

    const auto v = runProcess({"node", webScript("validate-glb.mjs"), pkg.string()}, 900);
    EXPECT_EQ(v.exitCode, 0) << v.out.substr(0, 4000) << v.err;

    const auto i = runCli({"info", pkg.string(), "--json"}, 600);
    ASSERT_EQ(i.exitCode, 0) << i.err;
    const auto counts = nlohmann::json::parse(i.out)["counts"];
    EXPECT_EQ(counts["triangles"], srcCounts["triangles"]);
    EXPECT_EQ(counts["instances"], srcCounts["instances"]);
}

INSTANTIATE_TEST_SUITE_P(SharedScenes, ScenePackage, ::testing::ValuesIn(kScenes), sceneName);
