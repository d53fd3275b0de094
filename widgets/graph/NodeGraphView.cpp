// Node-graph view over the pipeline graph model (contract in NodeGraphView.h).
#include "widgets/graph/NodeGraphView.h"

#include <QBrush>
#include <QGraphicsEllipseItem>
#include <QGraphicsLineItem>
#include <QGraphicsPathItem>
#include <QGraphicsRectItem>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainterPath>
#include <QPen>

namespace hlod::widgets {

namespace {

constexpr double kPortRadius = 6.0;
constexpr int kNodeIdRole = 0; // QGraphicsItem::data key holding the node id

QColor portColor(PortType t) {
    switch (t) {
    case PortType::Scene:
        return QColor(90, 160, 230);
    case PortType::Clusters:
        return QColor(200, 140, 60);
    case PortType::Hlod:
        return QColor(150, 100, 200);
    }
    return Qt::gray;
}

double boxHeight(NodeKind kind) {
    const auto ports = std::max(inputPorts(kind).size(), outputPorts(kind).size());
    return NodeGraphView::kHeaderHeight + NodeGraphView::kPortSpacing * (double(ports) + 0.5);
}

QString title(const GraphNode& n) {
    QString t = QString::fromLatin1(toString(n.kind));
    t[0] = t[0].toUpper();
    return t + QStringLiteral(" #") + QString::number(n.id);
}

} // namespace

NodeGraphView::NodeGraphView(QWidget* parent) : QGraphicsView(parent) {
    setScene(new QGraphicsScene(this));
    setRenderHint(QPainter::Antialiasing);
    setDragMode(QGraphicsView::NoDrag);
}

QColor NodeGraphView::statusColor(NodeStatus status) {
    switch (status) {
    case NodeStatus::UpToDate:
        return QColor(80, 170, 90);
    case NodeStatus::Pending:
        return QColor(220, 170, 50);
    case NodeStatus::Running:
        return QColor(70, 130, 210);
    case NodeStatus::Failed:
        return QColor(210, 60, 60);
    }
    return Qt::gray;
}

void NodeGraphView::setGraph(const PipelineGraph* graph) {
    graph_ = graph;
    refresh();
}

QGraphicsRectItem* NodeGraphView::nodeItem(NodeId node) const {
    auto it = boxes_.find(node);
    return it == boxes_.end() ? nullptr : it->second;
}

QPointF NodeGraphView::portPosition(NodeId node, bool output, int port) const {
    const GraphNode& n = graph_->node(node);
    const double y = n.y + kHeaderHeight + kPortSpacing * (port + 0.75);
    return {output ? n.x + kNodeWidth : n.x, y};
}

void NodeGraphView::refresh() {
    scene()->clear();
    boxes_.clear();
    headers_.clear();
    rubber_ = nullptr;
    if (!graph_) return;
    for (NodeId id : graph_->nodeIds())
        addNodeItem(graph_->node(id));
    for (const Connection& c : graph_->connections())
        addConnectionItem(c);
    setStatusOnly();
}

void NodeGraphView::addNodeItem(const GraphNode& n) {
    auto* box = scene()->addRect(0, 0, kNodeWidth, boxHeight(n.kind), QPen(QColor(60, 60, 60)),
                                 QBrush(QColor(245, 245, 245)));
    box->setPos(n.x, n.y);
    box->setData(kNodeIdRole, n.id);
    box->setFlag(QGraphicsItem::ItemIsSelectable);
    auto* header = new QGraphicsRectItem(0, 0, kNodeWidth, kHeaderHeight, box);
    header->setPen(Qt::NoPen);
    auto* text = new QGraphicsSimpleTextItem(title(n), header);
    text->setPos(8, 4);
    auto addPorts = [&](const std::vector<Port>& ports, bool output) {
        for (std::size_t i = 0; i < ports.size(); ++i) {
            const double y = kHeaderHeight + kPortSpacing * (double(i) + 0.75);
            const double x = output ? kNodeWidth : 0.0;
            auto* dot = new QGraphicsEllipseItem(x - kPortRadius, y - kPortRadius, 2 * kPortRadius,
                                                 2 * kPortRadius, box);
            dot->setBrush(portColor(ports[i].type));
            dot->setToolTip(QString::fromStdString(ports[i].name));
            auto* label = new QGraphicsSimpleTextItem(QString::fromStdString(ports[i].name), box);
            const double w = label->boundingRect().width();
            label->setPos(output ? x - w - 10 : x + 10, y - 8);
        }
    };
    addPorts(inputPorts(n.kind), false);
    addPorts(outputPorts(n.kind), true);
    boxes_[n.id] = box;
    headers_[n.id] = header;
}

void NodeGraphView::addConnectionItem(const Connection& c) {
    const QPointF a = portPosition(c.from, true, c.fromPort);
    const QPointF b = portPosition(c.to, false, c.toPort);
    QPainterPath path(a);
    const double dx = std::max(40.0, std::abs(b.x() - a.x()) / 2);
    path.cubicTo(a + QPointF(dx, 0), b - QPointF(dx, 0), b);
    const PortType t = outputPorts(graph_->node(c.from).kind)[c.fromPort].type;
    auto* item = scene()->addPath(path, QPen(portColor(t), 2.0));
    item->setZValue(-1);
}

void NodeGraphView::setStatusOnly() {
    if (!graph_) return;
    for (auto& [id, header] : headers_) {
        if (!graph_->hasNode(id)) continue;
        const NodeStatus s = graph_->status(id);
        header->setBrush(statusColor(s));
        const QString tip = s == NodeStatus::Failed ? QString::fromStdString(graph_->error(id))
                                                    : QString::fromLatin1(toString(s));
        boxes_[id]->setToolTip(tip);
    }
}

NodeGraphView::PortHit NodeGraphView::portAt(const QPointF& p) const {
    if (!graph_) return {};
    const double r2 = (kPortRadius + 3) * (kPortRadius + 3);
    for (NodeId id : graph_->nodeIds()) {
        const NodeKind kind = graph_->node(id).kind;
        for (bool output : {false, true}) {
            const auto n = (output ? outputPorts(kind) : inputPorts(kind)).size();
            for (std::size_t i = 0; i < n; ++i) {
                const QPointF d = portPosition(id, output, static_cast<int>(i)) - p;
                if (d.x() * d.x() + d.y() * d.y() <= r2) return {id, output, static_cast<int>(i)};
            }
        }
    }
    return {};
}

NodeId NodeGraphView::nodeAt(const QPointF& p) const {
    for (const auto& [id, box] : boxes_) {
        if (box->sceneBoundingRect().contains(p)) return id;
    }
    return kNoNode;
}

void NodeGraphView::mousePressEvent(QMouseEvent* event) {
    const QPointF p = mapToScene(event->position().toPoint());
    if (event->button() == Qt::LeftButton) {
        if (const PortHit hit = portAt(p); hit.node != kNoNode && hit.output) {
            dragFrom_ = hit;
            rubber_ = scene()->addLine(QLineF(p, p), QPen(Qt::darkGray, 1.5, Qt::DashLine));
            return;
        }
        if (const NodeId id = nodeAt(p); id != kNoNode) {
            scene()->clearSelection();
            boxes_[id]->setSelected(true);
            movingNode_ = id;
            moveStart_ = p;
            Q_EMIT nodeSelected(id);
            return;
        }
    }
    QGraphicsView::mousePressEvent(event);
}

void NodeGraphView::mouseMoveEvent(QMouseEvent* event) {
    const QPointF p = mapToScene(event->position().toPoint());
    if (rubber_) {
        rubber_->setLine(QLineF(rubber_->line().p1(), p));
        return;
    }
    if (movingNode_ != kNoNode) {
        const GraphNode& n = graph_->node(movingNode_);
        boxes_[movingNode_]->setPos(QPointF(n.x, n.y) + (p - moveStart_));
        return;
    }
    QGraphicsView::mouseMoveEvent(event);
}

void NodeGraphView::mouseReleaseEvent(QMouseEvent* event) {
    const QPointF p = mapToScene(event->position().toPoint());
    if (rubber_) {
        delete rubber_;
        rubber_ = nullptr;
        const PortHit to = portAt(p);
        if (to.node != kNoNode && !to.output)
            Q_EMIT connectRequested(Connection{dragFrom_.node, dragFrom_.port, to.node, to.port});
        dragFrom_ = {};
        return;
    }
    if (movingNode_ != kNoNode) {
        const NodeId id = movingNode_;
        movingNode_ = kNoNode;
        if (p != moveStart_) {
            const QPointF pos = boxes_[id]->pos();
            Q_EMIT nodeMoved(id, pos.x(), pos.y());
        }
        return;
    }
    QGraphicsView::mouseReleaseEvent(event);
}

void NodeGraphView::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Delete || event->key() == Qt::Key_Backspace) {
        for (const auto& [id, box] : boxes_) {
            if (box->isSelected()) {
                Q_EMIT removeRequested(id);
                return;
            }
        }
    }
    QGraphicsView::keyPressEvent(event);
}

} // namespace hlod::widgets
