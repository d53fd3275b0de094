// The pipeline graph model (pipeline/graph/PipelineGraph.h): typed connections without cycles,
// statuses, runs without any view that redo only what is downstream of a change, JSON.
#include <gtest/gtest.h>

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
              "cannot connect scene output of import node 1 to clusters input of bake node 3");
    EXPECT_EQ(problemOf([&] {
                  g.connect({1, 0, 2, 0});
              }),
              "input 'scene' of cluster node 2 is already connected");
    // A second Cluster node fed by the same Import is fine (side-by-side comparison).
    const NodeId c2 = g.addNode(NodeKind::Cluster);
    EXPECT_NO_THROW(g.connect({1, 0, c2, 0}));
    EXPECT_EQ(g.connections().size(), 4u);
    // No port type lets a chain loop back, and a node never feeds itself.
    EXPECT_EQ(problemOf([&] {
                  g.connect({c2, 0, c2, 0});
              }),
              "cannot connect clusters output of cluster node 5 to scene input of cluster node 5");
    g.removeNode(c2);
    EXPECT_EQ(g.connections().size(), 3u);
    EXPECT_EQ(g.nextId(), 6u); // ids are never reused
}

TEST(PipelineGraph, ParametersAreValidatedPerNodeKind) {
    PipelineGraph g = PipelineGraph::makeDefault();
    EXPECT_EQ(problemOf([&] { g.setParam(2, "screen_size", 100.0); }),
              "cluster node 2 has no parameter 'screen_size'");
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
    // The Export node without an output folder says so.
    test::TempDir tmp;
    PipelineGraph s = PipelineGraph::makeDefault(test::writeCubeFiles(tmp.path(), {{0, 0, 0}}));
    s.setParam(3, "cache", false);
    s.setParam(4, "dlod", false);
    EXPECT_THROW(s.runAll(), Error);
    EXPECT_EQ(s.status(4), NodeStatus::Failed);
    EXPECT_EQ(s.error(4), "missing -o DIR (output folder)");
}

TEST(PipelineGraph, JsonRoundTripsAndIsValidated) {
    PipelineGraph g = PipelineGraph::makeDefault({"a.glb"});
    g.setParam(2, "max_children", 4);
    HandEdits e;
    e.locked = {{0, 1}};
    g.setHandEdits(2, e);
    g.setPosition(3, 10.0, 20.0);
    const nlohmann::json j = g.toJson();
    const PipelineGraph back = PipelineGraph::fromJson(j);
    EXPECT_EQ(back.toJson(), j);
    EXPECT_EQ(back.node(2).edits, e);
    EXPECT_EQ(back.node(3).x, 10.0);

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
