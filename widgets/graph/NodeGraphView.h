// The node-graph editor (issue #7): a QGraphicsView over the pipeline graph model
// (pipeline/graph/PipelineGraph.h), after QtNodes' look: one box per node titled with its kind
// and id, input ports on the left, output ports on the right (named, coloured by port type),
// a curve per connection, and the box's header coloured by the node's run status:
//   up to date = green, pending = amber, running = blue, failed = red (tooltip: the error).
//
// The view holds no pipeline state: refresh() redraws from the graph, and user gestures become
// requests the owner turns into document commands (UndoAdapter), then calls refresh():
//   - click a node                      -> nodeSelected(id)
//   - drag a node and release           -> nodeMoved(id, x, y)  (MoveNode command)
//   - drag from an output port, release
//     over an input port                -> connectRequested(connection)
//   - select a node, press Delete       -> removeRequested(id)
//   - context menu on a node            -> removeRequested(id)
//   - context menu on a connection      -> disconnectRequested(connection)
//   - context menu on the background    -> addRequested(kind, x, y) (at the click)
// setStatusOnly() updates colours without rebuilding (for status changes during a run; call
// it on the GUI thread). setStatuses() shows statuses that do not come from the graph's own run
// state (the editor builds in the background without running the graph: PipelineEditor maps its
// builds onto the nodes); nodes without one show the graph's.
// The selected node stays selected across refresh() while it exists. The view keeps the whole
// graph in sight: after refresh() and resizes it is scaled down to fit (never up beyond 1:1).
#pragma once

#include <map>

#include <QGraphicsView>

#include "pipeline/graph/PipelineGraph.h"

class QGraphicsLineItem;
class QGraphicsPathItem;
class QGraphicsRectItem;
class QGraphicsSimpleTextItem;

namespace hlod::widgets {

class NodeGraphView : public QGraphicsView {
    Q_OBJECT
public:
    explicit NodeGraphView(QWidget* parent = nullptr);

    // The graph to show (not owned; must outlive the view or be replaced first).
    void setGraph(const PipelineGraph* graph);
    void refresh();
    void setStatusOnly();
    // Overrides of the shown status (and a tooltip message, e.g. the error of a failed build).
    void setStatuses(std::map<NodeId, NodeStatus> statuses,
                     std::map<NodeId, QString> messages = {});
    // The status a node's header shows.
    NodeStatus shownStatus(NodeId node) const;

    // Selects `node` (kNoNode: none) without emitting nodeSelected.
    void selectNode(NodeId node);
    NodeId selectedNode() const { return selected_; }
    // The connection whose curve passes within a few pixels of `scenePos` (from == kNoNode
    // when none).
    Connection connectionAt(const QPointF& scenePos) const;

    // Scene position of a port's centre (tests, tooltips).
    QPointF portPosition(NodeId node, bool output, int port) const;
    // The header colour used for a status.
    static QColor statusColor(NodeStatus status);
    // The box of a node (nullptr when not shown).
    QGraphicsRectItem* nodeItem(NodeId node) const;

    static constexpr double kNodeWidth = 160.0;
    static constexpr double kHeaderHeight = 24.0;
    static constexpr double kPortSpacing = 22.0;

Q_SIGNALS:
    // Node ids travel as quint32 (= hlod::NodeId) so queued connections need no registration.
    void nodeSelected(quint32 node);
    void nodeMoved(quint32 node, double x, double y);
    void connectRequested(const hlod::Connection& connection);
    void removeRequested(quint32 node);
    void disconnectRequested(const hlod::Connection& connection);
    // `kind` is a hlod::NodeKind value; (x, y) the scene position for the new node.
    void addRequested(int kind, double x, double y);

protected:
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    struct PortHit {
        NodeId node = kNoNode;
        bool output = false;
        int port = -1;
    };
    PortHit portAt(const QPointF& scenePos) const;
    NodeId nodeAt(const QPointF& scenePos) const;
    void addNodeItem(const GraphNode& node);
    void addConnectionItem(const Connection& c);
    void fitGraph();

    const PipelineGraph* graph_ = nullptr;
    std::map<NodeId, QGraphicsRectItem*> boxes_;
    std::map<NodeId, QGraphicsRectItem*> headers_;
    std::map<NodeId, QGraphicsSimpleTextItem*> statusTexts_;
    std::vector<std::pair<Connection, QGraphicsPathItem*>> curves_;
    std::map<NodeId, NodeStatus> statuses_;
    std::map<NodeId, QString> messages_;
    NodeId selected_ = kNoNode;
    PortHit dragFrom_;
    QGraphicsLineItem* rubber_ = nullptr;
    NodeId movingNode_ = kNoNode;
    QPointF moveStart_;
};

} // namespace hlod::widgets

Q_DECLARE_METATYPE(hlod::Connection)
