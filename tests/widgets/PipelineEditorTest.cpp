// widgets/graph/PipelineEditor (the Pipeline dock) with the Parameters dock: selecting a node
// shows its parameters (and only its own), a parameter edit there is one undo step named after
// the node and reruns the shown branch (only the bake when a bake parameter changed), the node
// statuses are the graph's as the runs bring them in, the graph's add / connect / duplicate /
// rename / remove requests are undoable commands, and new nodes are placed where no node is.
#include <gtest/gtest.h>

#include <QDoubleSpinBox>
#include <QGraphicsRectItem>
#include <QGroupBox>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include "TestBuilds.h"
#include "pipeline/doc/Commands.h"
#include "widgets/StudioModel.h"
#include "widgets/doc/AutoRebuild.h"
#include "widgets/doc/ProjectSession.h"
#include "widgets/graph/NodeGraphView.h"
#include "widgets/graph/PipelineEditor.h"
#include "widgets/params/BuildParameters.h"
#include "widgets/params/ParameterPanel.h"

namespace hlod::widgets {
namespace {

class PipelineDock : public ::testing::Test {
protected:
    void SetUp() override {
        // The sample build's parameters (TestBuilds.h): the shown build is up to date.
        ASSERT_TRUE(test::showSampleBuild(session, model));
        QObject::connect(&editor, &PipelineEditor::nodeSelected, &params,
                         [this](quint32 node) { params.showNode(node); });
        rebuild.setDelay(0);
        editor.resize(900, 300);
        editor.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&editor));
    }
    void clickNode(NodeId node) {
        NodeGraphView* view = editor.view();
        const QPointF header = view->nodeItem(node)->sceneBoundingRect().topLeft() +
                               QPointF(20.0, NodeGraphView::kHeaderHeight / 2);
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->mapFromScene(header));
    }
    bool waitForBuild() { return test::waitForBuild(model); }
    NodeStatus status(NodeId node) const { return editor.view()->shownStatus(node); }
    const PipelineGraph& graph() const { return session.document().graph(); }

    ProjectSession session;
    StudioModel model;
    AutoRebuild rebuild{&session, &model};
    BuildParameters params{*session.undo(), &model};
    PipelineEditor editor{&session, &model};
};

TEST_F(PipelineDock, SelectingTheClusterNodeShowsKAndEditingItRebuilds) {
    EXPECT_EQ(status(kDefaultImport), NodeStatus::UpToDate);
    EXPECT_EQ(status(kDefaultCluster), NodeStatus::UpToDate);
    EXPECT_EQ(status(kDefaultBake), NodeStatus::UpToDate);
    EXPECT_EQ(editor.view()->shownNode(), kDefaultBake); // outlined: the viewport shows it

    clickNode(kDefaultCluster);
    ASSERT_EQ(params.shownNode(), kDefaultCluster);
    auto* k = params.panel()->findChild<QDoubleSpinBox*>(QStringLiteral("param_k"));
    ASSERT_NE(k, nullptr);
    EXPECT_EQ(k->value(), 1.0);
    // Only the selected node's parameters: no Bake field beside the Cluster's.
    EXPECT_EQ(params.panel()->findChild<QDoubleSpinBox*>(QStringLiteral("param_screen_size")),
              nullptr);

    const std::size_t steps = session.document().history().count();
    QSignalSpy scheduled(&rebuild, &AutoRebuild::rebuildScheduled);
    k->setValue(2.0);
    EXPECT_EQ(session.document().history().count(), steps + 1); // one undo step
    EXPECT_EQ(session.undo()->stack()->undoText(),
              QStringLiteral("Set Proportion k of Cluster #2"));
    EXPECT_EQ(scheduled.count(), 1);
    EXPECT_EQ(status(kDefaultCluster), NodeStatus::Pending); // the edit reached it
    EXPECT_EQ(status(kDefaultBake), NodeStatus::Pending);
    ASSERT_TRUE(waitForBuild());
    EXPECT_EQ(model.built().build->cluster.k, 2.0);
    EXPECT_EQ(status(kDefaultCluster), NodeStatus::UpToDate);

    session.undo()->stack()->undo();
    EXPECT_EQ(k->value(), 1.0);
    ASSERT_TRUE(waitForBuild()); // undo reruns it too
    EXPECT_EQ(model.built().build->cluster.k, 1.0);
}

