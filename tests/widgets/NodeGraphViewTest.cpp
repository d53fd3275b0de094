// widgets/graph/NodeGraphView: one box per node with status colours, gestures become requests.
#include <gtest/gtest.h>

#include <QGraphicsRectItem>
#include <QSignalSpy>
#include <QTest>

#include "pipeline/core/Error.h"
#include "widgets/graph/NodeGraphView.h"

namespace hlod::widgets {
namespace {

TEST(NodeGraphView, ShowsEveryNodeWithItsStatusColour) {
    PipelineGraph g = PipelineGraph::makeDefault();
    NodeGraphView view;
    view.setGraph(&g);
    for (NodeId id : g.nodeIds())
        ASSERT_NE(view.nodeItem(id), nullptr) << id;
    // Every node is pending before the first run: the header is amber.
    auto* header = static_cast<QGraphicsRectItem*>(view.nodeItem(2)->childItems().at(0));
    EXPECT_EQ(header->brush().color(), NodeGraphView::statusColor(NodeStatus::Pending));
    g.run({1}); // the embedded sample scene: Import is up to date, the rest pending
    view.setStatusOnly();
    auto* importHeader = static_cast<QGraphicsRectItem*>(view.nodeItem(1)->childItems().at(0));
    EXPECT_EQ(importHeader->brush().color(), NodeGraphView::statusColor(NodeStatus::UpToDate));
    EXPECT_EQ(header->brush().color(), NodeGraphView::statusColor(NodeStatus::Pending));
}

TEST(NodeGraphView, DraggingFromAnOutputToAnInputRequestsAConnection) {
    PipelineGraph g = PipelineGraph::makeDefault();
    const NodeId extra = g.addNode(NodeKind::Cluster, 220.0, 160.0);
    NodeGraphView view;
    view.resize(1000, 500);
    view.setGraph(&g);
    view.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
    QSignalSpy requested(&view, &NodeGraphView::connectRequested);
    QSignalSpy selected(&view, &NodeGraphView::nodeSelected);
    const QPoint from = view.mapFromScene(view.portPosition(1, true, 0));
    const QPoint to = view.mapFromScene(view.portPosition(extra, false, 0));
    QTest::mousePress(view.viewport(), Qt::LeftButton, {}, from);
    QTest::mouseMove(view.viewport(), to);
    QTest::mouseRelease(view.viewport(), Qt::LeftButton, {}, to);
    ASSERT_EQ(requested.count(), 1);
    const auto c = requested.at(0).at(0).value<Connection>();
    EXPECT_EQ(c, (Connection{1, 0, extra, 0}));
    // A click on the box body selects the node.
    QTest::mouseClick(view.viewport(), Qt::LeftButton, {},
                      view.mapFromScene(view.portPosition(extra, false, 0) + QPointF(60, 0)));
    ASSERT_EQ(selected.count(), 1);
    EXPECT_EQ(selected.at(0).at(0).value<quint32>(), extra);
}

TEST(NodeGraphView, StatusesAreTheGraphsWithTheFailureAsTooltip) {
    PipelineGraph g = PipelineGraph::makeDefault();
    g.disconnect({2, 0, 3, 0});
    NodeGraphView view;
    view.setGraph(&g);
    EXPECT_EQ(view.shownStatus(3), NodeStatus::Pending);
    EXPECT_THROW(g.run({3}), Error); // refused: Bake #3 has no Cluster upstream
    view.setStatusOnly();
    EXPECT_EQ(view.shownStatus(3), NodeStatus::Failed);
    auto* header = static_cast<QGraphicsRectItem*>(view.nodeItem(3)->childItems().at(0));
    EXPECT_EQ(header->brush().color(), NodeGraphView::statusColor(NodeStatus::Failed));
    EXPECT_EQ(view.nodeItem(3)->toolTip(), QString::fromStdString(g.error(3)));
    view.refresh(); // redrawing shows the same
    header = static_cast<QGraphicsRectItem*>(view.nodeItem(3)->childItems().at(0));
    EXPECT_EQ(header->brush().color(), NodeGraphView::statusColor(NodeStatus::Failed));
}

TEST(NodeGraphView, LabelsStayReadableAndPortsAreEasyToHitAtAnyZoom) {
    // Six nodes in two branches and a view far too small to show them at 1:1.
    PipelineGraph g = PipelineGraph::makeDefault();
    const NodeId c = g.addNode(NodeKind::Cluster, 230, 160);
    const NodeId b = g.addNode(NodeKind::Bake, 460, 160);
    g.connect({1, 0, c, 0});
    g.connect({c, 0, b, 0});
    NodeGraphView view;
    view.resize(300, 150);
    view.setGraph(&g);
    view.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
    view.fitGraph();
    // Never below kMinScale: the view scrolls instead of shrinking the text.
    EXPECT_GE(view.transform().m11(), NodeGraphView::kMinScale);
    // A click kPortHitPx - 1 screen pixels off a port's centre still grabs it.
    QSignalSpy requested(&view, &NodeGraphView::connectRequested);
    view.centerOn((view.portPosition(c, true, 0) + view.portPosition(b, false, 0)) / 2.0);
    const QPoint from = view.mapFromScene(view.portPosition(c, true, 0)) +
                        QPoint(0, static_cast<int>(NodeGraphView::kPortHitPx) - 1);
    const QPoint to = view.mapFromScene(view.portPosition(b, false, 0));
    QTest::mousePress(view.viewport(), Qt::LeftButton, {}, from);
    QTest::mouseMove(view.viewport(), to);
    QTest::mouseRelease(view.viewport(), Qt::LeftButton, {}, to);
    ASSERT_EQ(requested.count(), 1);
    EXPECT_EQ(requested.at(0).at(0).value<Connection>(), (Connection{c, 0, b, 0}));
    // Each box names its node and its main parameters.
    EXPECT_EQ(view.titleOf(b), QStringLiteral("Bake #%1").arg(b));
    EXPECT_EQ(view.summaryOf(c), QStringLiteral("sphere, ≤ 8 children"));
}

TEST(NodeGraphView, SelectionSurvivesARedrawAndConnectionsAreFoundUnderTheCursor) {
    PipelineGraph g = PipelineGraph::makeDefault();
    NodeGraphView view;
    view.setGraph(&g);
    view.selectNode(3);
    view.refresh();
    EXPECT_EQ(view.selectedNode(), 3u);
    EXPECT_TRUE(view.nodeItem(3)->isSelected());
    // Halfway between Cluster's output and Bake's input lies their connection's curve.
    const QPointF mid = (view.portPosition(2, true, 0) + view.portPosition(3, false, 0)) / 2.0;
    EXPECT_EQ(view.connectionAt(mid), (Connection{2, 0, 3, 0}));
    EXPECT_EQ(view.connectionAt(mid + QPointF(0, 60)).from, kNoNode);
    g.removeNode(3);
    view.refresh();
    EXPECT_EQ(view.selectedNode(), kNoNode); // a removed node is not selected any more
}

} // namespace
} // namespace hlod::widgets
