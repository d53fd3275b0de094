// Hand-editing clusters in the editor (issue #7): split, move by drag and drop and by the "Move
// to Cluster" action, exclude and include, Ctrl-click multi-selection in the Clusters tree (and
// its highlight of every selected cluster in the viewport), each an undoable command followed by
// a rebuild (AutoRebuild) whose tree is the one `hlod build PROJECT.hlodproj` makes; and a
// project saved with hand edits reopens with them.
//
// The scene is the embedded sample (97 meshes) built with the document's own parameters, so a
// rebuild without edits gives the same tree: what changes between two builds is the edit.
#include <gtest/gtest.h>

#include <algorithm>

#include <QAction>
#include <QItemSelectionModel>
#include <QMimeData>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeView>
#include <QUndoStack>

#include <vtkRenderer.h>

#include "TestBuilds.h"
#include "pipeline/doc/Commands.h"
#include "pipeline/view/TreeViews.h"
#include "widgets/ClusterEditActions.h"
#include "widgets/ClusterTreeModel.h"
#include "widgets/DisplayController.h"
#include "widgets/GlSupport.h"
#include "widgets/SceneActors.h"
#include "widgets/SceneTreeModel.h"
#include "widgets/SelectionSync.h"
#include "widgets/StudioModel.h"
#include "widgets/Viewport.h"
#include "widgets/doc/AutoRebuild.h"
#include "widgets/doc/ProjectSession.h"

namespace hlod::widgets {
namespace {

const HandEdits& editsOf(const Document& doc) { return doc.graph().node(kDefaultCluster).edits; }

// The tree the Cluster node of `doc` gives when its graph runs afresh (what `hlod build
// PROJECT` runs), over `scene`.
std::shared_ptr<const ClusterTree> freshTree(const Document& doc,
                                             std::shared_ptr<const Scene> scene, NodeId node) {
    PipelineGraph graph = PipelineGraph::fromJson(doc.graph().toJson());
    test::seedScene(graph, std::move(scene));
    graph.run({node});
    return graph.output(node)->tree;
}

// The editor's pieces as the main window wires them, over the sample scene and its build.
class HandEdit : public ::testing::Test {
protected:
    void SetUp() override {
        const BuiltHlod& sample = test::sampleBuild();
        // The sample build's parameters (TestBuilds.h), so an unedited rebuild is the same tree.
        ASSERT_TRUE(test::showSampleBuild(session, model));
        tree.setModel(&treeModel);
        treeModel.setBuild(sample.scene, sample.build);
        QObject::connect(&model, &StudioModel::buildFinished, &treeModel,
                         [this] { treeModel.setBuild(model.built().scene, model.built().build); });
        edits = std::make_unique<ClusterEditActions>(&session, &model, &tree, &treeModel);
        rebuild = std::make_unique<AutoRebuild>(&session, &model);
        rebuild->setDelay(0);
    }

    const ClusterTree& current() const { return *model.built().build->tree; }
    void select(const std::vector<Id>& nodes) {
        tree.selectionModel()->clear();
        for (Id node : nodes)
            tree.selectionModel()->select(treeModel.indexOfNode(node),
                                          QItemSelectionModel::Select | QItemSelectionModel::Rows);
    }
    // A click on the row of `node` in the shown tree (scrolled into view first, as a person
    // would: the root of the sample has more children than the view shows at once).
    void clickRow(Id node, Qt::KeyboardModifiers mods) {
        tree.scrollTo(treeModel.indexOfNode(node));
        const QRect rect = tree.visualRect(treeModel.indexOfNode(node));
        ASSERT_TRUE(rect.isValid());
        QTest::mouseClick(tree.viewport(), Qt::LeftButton, mods, rect.center());
    }
    // The instances below `nodes` (sorted, each once).
    std::vector<Id> instancesOf(const std::vector<Id>& nodes) const {
        std::vector<Id> out;
        for (Id node : nodes) {
            const std::vector<Id> below = instancesBelow(current(), node);
            out.insert(out.end(), below.begin(), below.end());
        }
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return out;
    }
    // Inner children of the root, in row order.
    std::vector<Id> innerChildrenOfRoot() const {
        std::vector<Id> out;
        for (Id c : current().nodes[current().root].children)
            if (!current().nodes[c].isLeaf()) out.push_back(c);
        return out;
    }

