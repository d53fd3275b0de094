// Node-graph view over the pipeline graph model (contract in NodeGraphView.h).
#include "widgets/graph/NodeGraphView.h"

#include <QBrush>
#include <QContextMenuEvent>
#include <QGraphicsEllipseItem>
#include <QGraphicsLineItem>
#include <QGraphicsPathItem>
#include <QGraphicsRectItem>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QKeyEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QPainterPath>
#include <QPainterPathStroker>
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

QString kindName(NodeKind kind) {
    switch (kind) {
    case NodeKind::Import:
        return NodeGraphView::tr("Import");
    case NodeKind::Cluster:
        return NodeGraphView::tr("Cluster");
    case NodeKind::Bake:
        return NodeGraphView::tr("Bake");
    case NodeKind::Export:
        return NodeGraphView::tr("Export");
    }
    return {};
}

QString title(const GraphNode& n) { return kindName(n.kind) + QStringLiteral(" #%1").arg(n.id); }

QString statusName(NodeStatus s) {
    switch (s) {
    case NodeStatus::UpToDate:
        return NodeGraphView::tr("up to date");
    case NodeStatus::Pending:
        return NodeGraphView::tr("pending");
    case NodeStatus::Running:
        return NodeGraphView::tr("running");
    case NodeStatus::Failed:
        return NodeGraphView::tr("failed");
    }
    return {};
}

} // namespace

NodeGraphView::NodeGraphView(QWidget* parent) : QGraphicsView(parent) {
    setScene(new QGraphicsScene(this));
    setRenderHint(QPainter::Antialiasing);
    setDragMode(QGraphicsView::NoDrag);
    setBackgroundBrush(QColor(228, 230, 234));
    setAlignment(Qt::AlignCenter);
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
    statusTexts_.clear();
    curves_.clear();
    rubber_ = nullptr;
    movingNode_ = kNoNode;
    if (!graph_) return;
    for (NodeId id : graph_->nodeIds())
        addNodeItem(graph_->node(id));
    for (const Connection& c : graph_->connections())
        addConnectionItem(c);
    if (selected_ != kNoNode && !graph_->hasNode(selected_)) selected_ = kNoNode;
    if (selected_ != kNoNode) boxes_[selected_]->setSelected(true);
    setStatusOnly();
    fitGraph();
}

void NodeGraphView::fitGraph() {
    if (boxes_.empty()) return;
    const QRectF rect = scene()->itemsBoundingRect().adjusted(-24, -24, 24, 24);
    setSceneRect(rect);
    resetTransform();
    const QSize room = viewport()->size();
    if (rect.width() > room.width() || rect.height() > room.height())
        fitInView(rect, Qt::KeepAspectRatio);
}

void NodeGraphView::resizeEvent(QResizeEvent* event) {
    QGraphicsView::resizeEvent(event);
    fitGraph();
}

void NodeGraphView::selectNode(NodeId node) {
    selected_ = boxes_.count(node) ? node : kNoNode;
    scene()->clearSelection();
    if (selected_ != kNoNode) boxes_[selected_]->setSelected(true);
}

void NodeGraphView::setStatuses(std::map<NodeId, NodeStatus> statuses,
                                std::map<NodeId, QString> messages) {
    statuses_ = std::move(statuses);
    messages_ = std::move(messages);
    setStatusOnly();
}

NodeStatus NodeGraphView::shownStatus(NodeId node) const {
    if (auto it = statuses_.find(node); it != statuses_.end()) return it->second;
    return graph_ && graph_->hasNode(node) ? graph_->status(node) : NodeStatus::Pending;
}

Connection NodeGraphView::connectionAt(const QPointF& p) const {
    QPainterPathStroker stroker;
    stroker.setWidth(10.0);
    for (const auto& [c, item] : curves_)
        if (stroker.createStroke(item->path()).contains(p)) return c;
    return {};
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
    text->setBrush(Qt::white);
    QFont bold = text->font();
    bold.setBold(true);
    text->setFont(bold);
    text->setPos(8, (kHeaderHeight - text->boundingRect().height()) / 2);
    auto* status = new QGraphicsSimpleTextItem(header);
    status->setBrush(QColor(255, 255, 255, 230));
    statusTexts_[n.id] = status;
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
    curves_.emplace_back(c, item);
}

void NodeGraphView::setStatusOnly() {
    if (!graph_) return;
    for (auto& [id, header] : headers_) {
        if (!graph_->hasNode(id)) continue;
        const NodeStatus s = shownStatus(id);
        header->setBrush(statusColor(s));
        QString tip = statusName(s);
        if (auto it = messages_.find(id); it != messages_.end() && !it->second.isEmpty())
            tip = it->second;
        else if (s == NodeStatus::Failed && !statuses_.count(id))
            tip = QString::fromStdString(graph_->error(id));
        boxes_[id]->setToolTip(tip);
        QGraphicsSimpleTextItem* text = statusTexts_[id];
        text->setText(statusName(s));
        text->setPos(kNodeWidth - text->boundingRect().width() - 8,
                     (kHeaderHeight - text->boundingRect().height()) / 2);
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
            selectNode(id);
            movingNode_ = id;
            moveStart_ = p;
            Q_EMIT nodeSelected(id);
            return;
        }
        selectNode(kNoNode); // a click on the background
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

void NodeGraphView::contextMenuEvent(QContextMenuEvent* event) {
    if (!graph_) return;
    const QPointF p = mapToScene(event->pos());
    QMenu menu(this);
    if (const NodeId id = nodeAt(p); id != kNoNode) {
        selectNode(id);
        Q_EMIT nodeSelected(id);
        menu.addAction(tr("&Remove %1").arg(title(graph_->node(id))), this,
                       [this, id] { Q_EMIT removeRequested(id); });
    } else if (const Connection c = connectionAt(p); c.from != kNoNode) {
        menu.addAction(tr("&Disconnect"), this, [this, c] { Q_EMIT disconnectRequested(c); });
    } else {
        for (NodeKind kind :
             {NodeKind::Import, NodeKind::Cluster, NodeKind::Bake, NodeKind::Export})
            menu.addAction(tr("Add %1 Node").arg(kindName(kind)), this, [this, kind, p] {
                Q_EMIT addRequested(static_cast<int>(kind), p.x(), p.y());
            });
    }
    menu.exec(event->globalPos());
}

void NodeGraphView::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Delete || event->key() == Qt::Key_Backspace) {
        if (selected_ != kNoNode) {
            Q_EMIT removeRequested(selected_);
            return;
        }
    }
    QGraphicsView::keyPressEvent(event);
}

} // namespace hlod::widgets
