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
    const hlod::NodeId cluster = doc.clusterNode();
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
