// `hlod build PROJECT.hlodproj -o DIR` (app/cli/cmd_build.cpp): the project's graph runs
// headless with its hand edits, and the package's hlod.json shows them. The scene is seven unit
// cubes written as GLB files (instance i = file i): a touching row at x = 0, 1, 2 and two far
// pairs at x = 100, 102 and 200, 202.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "FolderCompare.h"
#include "RunCli.h"
#include "pipeline/doc/Commands.h"
#include "pipeline/doc/ProjectFile.h"
#include "pipeline/io/GlbWriter.h"

namespace fs = std::filesystem;
using hlod::test::runCli;

namespace {

struct TempDir {
    fs::path path = fs::temp_directory_path() /
                    ("hlod-proj-" + std::to_string(::getpid()) + "-" + std::to_string(std::rand()));
    TempDir() { fs::create_directories(path / "scene"); }
    ~TempDir() { fs::remove_all(path); }
};

std::vector<fs::path> writeCubes(const fs::path& dir) {
    const std::vector<glm::dvec3> corners{{0, 0, 0},   {1, 0, 0},   {2, 0, 0},  {100, 0, 0},
                                          {102, 0, 0}, {200, 0, 0}, {202, 0, 0}};
    std::vector<glm::vec3> positions;
    for (int i = 0; i < 8; ++i)
        positions.emplace_back((i & 1) ? 1.0f : 0.0f, (i & 2) ? 1.0f : 0.0f, (i & 4) ? 1.0f : 0.0f);
    const std::vector<std::uint32_t> indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6,
                                                0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7,
                                                0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
    std::vector<fs::path> files;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        hlod::GlbMesh m;
        m.name = "cube";
        m.translation = corners[i];
        m.positions = positions;
        m.indices = indices;
        files.push_back(dir / ("cube_" + std::to_string(i) + ".glb"));
        hlod::writeGlbFile(files.back(), m);
    }
    return files;
}

// Instance ids below node `id` of an hlod.json manifest (ascending).
std::vector<int> leavesBelow(const nlohmann::json& nodes, int id) {
    std::vector<int> out, stack{id};
    while (!stack.empty()) {
        const nlohmann::json& n = nodes[static_cast<std::size_t>(stack.back())];
        stack.pop_back();
        if (n["children"].empty()) out.push_back(n["instance"].get<int>());
        for (const auto& c : n["children"])
            stack.push_back(c.get<int>());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// The id of the node whose leaves are exactly `leaves`, -1 when none.
int nodeWithLeaves(const nlohmann::json& nodes, const std::vector<int>& leaves) {
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        if (leavesBelow(nodes, static_cast<int>(i)) == leaves) return static_cast<int>(i);
    }
    return -1;
}

nlohmann::json readJson(const fs::path& file) {
    std::ifstream in(file);
    return nlohmann::json::parse(in);
}

} // namespace