    // Shows the Clusters tree next to a Scene tree, both synced to the model as in the main
    // window, with the root's children visible.
    void showSyncedTrees() {
        sceneModel.setScene(model.scene());
        sceneTree.setModel(&sceneModel);
        sync = std::make_unique<SelectionSync>(&model, &sceneTree, &sceneModel, &tree, &treeModel);
        tree.resize(500, 600);
        tree.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&tree));
        tree.expandToDepth(0);
    }

    ProjectSession session;
    StudioModel model;
    ClusterTreeModel treeModel;
    QTreeView tree;
    std::unique_ptr<ClusterEditActions> edits;
    std::unique_ptr<AutoRebuild> rebuild;
    SceneTreeModel sceneModel;
    QTreeView sceneTree;
    std::unique_ptr<SelectionSync> sync;
};

TEST_F(HandEdit, SplitHangsTheChildrenFromTheParentAndUndoRestores) {
    // Every proxy kept (proxy ratio 1, set as a person would, one more undo step): a split
    // acts on the clustered tree, and under the default economy the cluster shown under the
    // root may have a dissolved parent there, which takes the children and may then pay for
    // its own proxy (the sample's {43, 45} sits in a 12-mesh cluster that only reappears once
    // {43, 45} is split). What is tested here is the split itself, on a tree shown as clustered.
    ASSERT_TRUE(
        session.undo()->execute(std::make_unique<SetParameter>(kDefaultBake, "proxy_ratio", 1.0)));
    ASSERT_TRUE(test::waitForBuild(model));
    ASSERT_EQ(model.built().build->bake->dissolved, 0u);
    const std::vector<Id> inner = innerChildrenOfRoot();
    ASSERT_FALSE(inner.empty());
    const Id cluster = inner.front();
    const InstanceSet splitSet = leafSet(current(), cluster);
    std::vector<InstanceSet> childSets;
    for (Id c : current().nodes[cluster].children)
        childSets.push_back(leafSet(current(), c));
    const std::size_t nodesBefore = current().nodes.size();

    select({cluster});
    edits->updateActions();
    ASSERT_TRUE(edits->splitAction()->isEnabled());
    ASSERT_TRUE(edits->split());
    EXPECT_EQ(editsOf(session.document()).dissolved, std::vector<InstanceSet>{splitSet});
    EXPECT_EQ(session.undo()->stack()->undoText(), QStringLiteral("Split cluster (Cluster #2)"));
    ASSERT_TRUE(test::waitForBuild(model));

    // The split cluster is gone; each of its children hangs from its parent, the root.
    const ClusterTree& after = current();
    EXPECT_EQ(after.nodes.size(), nodesBefore - 1);
    EXPECT_EQ(findCluster(after, splitSet), kNoId);
    for (const InstanceSet& child : childSets) {
        const Id c = findCluster(after, child);
        ASSERT_NE(c, kNoId);
        EXPECT_EQ(after.nodes[c].parent, after.root);
    }

    // The same tree as a fresh run of the document's graph (what `hlod build PROJECT` runs).
    const std::shared_ptr<const ClusterTree> cli =
        freshTree(session.document(), model.scene(), kDefaultBake);
    ASSERT_EQ(cli->nodes.size(), after.nodes.size());
    for (Id n = 0; n < cli->nodes.size(); ++n)
        EXPECT_EQ(leafSet(*cli, n), leafSet(after, n)) << n;

    session.undo()->stack()->undo();
    EXPECT_TRUE(editsOf(session.document()).dissolved.empty());
    ASSERT_TRUE(test::waitForBuild(model));
    EXPECT_EQ(current().nodes.size(), nodesBefore);
    EXPECT_NE(findCluster(current(), splitSet), kNoId);
}