TEST_F(PipelineDock, AScreenSizeChangeRerunsOnlyTheBake) {
    const std::shared_ptr<const ClusterTree> clustered = graph().output(kDefaultCluster)->tree;
    clickNode(kDefaultBake);
    ASSERT_EQ(params.shownNode(), kDefaultBake);
    auto* size = params.panel()->findChild<QDoubleSpinBox*>(QStringLiteral("param_screen_size"));
    ASSERT_NE(size, nullptr);
    size->setValue(600.0);
    // Clustering is unchanged: the Cluster node stays up to date, the Bake node waits.
    EXPECT_EQ(status(kDefaultCluster), NodeStatus::UpToDate);
    EXPECT_EQ(status(kDefaultBake), NodeStatus::Pending);
    QSignalSpy statuses(&model, &StudioModel::nodeStatusChanged);
    ASSERT_TRUE(waitForBuild());
    // Only the Bake node ran (running, then up to date), on the Cluster node's own tree.
    ASSERT_EQ(statuses.count(), 2);
    EXPECT_EQ(statuses.at(0).at(0).value<quint32>(), kDefaultBake);
    EXPECT_EQ(graph().output(kDefaultCluster)->tree, clustered);
    EXPECT_EQ(model.built().build->bakeParams.screen.screenSize, 600.0);
    EXPECT_EQ(status(kDefaultBake), NodeStatus::UpToDate);
    EXPECT_EQ(status(kDefaultCluster), NodeStatus::UpToDate);
}

TEST_F(PipelineDock, SelectingTheImportNodeShowsOnlyItsParameters) {
    clickNode(kDefaultImport);
    EXPECT_EQ(params.shownNode(), kDefaultImport);
    EXPECT_EQ(params.panel()->node(), kDefaultImport);
    EXPECT_NE(params.panel()->findChild<QWidget*>(QStringLiteral("param_deflection")), nullptr);
    EXPECT_EQ(params.panel()->findChild<QWidget*>(QStringLiteral("param_k")), nullptr);
    EXPECT_EQ(params.group()->title(), QStringLiteral("Import #1 — Import (reading the scene)"));
    // The Import node is not a Bake node: the viewport keeps showing Bake #3.
    EXPECT_EQ(model.shownBake(), kDefaultBake);
}

TEST_F(PipelineDock, GraphEditsAreUndoableCommands) {
    Document& doc = session.document();
    const std::size_t nodes = doc.graph().nodeIds().size();
    ASSERT_TRUE(editor.addNode(NodeKind::Bake, 440.0, 140.0));
    ASSERT_EQ(doc.graph().nodeIds().size(), nodes + 1);
    const NodeId added = doc.graph().nodeIds().back();
    ASSERT_NE(editor.view()->nodeItem(added), nullptr); // the view was redrawn
    EXPECT_EQ(status(added), NodeStatus::Pending);
    EXPECT_EQ(session.undo()->stack()->undoText(), QStringLiteral("Add Bake #5"));

    const Connection c{kDefaultCluster, 0, added, 0};
    ASSERT_TRUE(editor.connectNodes(c));
    EXPECT_EQ(doc.graph().upstreamOf(added), kDefaultCluster);
    EXPECT_EQ(session.undo()->stack()->undoText(), QStringLiteral("Connect Cluster #2 to Bake #5"));
    // A second connection into the same input is refused and changes nothing.
    QSignalSpy failed(session.undo(), &UndoAdapter::commandFailed);
    EXPECT_FALSE(editor.connectNodes({kDefaultImport, 0, added, 0}));
    EXPECT_EQ(failed.count(), 1);
    ASSERT_TRUE(editor.renameNode(added, QStringLiteral("coarse")));
    EXPECT_EQ(doc.graph().node(added).name, "coarse");
    EXPECT_EQ(editor.view()->summaryOf(added), QStringLiteral("S 300 px, decimate"));
    ASSERT_TRUE(editor.disconnectNode(added));
    EXPECT_EQ(doc.graph().upstreamOf(added), kNoNode);
    ASSERT_TRUE(editor.removeNode(added));
    EXPECT_EQ(editor.view()->nodeItem(added), nullptr);
    // Any node may go, the last Bake node too: the editor then has nothing to show.
    ASSERT_TRUE(editor.removeNode(kDefaultExport));

    session.undo()->stack()->undo(); // remove the Export node
    session.undo()->stack()->undo(); // remove
    session.undo()->stack()->undo(); // disconnect
    EXPECT_EQ(doc.graph().upstreamOf(added), kDefaultCluster);
    session.undo()->stack()->undo(); // rename
    EXPECT_EQ(doc.graph().node(added).name, "");
    session.undo()->stack()->undo(); // connect
    session.undo()->stack()->undo(); // add
    EXPECT_EQ(doc.graph().nodeIds().size(), nodes);
    EXPECT_EQ(editor.view()->nodeItem(added), nullptr);
}