TEST(ProjectBuild, HandEditsOfTheProjectAreInThePackage) {
    TempDir tmp;
    hlod::Document doc(writeCubes(tmp.path / "scene"));
    const hlod::NodeId cluster = hlod::kDefaultCluster;
    doc.execute(std::make_unique<hlod::SetParameter>(cluster, "volume", std::string("aabb")));
    // Cube 0 (x = 0) and cube 5 (x = 200) would never pair on cost: merged by hand.
    doc.execute(
        std::make_unique<hlod::MergeClusters>(cluster, std::vector<hlod::InstanceSet>{{0}, {5}}));
    doc.execute(std::make_unique<hlod::ExcludeInstance>(cluster, hlod::InstanceSet{3}));
    const fs::path project = tmp.path / "cubes.hlodproj";
    hlod::saveProject(doc, project);

    const fs::path pkg = tmp.path / "pkg";
    const auto r = runCli({"build", project.string(), "-o", pkg.string(), "--no-dlod", "--cache",
                           (tmp.path / "cache").string(), "--threads", "2"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("hand edits:   1 locked groups, 1 excluded, 0 split"), std::string::npos)
        << r.out;
    const nlohmann::json m = readJson(pkg / "hlod.json");
    const nlohmann::json& nodes = m["nodes"];
    EXPECT_EQ(m["volume"], "aabb");
    // The locked pair is one subtree holding exactly cubes 0 and 5.
    EXPECT_GE(nodeWithLeaves(nodes, {0, 5}), 0);
    // The excluded cube hangs directly from the root.
    const int root = m["root"].get<int>();
    EXPECT_EQ(nodes[3]["parent"], root);
    // The package records the edits with the parameters.
    EXPECT_EQ(m["parameters"]["cluster"]["hand_edits"]["locked"], nlohmann::json({{0, 5}}));
    EXPECT_EQ(m["parameters"]["cluster"]["hand_edits"]["excluded"], nlohmann::json({3}));
}

TEST(ProjectBuild, FlagsOverrideTheProjectAndErrorsNameTheProject) {
    TempDir tmp;
    hlod::Document doc(writeCubes(tmp.path / "scene"));
    const fs::path project = tmp.path / "cubes.hlodproj";
    hlod::saveProject(doc, project);
    const fs::path pkg = tmp.path / "pkg";
    const auto r = runCli({"build", project.string(), "-o", pkg.string(), "--no-dlod", "--no-cache",
                           "--volume", "aabb", "--k", "2", "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["parameters"]["cluster"]["volume"], "aabb"); // the project said sphere
    EXPECT_EQ(j["parameters"]["cluster"]["k"], 2.0);

    // Without -o and without an output in the project: a usage error.
    EXPECT_EQ(runCli({"build", project.string()}).exitCode, 2);
    // A missing scene file is named with the project.
    fs::remove(tmp.path / "scene" / "cube_6.glb");
    const auto missing = runCli({"build", project.string(), "-o", pkg.string()});
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_EQ(missing.err, "hlod build: error: " + project.string() + ": scene file " +
                               (tmp.path / "scene" / "cube_6.glb").string() + " does not exist\n");
    // A project of an unknown version.
    std::ofstream(tmp.path / "v9.hlodproj") << R"({"format": "hlod-project", "version": 9})";
    const auto v9 = runCli({"build", (tmp.path / "v9.hlodproj").string(), "-o", pkg.string()});
    EXPECT_EQ(v9.exitCode, 1);
    EXPECT_NE(v9.err.find("unsupported project version 9 (this build reads 1)"), std::string::npos)
        << v9.err;
}

TEST(ProjectBuild, FlagsKeepTheirRangesAndMessages) {
    const auto r = runCli({"build", "-o", "/tmp/x", "--k", "20"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err, "hlod build: error: --k must be within [0, 16], got 20\n");
    const auto g = runCli({"build", "-o", "/tmp/x", "--geo", "north"});
    EXPECT_EQ(g.exitCode, 2);
    EXPECT_NE(g.err.find("--geo expects lat,lon,height"), std::string::npos) << g.err;
}

namespace {

// The two-branch project of issue 29: Import -> Cluster #2 (sphere) -> Bake #3 (S = 300) ->
// Export #4 'a' writing pkg-a, and Duplicate Branch of Cluster #2: Cluster #5 (AABB, k = 0) ->
// Bake #6 (S = 150) -> Export #7 'b' writing pkg-b. Output folders are relative to the project.
hlod::Document twoBranchProject(const fs::path& dir) {
    using namespace hlod;
    Document doc(writeCubes(dir / "scene"));
    doc.execute(std::make_unique<DuplicateNodes>(
        DuplicateNodes::branchFrom(doc.graph(), kDefaultCluster),
        std::vector<std::pair<double, double>>{{220, 120}, {440, 120}, {660, 120}}, true));
    doc.execute(std::make_unique<SetParameter>(kDefaultExport, "output", (dir / "pkg-a").string()));
    doc.execute(std::make_unique<SetParameter>(7, "output", (dir / "pkg-b").string()));
    doc.execute(std::make_unique<RenameNode>(kDefaultExport, "a"));
    doc.execute(std::make_unique<RenameNode>(7, "b"));
    doc.execute(std::make_unique<SetParameter>(5, "volume", std::string("aabb")));
    doc.execute(std::make_unique<SetParameter>(5, "k", 0.0));
    doc.execute(std::make_unique<SetParameter>(6, "screen_size", 150.0));
    return doc;
}

} // namespace

TEST(ProjectBuild, EveryBranchBuildsThePackageASingleBranchBuildWrites) {
    TempDir tmp;
    const hlod::Document doc = twoBranchProject(tmp.path);
    const fs::path project = tmp.path / "two.hlodproj";
    hlod::saveProject(doc, project);
    const std::string cache = (tmp.path / "cache").string();
    const auto r =
        runCli({"build", project.string(), "--no-dlod", "--cache", cache, "--threads", "2"}, 600);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // One table per branch, each named by its chain.
    EXPECT_NE(r.out.find("branch:       Import #1 -> Cluster #2 -> Bake #3 -> Export #4 'a'"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("branch:       Import #1 -> Cluster #5 -> Bake #6 -> Export #7 'b'"),
              std::string::npos)
        << r.out;
    // Each package is where the project says (relative to the project's folder).
    ASSERT_TRUE(fs::exists(tmp.path / "pkg-a" / "tileset.json"));
    ASSERT_TRUE(fs::exists(tmp.path / "pkg-b" / "tileset.json"));

    // The same settings as single-branch builds of the scene: the same tiles, byte for byte.
    std::vector<std::string> scene;
    for (int i = 0; i < 7; ++i)
        scene.push_back((tmp.path / "scene" / ("cube_" + std::to_string(i) + ".glb")).string());
    auto single = [&](const std::string& out, std::vector<std::string> flags) {
        std::vector<std::string> args{"build"};
        args.insert(args.end(), scene.begin(), scene.end());
        for (const std::string& f :
             {std::string("-o"), out, std::string("--no-dlod"), std::string("--cache"), cache,
              std::string("--threads"), std::string("2")})
            args.push_back(f);
        args.insert(args.end(), flags.begin(), flags.end());
        return runCli(args, 600);
    };
    const std::string a = (tmp.path / "single-a").string();
    const std::string b = (tmp.path / "single-b").string();
    ASSERT_EQ(single(a, {}).exitCode, 0);
    ASSERT_EQ(single(b, {"--volume", "aabb", "--k", "0", "--screen-size", "150"}).exitCode, 0);
    EXPECT_EQ(hlod::test::folderDifference(tmp.path / "pkg-a" / "tiles", fs::path(a) / "tiles"),
              "");
    EXPECT_EQ(hlod::test::folderDifference(tmp.path / "pkg-b" / "tiles", fs::path(b) / "tiles"),
              "");
    EXPECT_EQ(hlod::test::fileBytes(tmp.path / "pkg-b" / "tileset.json"),
              hlod::test::fileBytes(fs::path(b) / "tileset.json"));
    // The branches differ: another volume and screen size make other tiles.
    EXPECT_NE(
        hlod::test::folderDifference(tmp.path / "pkg-a" / "tiles", tmp.path / "pkg-b" / "tiles"),
        "");
}

TEST(ProjectBuild, ExportPicksABranchAndAGraphThatCannotRunIsRefusedNamingTheNode) {
    TempDir tmp;
    hlod::Document doc = twoBranchProject(tmp.path);
    const fs::path project = tmp.path / "two.hlodproj";
    hlod::saveProject(doc, project);
    // -o names one folder: with two Export nodes it needs --export.
    const auto both = runCli({"build", project.string(), "-o", (tmp.path / "x").string()});
    EXPECT_EQ(both.exitCode, 2);
    EXPECT_EQ(both.err, "hlod build: error: -o names one output folder, but the project has 2 "
                        "Export nodes (Export #4 'a', Export #7 'b'): pick one with --export "
                        "ID|NAME, or leave out -o to write each to its own folder\n");
    // --export by name (or id) runs that branch alone, into -o.
    const fs::path only = tmp.path / "only-b";
    const auto b = runCli({"build", project.string(), "--export", "b", "-o", only.string(),
                           "--no-dlod", "--no-cache", "--threads", "2", "--json"},
                          600);
    ASSERT_EQ(b.exitCode, 0) << b.err;
    const auto j = nlohmann::json::parse(b.out);
    EXPECT_EQ(j["branch"]["export"], 7);
    EXPECT_EQ(j["branch"]["nodes"], nlohmann::json({1, 5, 6, 7}));
    EXPECT_EQ(j["parameters"]["cluster"]["volume"], "aabb");
    EXPECT_TRUE(fs::exists(only / "tileset.json"));
    EXPECT_FALSE(fs::exists(tmp.path / "pkg-a")); // the other branch did not run
    const auto unknown = runCli({"build", project.string(), "--export", "c"});
    EXPECT_EQ(unknown.exitCode, 2);
    EXPECT_EQ(unknown.err, "hlod build: error: --export c names no node of the project (its "
                           "Export nodes: Export #4 'a', Export #7 'b')\n");

    // Both Exports writing one folder: refused before anything runs, naming the node.
    doc.execute(std::make_unique<hlod::SetParameter>(7, "output", (tmp.path / "pkg-a").string()));
    hlod::saveProject(doc, project);
    const auto same = runCli({"build", project.string(), "--no-dlod", "--no-cache"});
    EXPECT_EQ(same.exitCode, 2);
    EXPECT_EQ(same.err,
              "hlod build: error: Export #7 'b' writes the same folder as Export #4 'a' (" +
                  (tmp.path / "pkg-a").string() + "): give one of them another output folder\n");
    EXPECT_FALSE(fs::exists(tmp.path / "pkg-a"));
    // A Bake node without a Cluster node upstream.
    doc.execute(std::make_unique<hlod::SetParameter>(7, "output", (tmp.path / "pkg-b").string()));
    doc.execute(std::make_unique<hlod::DisconnectNodes>(hlod::Connection{5, 0, 6, 0}));
    hlod::saveProject(doc, project);
    const auto loose = runCli({"build", project.string(), "--no-dlod", "--no-cache"});
    EXPECT_EQ(loose.exitCode, 2);
    EXPECT_EQ(loose.err, "hlod build: error: Bake #6 has no Cluster node upstream: connect a "
                         "Cluster node's clusters output to its input\n");
}

TEST(ProjectBuild, BenchTakesTheBuildFlagsWithTheirDeclaredRanges) {
    // One declaration per parameter: hlod bench refuses what hlod build refuses, in its words.
    const auto build = runCli({"build", "-o", "/tmp/x", "--proxy-ratio", "5"});
    const auto bench = runCli({"bench", "--out", "/tmp/x", "--proxy-ratio", "5"});
    EXPECT_EQ(build.exitCode, 2);
    EXPECT_EQ(bench.exitCode, 2);
    EXPECT_EQ(build.err, "hlod build: error: --proxy-ratio must be within [0.05, 1], got 5\n");
    EXPECT_EQ(bench.err, "hlod bench: error: --proxy-ratio must be within [0.05, 1], got 5\n");
    const auto fov = runCli({"bench", "--out", "/tmp/x", "--screen-size", "0"});
    EXPECT_EQ(fov.err, "hlod bench: error: --screen-size must be within [1, 100000], got 0\n");
}