TEST_F(HandEdit, SplitIsRefusedForTheRootAndLeaves) {
    Id leaf = current().root;
    while (!current().nodes[leaf].isLeaf())
        leaf = current().nodes[leaf].children.front();
    select({current().root, leaf});
    edits->updateActions();
    EXPECT_FALSE(edits->splitAction()->isEnabled());
    EXPECT_FALSE(edits->split());
    EXPECT_EQ(session.document().history().count(), 2u); // only the two parameter edits
}

TEST_F(HandEdit, DroppingALeafOnAnotherClusterMovesItThere) {
    const std::vector<Id> inner = innerChildrenOfRoot();
    ASSERT_GE(inner.size(), 2u);
    const Id from = inner[0];
    const Id target = inner[1];
    // A leaf below `from`: the first leaf of its subtree.
    Id leaf = from;
    while (!current().nodes[leaf].isLeaf())
        leaf = current().nodes[leaf].children.front();
    const Id instance = current().nodes[leaf].instance;
    const InstanceSet targetSet = leafSet(current(), target);

    std::unique_ptr<QMimeData> data(treeModel.mimeData({treeModel.indexOfNode(leaf)}));
    ASSERT_NE(data, nullptr);
    const QModelIndex onTarget = treeModel.indexOfNode(target);
    // Refused: the root, the leaf's own parent (nothing would move), the leaf itself.
    EXPECT_FALSE(treeModel.canDropMimeData(data.get(), Qt::MoveAction, -1, -1,
                                           treeModel.indexOfNode(current().root)));
    EXPECT_FALSE(treeModel.canDropMimeData(data.get(), Qt::MoveAction, -1, -1,
                                           treeModel.indexOfNode(current().nodes[leaf].parent)));
    EXPECT_FALSE(
        treeModel.canDropMimeData(data.get(), Qt::MoveAction, -1, -1, treeModel.indexOfNode(leaf)));
    ASSERT_TRUE(treeModel.canDropMimeData(data.get(), Qt::MoveAction, -1, -1, onTarget));

    QSignalSpy requested(&treeModel, &ClusterTreeModel::moveRequested);
    ASSERT_TRUE(treeModel.dropMimeData(data.get(), Qt::MoveAction, -1, -1, onTarget));
    ASSERT_EQ(requested.count(), 1);
    EXPECT_EQ(session.undo()->stack()->undoText(), QStringLiteral("Move to cluster (Cluster #2)"));
    // The target became a locked group holding the leaf (ClusterEdits.h moveToCluster).
    InstanceSet moved = targetSet;
    moved.push_back(instance);
    moved = normalizedSet(moved);
    ASSERT_EQ(editsOf(session.document()).locked, std::vector<InstanceSet>{moved});
    ASSERT_TRUE(test::waitForBuild(model));

    const Id group = findCluster(current(), moved);
    ASSERT_NE(group, kNoId); // the rebuilt tree has the leaf under the target's cluster
    EXPECT_TRUE(current().nodes[group].locked);
    Id up = current().nodes[instance].parent; // leaves keep the instance ids as node ids
    while (up != kNoId && up != group)
        up = current().nodes[up].parent;
    EXPECT_EQ(up, group);

    session.undo()->stack()->undo();
    EXPECT_TRUE(editsOf(session.document()).empty());
    ASSERT_TRUE(test::waitForBuild(model));
    EXPECT_EQ(findCluster(current(), moved), kNoId);
}

TEST_F(HandEdit, IncludeUndoesAnExclude) {
    const std::vector<Id> inner = innerChildrenOfRoot();
    ASSERT_FALSE(inner.empty());
    Id leaf = inner.front();
    while (!current().nodes[leaf].isLeaf())
        leaf = current().nodes[leaf].children.front();
    const Id instance = current().nodes[leaf].instance;

    select({leaf});
    edits->updateActions();
    EXPECT_FALSE(edits->includeAction()->isEnabled()); // nothing excluded yet
    ASSERT_TRUE(edits->exclude());
    EXPECT_EQ(editsOf(session.document()).excluded, InstanceSet{instance});
    ASSERT_TRUE(test::waitForBuild(model));
    // Excluded: a leaf directly under the root.
    const Id excludedLeaf = findCluster(current(), {instance});
    ASSERT_NE(excludedLeaf, kNoId);
    EXPECT_EQ(current().nodes[excludedLeaf].parent, current().root);

    select({excludedLeaf});
    edits->updateActions();
    ASSERT_TRUE(edits->includeAction()->isEnabled());
    ASSERT_TRUE(edits->include());
    EXPECT_TRUE(editsOf(session.document()).excluded.empty());
    EXPECT_EQ(session.undo()->stack()->undoText(), QStringLiteral("Include in HLOD (Cluster #2)"));
    ASSERT_TRUE(test::waitForBuild(model));
    EXPECT_NE(current().nodes[findCluster(current(), {instance})].parent, current().root);
    EXPECT_EQ(session.document().history().count(), 4u); // cache, threads, exclude, include
}

