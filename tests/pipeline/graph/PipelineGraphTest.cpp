// The pipeline graph model (pipeline/graph/PipelineGraph.h): typed connections without cycles,
// statuses, runs without any view that redo only what is downstream of a change, JSON.
#include <gtest/gtest.h>

#include <map>

#include <nlohmann/json.hpp>

#include "TestUtil.h"
#include "doc/CubeFiles.h"
#include "pipeline/core/Error.h"
#include "pipeline/graph/PipelineGraph.h"

namespace hlod {
namespace {

using test::problemOf;

TEST(PipelineGraph, DefaultGraphIsAChainWithEveryNodePending) {
    const PipelineGraph g = PipelineGraph::makeDefault();
    EXPECT_EQ(g.nodeIds(), (std::vector<NodeId>{1, 2, 3, 4}));
    EXPECT_EQ(g.connections().size(), 3u);
    EXPECT_EQ(g.upstreamOf(2), 1u);
    EXPECT_EQ(g.downstreamOf(2), (std::vector<NodeId>{3, 4}));
    for (NodeId id : g.nodeIds())
        EXPECT_EQ(g.status(id), NodeStatus::Pending);
}

TEST(PipelineGraph, ConnectRefusesWrongTypesTakenInputsAndCycles) {
    PipelineGraph g = PipelineGraph::makeDefault();
    EXPECT_EQ(problemOf([&] {
                  g.connect({1, 0, 3, 0});
              }),
              "cannot connect scene output of Import #1 to clusters input of Bake #3");
    EXPECT_EQ(problemOf([&] {
                  g.connect({1, 0, 2, 0});
              }),
              "input 'scene' of Cluster #2 is already connected");
    // A second Cluster node fed by the same Import is fine (side-by-side comparison).
    const NodeId c2 = g.addNode(NodeKind::Cluster);
    EXPECT_NO_THROW(g.connect({1, 0, c2, 0}));
    EXPECT_EQ(g.connections().size(), 4u);
    // No port type lets a chain loop back, and a node never feeds itself.
    EXPECT_EQ(problemOf([&] {
                  g.connect({c2, 0, c2, 0});
              }),
              "cannot connect clusters output of Cluster #5 to scene input of Cluster #5");
    g.removeNode(c2);
    EXPECT_EQ(g.connections().size(), 3u);
    EXPECT_EQ(g.nextId(), 6u); // ids are never reused
}

TEST(PipelineGraph, ParametersAreValidatedPerNodeKind) {
    PipelineGraph g = PipelineGraph::makeDefault();
    EXPECT_EQ(problemOf([&] { g.setParam(2, "screen_size", 100.0); }),
              "Cluster #2 has no parameter 'screen_size'");
    EXPECT_EQ(problemOf([&] { g.setParam(2, "k", -1.0); }), "k must be within [0, 16], got -1");
    g.setParam(2, "k", 2); // an int is accepted for a double parameter
    EXPECT_EQ(std::get<double>(g.node(2).params.at("k")), 2.0);
}

TEST(PipelineGraph, RunsHeadlessAndRerunsOnlyWhatIsDownstreamOfAChange) {
    test::TempDir tmp;
    std::filesystem::create_directories(tmp / "scene");
    PipelineGraph g = PipelineGraph::makeDefault(test::writeSevenCubes(tmp / "scene"));
    g.setParam(2, "volume", std::string("aabb"));
    g.setParam(2, "k", 0.0);
    g.setParam(2, "level_growth", 1.0); // the thesis' merges: five inner nodes
    g.setParam(3, "cache_dir", (tmp / "cache").string());
    g.setParam(3, "proxy_ratio", 1.0); // every proxy kept (the economy is tested elsewhere)
    std::vector<std::pair<NodeId, NodeStatus>> events;
    g.setStatusListener([&](NodeId id, NodeStatus s) { events.push_back({id, s}); });
    g.run({3});
    EXPECT_EQ(g.status(1), NodeStatus::UpToDate);
    EXPECT_EQ(g.status(3), NodeStatus::UpToDate);
    EXPECT_EQ(g.status(4), NodeStatus::Pending); // not asked for
    // Each of the three nodes went running -> up to date, in dependency order.
    ASSERT_EQ(events.size(), 6u);
    EXPECT_EQ(events[0], (std::pair<NodeId, NodeStatus>{1, NodeStatus::Running}));
    EXPECT_EQ(events[5], (std::pair<NodeId, NodeStatus>{3, NodeStatus::UpToDate}));
    // The five inner nodes of the seven cubes; DE and FG are translated copies, baked once.
    EXPECT_EQ(g.output(3)->bake->baked, 4u);

    const ClusterTree* tree = g.output(2)->tree.get();
    g.setParam(3, "screen_size", 150.0);
    EXPECT_EQ(g.status(2), NodeStatus::UpToDate);
    EXPECT_EQ(g.status(3), NodeStatus::Pending);
    g.run({3});
    EXPECT_EQ(g.output(2)->tree.get(), tree); // clustering was not rerun
    // A new screen size changes every error budget: all proxies are baked again.
    EXPECT_EQ(g.output(3)->bake->baked, 4u);
    g.setParam(3, "screen_size", 300.0);
    g.run({3});
    EXPECT_EQ(g.output(3)->bake->reused, 5u); // back to the first keys: all from the cache
}

TEST(PipelineGraph, FailureMarksTheNodeAndKeepsTheMessage) {
    PipelineGraph g = PipelineGraph::makeDefault({"/no/such/scene.glb"});
    EXPECT_THROW(g.run({2}), Error);
    EXPECT_EQ(g.status(1), NodeStatus::Failed);
    EXPECT_EQ(g.error(1), "/no/such/scene.glb: no such file");
    EXPECT_EQ(g.status(2), NodeStatus::Pending);
    // The Export node without an output folder is refused before anything runs.
    test::TempDir tmp;
    PipelineGraph s = PipelineGraph::makeDefault(test::writeCubeFiles(tmp.path(), {{0, 0, 0}}));
    s.setParam(3, "cache", false);
    s.setParam(4, "dlod", false);
    EXPECT_THROW(s.runAll(), Error);
    EXPECT_EQ(s.status(4), NodeStatus::Failed);
    EXPECT_EQ(s.status(1), NodeStatus::Pending); // nothing ran
    EXPECT_EQ(s.error(4), "Export #4 has no output folder (set its Output folder, or -o DIR on "
                          "the command line)");
}

TEST(PipelineGraph, AGraphThatCannotRunIsRefusedNamingTheNode) {
    PipelineGraph g = PipelineGraph::makeDefault({"a.glb"});
    g.setParam(4, "output", std::string("/out/a"));
    // A second branch whose Bake has no Cluster upstream.
    const NodeId bake = g.addNode(NodeKind::Bake);
    const NodeId exp = g.addNode(NodeKind::Export);
    g.connect({bake, 0, exp, 0});
    g.setParam(exp, "output", std::string("/out/b"));
    g.setName(bake, "coarse");
    EXPECT_EQ(problemOf([&] {
                  g.run({4, exp});
              }),
              "Bake #5 'coarse' has no Cluster node upstream: connect a Cluster node's clusters "
              "output to its input");
    EXPECT_EQ(g.status(bake), NodeStatus::Failed);
    EXPECT_EQ(g.status(1), NodeStatus::Pending); // refused before the import ran
    // Connected, but both Exports write one folder ("/out/a/" is "/out/a").
    const NodeId cluster = g.addNode(NodeKind::Cluster);
    g.connect({1, 0, cluster, 0});
    g.connect({cluster, 0, bake, 0});
    g.setParam(exp, "output", std::string("/out/a/"));
    EXPECT_EQ(problemOf([&] {
                  g.checkRunnable({4, exp});
              }),
              "Export #6 writes the same folder as Export #4 (/out/a): give one of them another "
              "output folder");
    EXPECT_EQ(g.status(exp), NodeStatus::Failed);
    g.setParam(exp, "output", std::string("/out/b"));
    EXPECT_NO_THROW(g.checkRunnable({4, exp}));
    EXPECT_EQ(g.status(exp), NodeStatus::Pending); // the edit took the failure away
}

TEST(PipelineGraph, BranchesShareTheImportAndEachBuildsItsOwnVariant) {
    test::TempDir tmp;
    std::filesystem::create_directories(tmp / "scene");
    PipelineGraph g = PipelineGraph::makeDefault(test::writeSevenCubes(tmp / "scene"));
    const NodeId cluster = g.addNode(NodeKind::Cluster);
    const NodeId bake = g.addNode(NodeKind::Bake);
    g.connect({1, 0, cluster, 0});
    g.connect({cluster, 0, bake, 0});
    for (NodeId b : {NodeId(3), bake}) {
        g.setParam(b, "cache_dir", (tmp / "cache").string());
        g.setParam(b, "proxy_ratio", 1.0);
    }
    g.setParam(2, "level_growth", 1.0);
    g.setParam(cluster, "level_growth", 1.0);
    g.setParam(cluster, "volume", std::string("aabb"));
    g.setParam(cluster, "k", 0.0);
    EXPECT_EQ(g.branchOf(bake), (std::vector<NodeId>{1, cluster, bake}));
    EXPECT_EQ(g.upstreamOfKind(bake, NodeKind::Cluster), cluster);
    std::vector<NodeId> imports;
    std::map<NodeId, std::uint64_t> lastDone;
    g.setStatusListener([&](NodeId id, NodeStatus s) {
        if (id == 1 && s == NodeStatus::Running) imports.push_back(id);
    });
    g.setProgressListener([&](NodeId id, const ProgressInfo& p) { lastDone[id] = p.done; });
    g.run({3, bake});
    EXPECT_EQ(imports.size(), 1u); // one import feeds both branches
    EXPECT_EQ(g.status(3), NodeStatus::UpToDate);
    EXPECT_EQ(g.status(bake), NodeStatus::UpToDate);
    // Each Bake reported its own progress: all its inner nodes (AABB k = 0: five).
    EXPECT_EQ(lastDone.at(bake), g.output(bake)->bake->innerNodes);
    EXPECT_EQ(g.output(bake)->bake->innerNodes, 5u);
    EXPECT_EQ(g.output(bake)->cluster.volume, VolumeType::Aabb);
    EXPECT_EQ(g.output(3)->cluster.volume, VolumeType::Sphere);
}

TEST(PipelineGraph, ARunOnACopyComesBackOnlyWhereTheDefinitionIsUnchanged) {
    test::TempDir tmp;
    PipelineGraph g = PipelineGraph::makeDefault(test::writeCubeFiles(tmp.path(), {{0, 0, 0}}));
    g.setParam(3, "cache", false);
    PipelineGraph copy = g; // what the editor's worker runs
    const std::string importDef = copy.definition(1);
    const std::string clusterDef = copy.definition(2);
    const std::string bakeDef = copy.definition(3);
    copy.run({3});
    // While the copy ran, the user changed the Bake node (not the Cluster node).
    g.setParam(3, "screen_size", 150.0);
    g.setName(2, "renamed"); // names and positions are not part of a definition
    EXPECT_EQ(g.definition(2), clusterDef);
    EXPECT_TRUE(g.adopt(1, importDef, NodeStatus::UpToDate, copy.sharedOutput(1)));
    EXPECT_TRUE(g.adopt(2, clusterDef, NodeStatus::UpToDate, copy.sharedOutput(2)));
    EXPECT_FALSE(g.adopt(3, bakeDef, NodeStatus::UpToDate, copy.sharedOutput(3)));
    EXPECT_EQ(g.status(2), NodeStatus::UpToDate);
    EXPECT_EQ(g.output(2)->tree, copy.output(2)->tree); // shared, not copied
    EXPECT_EQ(g.status(3), NodeStatus::Pending);
    EXPECT_EQ(g.output(3), nullptr);
    // Running the graph now reruns only the Bake node.
    std::vector<NodeId> ran;
    g.setStatusListener([&](NodeId id, NodeStatus s) {
        if (s == NodeStatus::Running) ran.push_back(id);
    });
    g.run({3});
    EXPECT_EQ(ran, (std::vector<NodeId>{3}));
    // A node gone meanwhile takes nothing.
    g.removeNode(4);
    EXPECT_FALSE(g.adopt(4, copy.definition(4), NodeStatus::UpToDate, nullptr));
}

TEST(PipelineGraph, JsonRoundTripsAndIsValidated) {
    PipelineGraph g = PipelineGraph::makeDefault({"a.glb"});
    g.setParam(2, "max_children", 4);
    HandEdits e;
    e.locked = {{0, 1}};
    g.setHandEdits(2, e);
    g.setPosition(3, 10.0, 20.0);
    g.setName(4, "web");
    const nlohmann::json j = g.toJson();
    const PipelineGraph back = PipelineGraph::fromJson(j);
    EXPECT_EQ(back.toJson(), j);
    EXPECT_EQ(back.node(2).edits, e);
    EXPECT_EQ(back.node(3).x, 10.0);
    EXPECT_EQ(back.node(4).name, "web");

    nlohmann::json bad = j;
    bad["connections"][0]["to_port"] = "mesh";
    try {
        PipelineGraph::fromJson(bad, "x.hlodproj");
        FAIL();
    } catch (const Error& err) {
        EXPECT_EQ(err.code(), ErrorCode::Malformed);
        EXPECT_EQ(std::string(err.what()),
                  "x.hlodproj: graph.connections[0] names a port the node does not have");
    }
}

} // namespace
} // namespace hlod
