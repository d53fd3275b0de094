// Tests of widgets/StudioModel and GraphRunner: background runs of the graph, cancellation,
// failures, statistics, branches (the shown Bake node, the kept builds, statuses brought into the
// graph), and the selection mapping between instances, scene nodes and (one or several) cluster
// nodes.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <thread>

#include <QCoreApplication>
#include <QSignalSpy>
#include <QTimer>

#include "TestBuilds.h"
#include "TestScenes.h"
#include "pipeline/io/SampleScene.h"
#include "pipeline/proxy/ProxyEconomy.h"
#include "pipeline/view/TreeViews.h"
#include "widgets/StudioModel.h"

namespace hlod::widgets {
namespace {

// Long enough for the sample scene's build on a loaded 2-core machine, short enough to fail.
constexpr int kBuildWaitMs = 180000;

std::shared_ptr<const Scene> sample() { return std::make_shared<const Scene>(makeSampleScene()); }

// Opens the tiny test scene in `model` and hands it a build of it; returns the scene.
std::shared_ptr<const Scene> openBuiltTinyScene(StudioModel& model) {
    const auto scene = std::make_shared<const Scene>(test::makeTinyScene());
    model.setScene(scene);
    model.setBuilt(test::buildNow(scene));
    return scene;
}

// `model` running `graph` (seeded with `scene`) and showing its Bake node.
void runGraph(StudioModel& model, PipelineGraph& graph, std::shared_ptr<const Scene> scene) {
    model.setScene(scene);
    model.setGraph(&graph);
    model.setShownBake(kDefaultBake);
}

TEST(StudioModel, BuildsInTheBackgroundAndKeepsTheStatisticsOfBakeStats) {
    StudioModel model;
    const auto scene = sample();
    PipelineGraph graph = test::testGraph(scene);
    runGraph(model, graph, scene);
    std::vector<std::pair<quint32, NodeStatus>> statuses;
    QObject::connect(&model, &StudioModel::nodeStatusChanged, [&](quint32 node) {
        statuses.push_back({node, graph.status(node)});
    });
    QSignalSpy finished(&model, &StudioModel::buildFinished);
    QSignalSpy progress(&model, &StudioModel::buildProgress);
    // The event loop keeps running while the worker bakes: a timer on the GUI thread ticks.
    int ticks = 0;
    QTimer timer;
    QObject::connect(&timer, &QTimer::timeout, [&] { ++ticks; });
    timer.start(5);
    model.build();
    EXPECT_TRUE(model.building());
    ASSERT_TRUE(finished.wait(kBuildWaitMs));
    EXPECT_GT(ticks, 0);
    EXPECT_GT(progress.count(), 0);
    EXPECT_FALSE(model.building());
    ASSERT_TRUE(model.hasBuild());
    // The run's statuses came into the graph as they happened: Cluster then Bake ran (the Import
    // node held the scene already), each running, then up to date.
    EXPECT_EQ(statuses,
              (std::vector<std::pair<quint32, NodeStatus>>{{kDefaultCluster, NodeStatus::Running},
                                                           {kDefaultCluster, NodeStatus::UpToDate},
                                                           {kDefaultBake, NodeStatus::Running},
                                                           {kDefaultBake, NodeStatus::UpToDate}}));
    EXPECT_EQ(graph.status(kDefaultExport), NodeStatus::Pending); // not asked for

    const BuiltHlod& built = model.built();
    EXPECT_EQ(built.build, graph.sharedOutput(kDefaultBake));
    const ClusterTree& tree = *built.build->tree;
    // The rows the statistics dock shows are exactly BakeStats' rows for this build.
    const GeometryStats original = originalStats(*model.scene());
    const GeometryStats hlod = hlodStats(*model.scene(), tree, *built.build->bake, "x");
    EXPECT_EQ(built.original.triangles, original.triangles);
    EXPECT_EQ(built.original.meshes, original.meshes);
    EXPECT_EQ(built.hlod.triangles, hlod.triangles);
    EXPECT_EQ(built.hlod.vertices, hlod.vertices);
    EXPECT_EQ(built.hlod.bytes, hlod.bytes);
    // HLOD meshes: one per leaf (original) plus one per proxy. After the proxy economy every
    // inner node keeps its proxy except, possibly, the root (rootHasNoProxy: a root whose proxy
    // does not pay is always refined and stores nothing), so the count is the tree's nodes
    // less such a root.
    std::size_t meshes = 0;
    for (Id n = 0; n < tree.nodes.size(); ++n)
        if (tree.nodes[n].isLeaf() || built.build->bake->nodes[n].hasProxy) ++meshes;
    EXPECT_EQ(meshes, tree.nodes.size() - (rootHasNoProxy(tree, *built.build->bake) ? 1 : 0));
    EXPECT_EQ(built.hlod.meshes, meshes);
    EXPECT_EQ(built.hlod.version, "HLOD, sphere");
    // The root's subtree holds every instance's triangles.
    EXPECT_EQ(model.subtreeTriangles()[tree.root], model.scene()->stats().triangles);
    EXPECT_EQ(model.maxLevel(), tree.height());
}

TEST(StudioModel, CancelEndsWithoutAResultAndTheNextBuildWorks) {
    StudioModel model;
    const auto scene = sample();
    PipelineGraph graph = test::testGraph(scene);
    runGraph(model, graph, scene);
    QSignalSpy finished(&model, &StudioModel::buildFinished);
    QSignalSpy cancelled(&model, &StudioModel::buildCancelled);
    // Cancel right after the run started: the worker thread is already going, the flag is
    // raised under it. (Cancelling from a queued progress signal raced with the bake, which
    // now finishes the sample before the signal is delivered.)
    model.build();
    ASSERT_TRUE(model.building());
    model.cancelBuild();
    ASSERT_TRUE(cancelled.count() > 0 || cancelled.wait(kBuildWaitMs));
    EXPECT_EQ(finished.count(), 0);
    EXPECT_FALSE(model.hasBuild());
    EXPECT_FALSE(model.building());
    // Nothing is left running in the graph: the cancelled node is pending again.
    for (NodeId id : graph.nodeIds())
        EXPECT_NE(graph.status(id), NodeStatus::Running) << id;

    model.build();
    ASSERT_TRUE(finished.wait(kBuildWaitMs));
    EXPECT_TRUE(model.hasBuild());
    EXPECT_EQ(cancelled.count(), 1);
}

TEST(StudioModel, ACancelWhileTheResultIsOnItsWayStillEndsWithoutAResult) {
    StudioModel model;
    const auto scene = std::make_shared<const Scene>(test::makeTinyScene());
    PipelineGraph graph = test::testGraph(scene);
    runGraph(model, graph, scene);
    QSignalSpy finished(&model, &StudioModel::buildFinished);
    QSignalSpy cancelled(&model, &StudioModel::buildCancelled);
    model.build();
    // The tiny scene builds in milliseconds: with no events processed meanwhile, the worker has
    // ended and its result waits in the event queue when the cancel comes (a Compare window
    // closed just then). The result is dropped: cancelled(), never finished().
    std::this_thread::sleep_for(std::chrono::seconds(3));
    ASSERT_TRUE(model.building());
    model.cancelBuild();
    ASSERT_TRUE(cancelled.wait(30000)); // already queued: delivered at once
    QCoreApplication::processEvents();
    EXPECT_EQ(finished.count(), 0);
    EXPECT_EQ(cancelled.count(), 1);
    EXPECT_FALSE(model.hasBuild());
    EXPECT_FALSE(model.building());
}

TEST(StudioModel, AGraphThatCannotRunFailsNamingTheNodeAndMarksItFailed) {
    StudioModel model;
    const auto scene = std::make_shared<const Scene>(test::makeTinyScene());
    PipelineGraph graph = test::testGraph(scene);
    graph.disconnect({kDefaultCluster, 0, kDefaultBake, 0});
    runGraph(model, graph, scene);
    QSignalSpy failed(&model, &StudioModel::buildFailed);
    model.build();
    ASSERT_TRUE(failed.wait(kBuildWaitMs));
    EXPECT_EQ(failed.front().front().toString(),
              QStringLiteral("Bake #3 has no Cluster node upstream: connect a Cluster node's "
                             "clusters output to its input"));
    EXPECT_FALSE(model.hasBuild());
    // The refusal is the node's status, with its message (the Pipeline dock shows it).
    EXPECT_EQ(graph.status(kDefaultBake), NodeStatus::Failed);
    EXPECT_EQ(graph.error(kDefaultBake), failed.front().front().toString().toStdString());
}

TEST(StudioModel, EachBranchKeepsItsBuildAndShowingOneShowsItAtOnce) {
    // Two branches from one import: the default sphere chain and an AABB k = 2 one.
    StudioModel model;
    const auto scene = std::make_shared<const Scene>(test::makeTinyScene());
    PipelineGraph graph = test::testGraph(scene);
    const NodeId cluster = graph.addNode(NodeKind::Cluster);
    const NodeId bake = graph.addNode(NodeKind::Bake);
    graph.connect({kDefaultImport, 0, cluster, 0});
    graph.connect({cluster, 0, bake, 0});
    graph.setParam(cluster, "volume", std::string("aabb"));
    graph.setParam(cluster, "k", 2.0);
    for (const auto& [key, value] : test::testBakeValues())
        graph.setParam(bake, key, value);
    runGraph(model, graph, scene);
    EXPECT_EQ(model.bakeNodes(), (std::vector<NodeId>{kDefaultBake, bake}));
    EXPECT_EQ(model.branchLabel(bake), QStringLiteral("Cluster #5 → Bake #6"));
    QSignalSpy finished(&model, &StudioModel::runFinished);
    model.buildAll();
    ASSERT_TRUE(finished.wait(kBuildWaitMs));
    EXPECT_EQ(graph.status(kDefaultBake), NodeStatus::UpToDate);
    EXPECT_EQ(graph.status(bake), NodeStatus::UpToDate);
    ASSERT_NE(model.builtOf(bake), nullptr);
    EXPECT_EQ(model.built().bakeNode, kDefaultBake); // the shown one
    EXPECT_EQ(model.built().build->cluster.volume, VolumeType::Sphere);
    // Showing the other branch shows its build without a run.
    QSignalSpy shown(&model, &StudioModel::buildFinished);
    model.setShownBake(bake);
    EXPECT_EQ(shown.count(), 1);
    EXPECT_FALSE(model.building());
    EXPECT_EQ(model.built().bakeNode, bake);
    EXPECT_EQ(model.built().build->cluster.volume, VolumeType::Aabb);
    EXPECT_EQ(model.shownCluster(), cluster);
    // A branch never built shows nothing until it is.
    const NodeId third = graph.addNode(NodeKind::Bake);
    graph.connect({cluster, 0, third, 0});
    model.setShownBake(third);
    EXPECT_FALSE(model.hasBuild());
}

TEST(StudioModel, SelectionMapsBetweenInstancesSceneNodesAndClusters) {
    StudioModel model;
    openBuiltTinyScene(model);
    ASSERT_TRUE(model.hasBuild());
    const ClusterTree& tree = *model.built().build->tree;
    QSignalSpy changed(&model, &StudioModel::selectionChanged);

    // Node 2 "group" holds node 3 "right", which holds instance 1 only.
    model.selectSceneNode(2);
    EXPECT_EQ(model.selection().instances, std::vector<Id>{1});
    EXPECT_EQ(model.selection().clusterNode, leafOfInstance(tree, 1));
    EXPECT_EQ(changed.count(), 1);
    model.selectSceneNode(2); // same selection: no signal
    EXPECT_EQ(changed.count(), 1);

    // The cluster root covers all three instances; they sit on different scene nodes.
    model.selectClusterNode(tree.root);
    EXPECT_EQ(model.selection().instances, (std::vector<Id>{0, 1, 2}));
    EXPECT_EQ(model.selection().sceneNode, kNoId);

    // Instance 2 (the quad) is placed on the root node 0.
    model.selectInstance(2);
    EXPECT_EQ(model.selection().sceneNode, 0u);
    EXPECT_EQ(model.selection().clusterNode, leafOfInstance(tree, 2));

    model.selectInstance(kNoId);
    EXPECT_TRUE(model.selection().empty());
}

TEST(StudioModel, SeveralClusterNodesSelectTheUnionOfTheirInstances) {
    StudioModel model;
    openBuiltTinyScene(model);
    ASSERT_TRUE(model.hasBuild());
    const ClusterTree& tree = *model.built().build->tree;
    const Id leaf0 = leafOfInstance(tree, 0);
    const Id leaf2 = leafOfInstance(tree, 2);
    QSignalSpy changed(&model, &StudioModel::selectionChanged);

    // Ids outside the tree are dropped; `current` becomes the selection's cluster node.
    model.setSelection({leaf2, kNoId, leaf0, leaf2}, leaf2);
    EXPECT_EQ(model.selectedNodes(),
              (std::vector<Id>{std::min(leaf0, leaf2), std::max(leaf0, leaf2)}));
    EXPECT_EQ(model.selection().clusterNode, leaf2);
    EXPECT_EQ(model.selection().instances, (std::vector<Id>{0, 2}));
    EXPECT_EQ(model.selection().sceneNode, kNoId);
    EXPECT_EQ(changed.count(), 1);
    // A current node that is not selected falls back to the first selected one.
    model.setSelection({leaf0, leaf2}, tree.root);
    EXPECT_EQ(model.selection().clusterNode, std::min(leaf0, leaf2));
    // A node inside another selected one adds no instance twice.
    model.setSelection({tree.root, leaf0});
    EXPECT_EQ(model.selection().instances, (std::vector<Id>{0, 1, 2}));
    // The single-selection calls select one cluster node.
    model.selectInstance(1);
    EXPECT_EQ(model.selectedNodes(), std::vector<Id>{leafOfInstance(tree, 1)});
    model.setSelection({kNoId});
    EXPECT_TRUE(model.selection().empty());
    EXPECT_TRUE(model.selectedNodes().empty());
}

TEST(StudioModel, OpeningAnotherSceneDropsTheBuildAndGoesBackToOriginal) {
    StudioModel model;
    const auto scene = openBuiltTinyScene(model);
    model.setMode(DisplayMode::Hlod);
    model.selectInstance(0);
    model.setScene(std::make_shared<const Scene>(test::makeTinyScene()));
    EXPECT_FALSE(model.hasBuild());
    EXPECT_TRUE(model.selection().empty());
    EXPECT_EQ(model.view().mode, DisplayMode::Original);
    // A build of the old scene arriving late is ignored.
    model.setBuilt(test::buildNow(scene));
    EXPECT_FALSE(model.hasBuild());
}

TEST(StudioModel, DisplayModeNamesParse) {
    DisplayMode mode = DisplayMode::Original;
    EXPECT_TRUE(displayModeFromString(QStringLiteral("HLOD"), mode));
    EXPECT_EQ(mode, DisplayMode::Hlod);
    EXPECT_TRUE(displayModeFromString(QStringLiteral("clusters"), mode));
    EXPECT_EQ(mode, DisplayMode::Clusters);
    EXPECT_FALSE(displayModeFromString(QStringLiteral("wireframe"), mode));
    EXPECT_EQ(mode, DisplayMode::Clusters); // unchanged on failure
}

} // namespace
} // namespace hlod::widgets