TEST_F(HandEdit, CtrlClickSelectsSeveralClustersAndEnablesMerge) {
    ASSERT_NO_FATAL_FAILURE(showSyncedTrees());
    const std::vector<Id> inner = innerChildrenOfRoot();
    ASSERT_GE(inner.size(), 2u);
    clickRow(inner[0], Qt::NoModifier);
    EXPECT_EQ(model.selection().clusterNode, inner[0]);
    clickRow(inner[1], Qt::ControlModifier);
    // The model holds both rows (the viewport highlights both); the last click is current.
    EXPECT_EQ(model.selection().clusterNode, inner[1]);
    EXPECT_EQ(edits->selectedNodes(),
              (std::vector<Id>{std::min(inner[0], inner[1]), std::max(inner[0], inner[1])}));
    edits->updateActions();
    EXPECT_TRUE(edits->mergeAction()->isEnabled());

    // Ctrl-click again deselects that row; the model shows the row still selected.
    clickRow(inner[1], Qt::ControlModifier);
    EXPECT_EQ(edits->selectedNodes(), std::vector<Id>{inner[0]});
    EXPECT_EQ(model.selection().clusterNode, inner[0]);
    // A selection made elsewhere (a click in the viewport) replaces the rows.
    clickRow(inner[1], Qt::ControlModifier);
    model.selectClusterNode(current().root);
    EXPECT_EQ(edits->selectedNodes(), std::vector<Id>{current().root});
    // A plain click selects one row again.
    clickRow(inner[1], Qt::NoModifier);
    EXPECT_EQ(edits->selectedNodes(), std::vector<Id>{inner[1]});
    // Shift-click selects the range of rows between the two (siblings under the root).
    clickRow(inner[0], Qt::ShiftModifier);
    const std::vector<Id> range = edits->selectedNodes();
    EXPECT_GE(range.size(), 2u);
    EXPECT_NE(std::find(range.begin(), range.end(), inner[0]), range.end());
    EXPECT_NE(std::find(range.begin(), range.end(), inner[1]), range.end());
    EXPECT_EQ(model.selection().clusterNode, inner[0]);
    edits->updateActions();
    EXPECT_TRUE(edits->mergeAction()->isEnabled());
}

TEST_F(HandEdit, SeveralSelectedClustersAreAllHighlighted) {
    const GlProbeResult gl = probeOpenGl();
    ASSERT_TRUE(gl.ok) << gl.problem.toStdString();
    Viewport viewport;
    viewport.setFixedSize(320, 240);
    DisplayController display(&model, &viewport);
    viewport.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&viewport));
    ASSERT_NO_FATAL_FAILURE(showSyncedTrees());
    const std::vector<Id> inner = innerChildrenOfRoot();
    ASSERT_GE(inner.size(), 2u);
    const std::vector<Id> both{std::min(inner[0], inner[1]), std::max(inner[0], inner[1])};

    clickRow(inner[0], Qt::NoModifier);
    EXPECT_EQ(display.highlightedInstances(), instancesOf({inner[0]}));
    clickRow(inner[1], Qt::ControlModifier);
    // Both clusters are the model's selection; the clicked one is current.
    EXPECT_EQ(model.selectedNodes(), both);
    EXPECT_EQ(model.selection().clusterNode, inner[1]);
    const std::vector<Id> all = instancesOf(both);
    EXPECT_GT(all.size(), instancesOf({inner[1]}).size());
    EXPECT_EQ(model.selection().instances, all);
    EXPECT_EQ(display.highlightedInstances(), all); // the union, not the last click's
    // Ctrl-click again: back to the first cluster's meshes.
    clickRow(inner[1], Qt::ControlModifier);
    EXPECT_EQ(model.selectedNodes(), std::vector<Id>{inner[0]});
    EXPECT_EQ(display.highlightedInstances(), instancesOf({inner[0]}));

    // A multi-selection set in the model selects every row of the tree.
    model.setSelection({inner[1], inner[0]}, inner[0]);
    EXPECT_EQ(edits->selectedNodes(), both);
    EXPECT_EQ(tree.selectionModel()->currentIndex(), treeModel.indexOfNode(inner[0]));
    EXPECT_EQ(display.highlightedInstances(), all);
    model.clearSelection();
    EXPECT_TRUE(display.highlightedInstances().empty());
    EXPECT_TRUE(edits->selectedNodes().empty());
}