TEST_F(PipelineDock, DuplicateBranchPlacesACopyFreeOfOtherNodesAndKeepsTheZoom) {
    const QTransform zoom = editor.view()->transform();
    ASSERT_TRUE(editor.duplicate(kDefaultCluster, true));
    const PipelineGraph& g = graph();
    EXPECT_EQ(g.nodeIds(), (std::vector<NodeId>{1, 2, 3, 4, 5, 6, 7}));
    EXPECT_EQ(g.branchOf(7), (std::vector<NodeId>{1, 5, 6, 7}));
    // The copies keep the originals' layout, one row down, and overlap no box.
    for (NodeId id : g.nodeIds()) {
        const QRectF a = editor.view()->nodeItem(id)->sceneBoundingRect();
        for (NodeId other : g.nodeIds()) {
            if (other == id) continue;
            EXPECT_FALSE(a.intersects(editor.view()->nodeItem(other)->sceneBoundingRect()))
                << id << " and " << other;
        }
    }
    EXPECT_EQ(g.node(6).x, g.node(3).x);
    EXPECT_GT(g.node(6).y, g.node(3).y);
    EXPECT_EQ(editor.view()->transform(), zoom); // adding nodes does not re-zoom
    // The new branch is pending; its Bake node shows its HLOD once clicked (and built).
    EXPECT_EQ(status(6), NodeStatus::Pending);
    clickNode(6);
    EXPECT_EQ(model.shownBake(), 6u);
    EXPECT_EQ(editor.view()->shownNode(), 6u);
    ASSERT_TRUE(waitForBuild()); // AutoRebuild: the shown branch is pending
    EXPECT_EQ(status(5), NodeStatus::UpToDate);
    EXPECT_EQ(status(6), NodeStatus::UpToDate);
    EXPECT_EQ(model.built().bakeNode, 6u);
    EXPECT_EQ(status(7), NodeStatus::Pending); // exports run on File ▸ Export only
}

TEST_F(PipelineDock, AddNodeAfterTheSelectedNodeGoesToItsRightConnected) {
    clickNode(kDefaultCluster);
    // The Add Node menu's Bake entry with Cluster #2 selected.
    ASSERT_TRUE(editor.addAfter(NodeKind::Bake, kDefaultCluster));
    const PipelineGraph& g = graph();
    const NodeId added = g.nodeIds().back();
    EXPECT_EQ(g.upstreamOf(added), kDefaultCluster);
    EXPECT_GT(g.node(added).x, g.node(kDefaultCluster).x); // to the right of its input
    // Bake #3 sits right of Cluster #2 already: the new box goes below it, not on it.
    const QRectF box = editor.view()->nodeItem(added)->sceneBoundingRect();
    ASSERT_NE(editor.view()->nodeItem(kDefaultBake), nullptr);
    EXPECT_FALSE(box.intersects(editor.view()->nodeItem(kDefaultBake)->sceneBoundingRect()));
    EXPECT_EQ(session.undo()->stack()->undoText(), QStringLiteral("Add Bake #5"));
}

} // namespace
} // namespace hlod::widgets
