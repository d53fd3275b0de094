// widgets/graph/PipelineEditor (the Pipeline dock) with the Parameters dock: selecting a node
// shows its parameters, a parameter edit there is one undo step and reruns the build (only the
// bake when a bake parameter changed), the node statuses follow the builds, and the graph's
// add / connect / remove requests are undoable commands.
#include <gtest/gtest.h>

#include <QDoubleSpinBox>
#include <QGraphicsRectItem>
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
        Document& doc = session.document();
        QObject::connect(&session, &ProjectSession::documentChanged, &model,
                         &StudioModel::syncSettings);
        params.setNodes(doc.clusterNode(), doc.bakeNode());
        QObject::connect(&editor, &PipelineEditor::nodeSelected, &params,
                         [this](quint32 node) { params.showNode(node); });
        rebuild.setDelay(0);
        editor.resize(900, 260);
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

    ProjectSession session;
    StudioModel model;
    AutoRebuild rebuild{&session, &model};
    BuildParameters params{*session.undo(), &model};
    PipelineEditor editor{&session, &model};
};

TEST_F(PipelineDock, SelectingTheClusterNodeShowsKAndEditingItRebuilds) {
    const Document& doc = session.document();
    EXPECT_EQ(status(doc.importNode()), NodeStatus::UpToDate);
    EXPECT_EQ(status(doc.clusterNode()), NodeStatus::UpToDate);
    EXPECT_EQ(status(doc.bakeNode()), NodeStatus::UpToDate);

    clickNode(doc.clusterNode());
    ASSERT_EQ(params.shownNode(), doc.clusterNode());
    ASSERT_EQ(params.selectedPanel(), params.clusterPanel());
    auto* k = params.selectedPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("param_k"));
    ASSERT_NE(k, nullptr);
    EXPECT_EQ(k->value(), 1.0);

    const std::size_t steps = doc.history().count();
    QSignalSpy scheduled(&rebuild, &AutoRebuild::rebuildScheduled);
    k->setValue(2.0);
    EXPECT_EQ(doc.history().count(), steps + 1); // one undo step
    EXPECT_EQ(session.undo()->stack()->undoText(), QStringLiteral("Set Proportion k"));
    EXPECT_EQ(scheduled.count(), 1);
    EXPECT_EQ(status(doc.clusterNode()), NodeStatus::Pending); // k differs from the build's
    ASSERT_TRUE(waitForBuild());
    EXPECT_EQ(model.built().build->settings.cluster.k, 2.0);
    EXPECT_FALSE(model.built().build->treeReused);
    EXPECT_EQ(status(doc.clusterNode()), NodeStatus::UpToDate);

    session.undo()->stack()->undo();
    EXPECT_EQ(k->value(), 1.0);
    ASSERT_TRUE(waitForBuild()); // undo reruns it too
    EXPECT_EQ(model.built().build->settings.cluster.k, 1.0);
}

TEST_F(PipelineDock, AScreenSizeChangeRerunsOnlyTheBake) {
    const Document& doc = session.document();
    // The builder reuses the tree of its own last build: make one.
    model.build();
    ASSERT_TRUE(waitForBuild());
    EXPECT_FALSE(model.built().build->treeReused);
    clickNode(doc.bakeNode());
    ASSERT_EQ(params.selectedPanel(), params.bakePanel());
    auto* size =
        params.selectedPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("param_screen_size"));
    ASSERT_NE(size, nullptr);
    size->setValue(600.0);
    // Clustering is unchanged: the Cluster node stays up to date, the Bake node waits.
    EXPECT_EQ(status(doc.clusterNode()), NodeStatus::UpToDate);
    EXPECT_EQ(status(doc.bakeNode()), NodeStatus::Pending);
    QSignalSpy started(&model, &StudioModel::buildStarted);
    ASSERT_TRUE(started.wait(5000));
    EXPECT_EQ(status(doc.clusterNode()), NodeStatus::UpToDate);
    EXPECT_EQ(status(doc.bakeNode()), NodeStatus::Running);
    ASSERT_TRUE(waitForBuild());
    EXPECT_TRUE(model.built().build->treeReused);
    EXPECT_EQ(model.built().build->settings.bake.screen.screenSize, 600.0);
    EXPECT_EQ(status(doc.bakeNode()), NodeStatus::UpToDate);
}

TEST_F(PipelineDock, SelectingTheImportNodeShowsItsOwnPanel) {
    const Document& doc = session.document();
    clickNode(doc.importNode());
    ASSERT_EQ(params.selectedPanel(), params.otherPanel());
    EXPECT_EQ(params.otherPanel()->node(), doc.importNode());
    EXPECT_TRUE(params.otherPanel()->isVisibleTo(&params));
}

TEST_F(PipelineDock, GraphEditsAreUndoableCommands) {
    Document& doc = session.document();
    const std::size_t nodes = doc.graph().nodeIds().size();
    ASSERT_TRUE(editor.addNode(NodeKind::Bake, 440.0, 140.0));
    ASSERT_EQ(doc.graph().nodeIds().size(), nodes + 1);
    const NodeId added = doc.graph().nodeIds().back();
    ASSERT_NE(editor.view()->nodeItem(added), nullptr); // the view was redrawn
    EXPECT_EQ(status(added), NodeStatus::Pending);      // the editor does not build it

    const Connection c{doc.clusterNode(), 0, added, 0};
    ASSERT_TRUE(editor.connectNodes(c));
    EXPECT_EQ(doc.graph().upstreamOf(added), doc.clusterNode());
    // A second connection into the same input is refused and changes nothing.
    QSignalSpy failed(session.undo(), &UndoAdapter::commandFailed);
    EXPECT_FALSE(editor.connectNodes({doc.importNode(), 0, added, 0}));
    EXPECT_EQ(failed.count(), 1);
    ASSERT_TRUE(editor.disconnectNodes(c));
    EXPECT_EQ(doc.graph().upstreamOf(added), kNoNode);
    ASSERT_TRUE(editor.removeNode(added));
    EXPECT_EQ(editor.view()->nodeItem(added), nullptr);
    // The last Bake node stays: the editor's builds use it.
    EXPECT_FALSE(editor.removeNode(doc.bakeNode()));
    EXPECT_EQ(failed.count(), 2);

    session.undo()->stack()->undo(); // remove
    session.undo()->stack()->undo(); // disconnect
    EXPECT_EQ(doc.graph().upstreamOf(added), doc.clusterNode());
    session.undo()->stack()->undo(); // connect
    session.undo()->stack()->undo(); // add
    EXPECT_EQ(doc.graph().nodeIds().size(), nodes);
    EXPECT_EQ(editor.view()->nodeItem(added), nullptr);
}

} // namespace
} // namespace hlod::widgets