TEST_F(HandEdit, MoveToClusterMovesTheOtherRowsIntoTheCurrentOneAsADropDoes) {
    const std::vector<Id> inner = innerChildrenOfRoot();
    ASSERT_GE(inner.size(), 2u);
    const Id target = inner[1];
    Id leaf = inner[0];
    while (!current().nodes[leaf].isLeaf())
        leaf = current().nodes[leaf].children.front();
    const Id instance = current().nodes[leaf].instance;
    auto makeCurrent = [&](Id node) {
        tree.selectionModel()->setCurrentIndex(treeModel.indexOfNode(node),
                                               QItemSelectionModel::NoUpdate);
        edits->updateActions();
    };

    // Only the target selected: nothing to move.
    select({target});
    makeCurrent(target);
    EXPECT_FALSE(edits->moveAction()->isEnabled());
    // The leaf current: refused, as a drop onto a leaf is.
    select({leaf, target});
    makeCurrent(leaf);
    EXPECT_FALSE(edits->moveAction()->isEnabled());
    EXPECT_FALSE(edits->moveToCurrent());
    // The root current: refused, as a drop onto the root is.
    select({leaf, current().root});
    makeCurrent(current().root);
    EXPECT_FALSE(edits->moveAction()->isEnabled());
    EXPECT_EQ(session.document().history().count(), 2u); // only the two parameter edits

    select({leaf, target});
    makeCurrent(target);
    ASSERT_TRUE(edits->moveAction()->isEnabled());
    edits->moveAction()->trigger();
    EXPECT_EQ(session.undo()->stack()->undoText(), QStringLiteral("Move to cluster (Cluster #2)"));
    const HandEdits moved = editsOf(session.document());
    InstanceSet group = leafSet(current(), target);
    group.push_back(instance);
    group = normalizedSet(group);
    ASSERT_EQ(moved.locked, std::vector<InstanceSet>{group});

    // Dropping the leaf on the target makes the same edit.
    session.undo()->stack()->undo();
    ASSERT_TRUE(editsOf(session.document()).empty());
    std::unique_ptr<QMimeData> data(treeModel.mimeData({treeModel.indexOfNode(leaf)}));
    ASSERT_TRUE(
        treeModel.dropMimeData(data.get(), Qt::MoveAction, -1, -1, treeModel.indexOfNode(target)));
    EXPECT_EQ(editsOf(session.document()), moved);

    ASSERT_TRUE(test::waitForBuild(model));
    const Id cluster = findCluster(current(), group);
    ASSERT_NE(cluster, kNoId);
    EXPECT_TRUE(current().nodes[cluster].locked);
}

