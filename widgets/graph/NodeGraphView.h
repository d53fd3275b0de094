// The node-graph editor (issue #7, issue 29): a QGraphicsView over the pipeline graph model
// (pipeline/graph/PipelineGraph.h), after QtNodes' look: one box per node titled with its kind
// and id ("Bake #6"), its name and a line of its main parameters below, input ports on the left,
// output ports on the right (named, coloured by port type), a curve per connection, and the
// box's header coloured by the node's run status, as the graph holds it (the editor's runs bring
// their statuses into the graph, widgets/GraphRunner.h):
//   up to date = green, pending = amber, running = blue (with the step's progress), failed = red
//   (tooltip: the error).
// The Bake node the viewport shows (setShownNode) has a thick outline in the highlight colour.
//
// The view holds no pipeline state: refresh() redraws from the graph, and user gestures become
// requests the owner turns into document commands (UndoAdapter), then calls refresh():
//   - click a node                      -> nodeSelected(id)
//   - drag a node and release           -> nodeMoved(id, x, y)  (MoveNode command)
//   - drag from an output port, release
//     over an input port                -> connectRequested(connection)
//   - select a node, press Delete       -> removeRequested(id)
//   - context menu on a node            -> duplicateRequested(id, false), duplicateRequested(id,
//                                          true) (Duplicate Branch), disconnectNodeRequested(id),
//                                          removeRequested(id), renameRequested(id)
//   - context menu on a connection      -> disconnectRequested(connection)
//   - context menu on the background    -> addRequested(kind, x, y) (at the click)
// Zoom: the view never re-zooms by itself (adding a node leaves it as it is). fitGraph() (key F)
// shows the whole graph, at most at 1:1 and never below kMinScale, so labels stay readable
// however many nodes there are (the view scrolls instead); Ctrl+wheel zooms within the same
// bounds. Ports take a click within kPortHitPx screen pixels of their centre at any zoom.
// setStatusOnly() updates colours and progress without rebuilding (call it on the GUI thread).
// The selected node stays selected across refresh() while it exists.
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

    // The graph to show (not owned; must outlive the view or be replaced first). Fits the view.
    void setGraph(const PipelineGraph* graph);
    void refresh();
    void setStatusOnly();
    // The status a node's header shows (the graph's).
    NodeStatus shownStatus(NodeId node) const;
    // Progress of a running node's step (fraction in [0, 1], negative: unknown) and its text;
    // cleared by clearProgress() and by a status other than Running.
    void setProgress(NodeId node, double fraction, const QString& text);
    void clearProgress();
    // The Bake node the viewport shows (outlined; kNoNode: none).
    void setShownNode(NodeId node);
    NodeId shownNode() const { return shown_; }

    // Selects `node` (kNoNode: none) without emitting nodeSelected.
    void selectNode(NodeId node);
    NodeId selectedNode() const { return selected_; }
    // The connection whose curve passes within a few pixels of `scenePos` (from == kNoNode
    // when none).
    Connection connectionAt(const QPointF& scenePos) const;
    // Shows the whole graph (see Zoom above).
    void fitGraph();

    // Scene position of a port's centre (tests, tooltips).
    QPointF portPosition(NodeId node, bool output, int port) const;
    // The header colour used for a status.
    static QColor statusColor(NodeStatus status);
    // The box of a node (nullptr when not shown).
    QGraphicsRectItem* nodeItem(NodeId node) const;
    // The header text of a node's box ("Bake #6"), and its name and parameter lines.
    QString titleOf(NodeId node) const;
    QString summaryOf(NodeId node) const;
    // The size of a box of `kind`, in scene units (for placing new nodes).
    static QSizeF boxSize(NodeKind kind);

    static constexpr double kNodeWidth = 190.0;
    static constexpr double kHeaderHeight = 26.0;
    static constexpr double kPortSpacing = 22.0;
    static constexpr double kMinScale = 0.8;
    static constexpr double kMaxScale = 2.0;
    static constexpr double kPortHitPx = 10.0; // radius: a 20 px target at any zoom

Q_SIGNALS:
    // Node ids travel as quint32 (= hlod::NodeId) so queued connections need no registration.
    void nodeSelected(quint32 node);
    void nodeMoved(quint32 node, double x, double y);
    void connectRequested(const hlod::Connection& connection);
    void removeRequested(quint32 node);
    void disconnectRequested(const hlod::Connection& connection);
    void disconnectNodeRequested(quint32 node);
    void duplicateRequested(quint32 node, bool branch);
    void renameRequested(quint32 node);
    // `kind` is a hlod::NodeKind value; (x, y) the scene position for the new node.
    void addRequested(int kind, double x, double y);

protected:
    // F and Delete are the view's own keys while it has the focus (the main window's View ▸ Fit
    // View takes F elsewhere).
    bool event(QEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;

private:
    struct PortHit {
        NodeId node = kNoNode;
        bool output = false;
        int port = -1;
    };
    struct NodeItems {
        QGraphicsRectItem* box = nullptr;
        QGraphicsRectItem* header = nullptr;
        QGraphicsRectItem* bar = nullptr; // progress, inside the header
        QGraphicsSimpleTextItem* status = nullptr;
    };
    PortHit portAt(const QPointF& scenePos) const;
    NodeId nodeAt(const QPointF& scenePos) const;
    void addNodeItem(const GraphNode& node);
    void addConnectionItem(const Connection& c);
    void fillNodeMenu(QMenu& menu, NodeId id);
    void setZoom(double scale);
    void updateSceneRect();

    const PipelineGraph* graph_ = nullptr;
    std::map<NodeId, NodeItems> items_;
    std::vector<std::pair<Connection, QGraphicsPathItem*>> curves_;
    std::map<NodeId, std::pair<double, QString>> progress_;
    NodeId selected_ = kNoNode;
    NodeId shown_ = kNoNode;
    PortHit dragFrom_;
    QGraphicsLineItem* rubber_ = nullptr;
    NodeId movingNode_ = kNoNode;
    QPointF moveStart_;
};

} // namespace hlod::widgets

Q_DECLARE_METATYPE(hlod::Connection)