TEST_F(HandEdit, ProjectWithHandEditsReopensWithThem) {
    const std::vector<Id> inner = innerChildrenOfRoot();
    ASSERT_GE(inner.size(), 3u);
    select({inner[0], inner[1]});
    ASSERT_TRUE(edits->merge());
    select({inner[2]});
    ASSERT_TRUE(edits->split());
    const HandEdits saved = editsOf(session.document());
    ASSERT_EQ(saved.locked.size(), 1u);
    ASSERT_EQ(saved.dissolved.size(), 1u);
    ASSERT_TRUE(test::waitForBuild(model));

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("edited.hlodproj"));
    session.save(path);
    ProjectSession reopened;
    reopened.open(path);
    EXPECT_EQ(editsOf(reopened.document()), saved);
    // The reopened project builds the tree the editor showed when it was saved.
    const std::shared_ptr<const ClusterTree> again =
        freshTree(reopened.document(), model.scene(), kDefaultBake);
    const ClusterTree& shown = current();
    ASSERT_EQ(again->nodes.size(), shown.nodes.size());
    for (Id n = 0; n < again->nodes.size(); ++n)
        EXPECT_EQ(leafSet(*again, n), leafSet(shown, n)) << n;
}

TEST(HandEditViewport, CtrlClickAddsPickedClustersAndARightClickKeepsThem) {
    const GlProbeResult gl = probeOpenGl();
    ASSERT_TRUE(gl.ok) << gl.problem.toStdString();
    const BuiltHlod built = test::buildNow(std::make_shared<const Scene>(test::makeCubeRow()));
    ProjectSession session;
    StudioModel model;
    model.setGraph(&session.document().graph()); // hand edits act on the shown branch's Cluster
    model.setScene(built.scene);
    model.setBuilt(built);
    ClusterTreeModel treeModel;
    treeModel.setBuild(built.scene, built.build);
    QTreeView tree;
    tree.setModel(&treeModel);
    Viewport viewport;
    viewport.setFixedSize(480, 360);
    DisplayController display(&model, &viewport);
    viewport.setSceneActors(SceneActors::build(*built.scene), suggestedUpAxis(*built.scene));
    viewport.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&viewport));
    ClusterEditActions edits(&session, &model, &tree, &treeModel);
    edits.attachViewport(&viewport, &display);
    viewport.grabFrame(); // lays out and fits the camera
    auto project = [&](const glm::dvec3& p) {
        vtkRenderer* r = viewport.renderer();
        r->SetWorldPoint(p.x, p.y, p.z, 1.0);
        r->WorldToDisplay();
        const double* d = r->GetDisplayPoint();
        const double dpr = viewport.devicePixelRatioF();
        return QPoint(static_cast<int>(d[0] / dpr),
                      static_cast<int>(viewport.height() - d[1] / dpr));
    };
    // Cubes 0 and 2 sit at x = -4 and +4 (TestBuilds.h).
    const Id leaf0 = leafOfInstance(*built.build->tree, 0);
    const Id leaf2 = leafOfInstance(*built.build->tree, 2);
    const QPoint cube0 = project({-4.0, 0.0, 0.0});
    const QPoint cube2 = project({4.0, 0.0, 0.0});
    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::ControlModifier, cube0);
    EXPECT_EQ(edits.selectedNodes(), std::vector<Id>{leaf0});
    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::ControlModifier, cube2);
    EXPECT_EQ(edits.selectedNodes(), (std::vector<Id>{leaf0, leaf2}));
    EXPECT_EQ(model.selection().clusterNode, leaf2); // the last pick is highlighted
    edits.updateActions();
    EXPECT_TRUE(edits.mergeAction()->isEnabled());
    // The context menu's pick of a selected cluster keeps the selection.
    EXPECT_EQ(edits.selectForMenuAt(cube0), leaf0);
    EXPECT_EQ(edits.selectedNodes(), (std::vector<Id>{leaf0, leaf2}));
    // Ctrl+click on a selected cluster removes it.
    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::ControlModifier, cube2);
    EXPECT_EQ(edits.selectedNodes(), std::vector<Id>{leaf0});
    // In Clusters mode a pick means the coloured cluster of the shown level: at the top level
    // that is the root alone, whatever cube is clicked.
    model.setMode(DisplayMode::Clusters);
    model.setLevel(model.maxLevel());
    viewport.grabFrame();
    EXPECT_EQ(edits.toggleAt(cube2), built.build->tree->root);
}

} // namespace
} // namespace hlod::widgets
