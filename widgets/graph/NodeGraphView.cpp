// Node-graph view over the pipeline graph model (contract in NodeGraphView.h).
#include "widgets/graph/NodeGraphView.h"

#include <algorithm>
#include <cmath>

#include <QBrush>
#include <QContextMenuEvent>
#include <QFileInfo>
#include <QGraphicsEllipseItem>
#include <QGraphicsLineItem>
#include <QGraphicsPathItem>
#include <QGraphicsRectItem>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QKeyEvent>
#include <QLocale>
#include <QMenu>
#include <QMouseEvent>
#include <QPainterPath>
#include <QPainterPathStroker>
#include <QPen>
#include <QScrollBar>
#include <QStyleOptionGraphicsItem>
#include <QWheelEvent>

namespace hlod::widgets {

namespace {

constexpr double kPortRadius = 7.0;
constexpr double kFirstPort = 15.0; // from the header to the first port's centre
constexpr double kLineHeight = 17.0;
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

int portRows(NodeKind kind) {
    return static_cast<int>(std::max(inputPorts(kind).size(), outputPorts(kind).size()));
}

// Where the two text lines (name, parameters) start below the ports.
double bodyTop(NodeKind kind) {
    return NodeGraphView::kHeaderHeight + kFirstPort +
           NodeGraphView::kPortSpacing * (portRows(kind) - 1) + kPortRadius + 6.0;
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

QString number(double v) { return QLocale().toString(v, 'g', 6); }

// The parameters that tell one node of a kind from another, on one line.
QString summary(const GraphNode& n) {
    const ParamValues& p = n.params;
    switch (n.kind) {
    case NodeKind::Import: {
        if (n.sources.empty()) return NodeGraphView::tr("sample scene");
        const QString first = QFileInfo(QString::fromStdString(n.sources[0].string())).fileName();
        return n.sources.size() == 1
                   ? first
                   : NodeGraphView::tr("%1 + %2 more").arg(first).arg(n.sources.size() - 1);
    }
    case NodeKind::Cluster: {
        const QString volume = QString::fromStdString(paramText(p, "volume"));
        const QString k = volume == QLatin1String("aabb")
                              ? QStringLiteral(" k=%1").arg(number(paramNumber(p, "k")))
                              : QString();
        return NodeGraphView::tr("%1%2, ≤ %3 children")
            .arg(volume, k)
            .arg(paramInt(p, "max_children"));
    }
    case NodeKind::Bake:
        return NodeGraphView::tr("S %1 px, %2")
            .arg(number(paramNumber(p, "screen_size")),
                 QString::fromStdString(paramText(p, "proxy")));
    case NodeKind::Export: {
        const QString out = QString::fromStdString(paramText(p, "output"));
        return out.isEmpty() ? NodeGraphView::tr("no output folder")
                             : NodeGraphView::tr("to %1").arg(QFileInfo(out).fileName());
    }
    }
    return {};
}

// A node's box: the selection is shown by its outline (setStatusOnly), not by the style's dashed
// frame, which would hide the outline of the shown node.
class NodeBox : public QGraphicsRectItem {
public:
    using QGraphicsRectItem::QGraphicsRectItem;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option,
               QWidget* widget) override {
        QStyleOptionGraphicsItem plain(*option);
        plain.state &= ~QStyle::State_Selected;
        QGraphicsRectItem::paint(painter, &plain, widget);
    }
};

} // namespace

NodeGraphView::NodeGraphView(QWidget* parent) : QGraphicsView(parent) {
    setScene(new QGraphicsScene(this));
    setRenderHint(QPainter::Antialiasing);
    setRenderHint(QPainter::TextAntialiasing);
    setDragMode(QGraphicsView::NoDrag);
    setBackgroundBrush(QColor(228, 230, 234));
    setAlignment(Qt::AlignLeft | Qt::AlignTop);
    setTransformationAnchor(QGraphicsView::AnchorUnderMouse);
    setFocusPolicy(Qt::StrongFocus);
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

QSizeF NodeGraphView::boxSize(NodeKind kind) {
    return {kNodeWidth, bodyTop(kind) + 2.0 * kLineHeight + 6.0};
}

void NodeGraphView::setGraph(const PipelineGraph* graph) {
    graph_ = graph;
    refresh();
    fitGraph();
}

QGraphicsRectItem* NodeGraphView::nodeItem(NodeId node) const {
    auto it = items_.find(node);
    return it == items_.end() ? nullptr : it->second.box;
}

QString NodeGraphView::titleOf(NodeId node) const {
    return graph_ && graph_->hasNode(node) ? title(graph_->node(node)) : QString();
}

QString NodeGraphView::summaryOf(NodeId node) const {
    return graph_ && graph_->hasNode(node) ? summary(graph_->node(node)) : QString();
}

QPointF NodeGraphView::portPosition(NodeId node, bool output, int port) const {
    const GraphNode& n = graph_->node(node);
    const double y = n.y + kHeaderHeight + kFirstPort + kPortSpacing * port;
    return {output ? n.x + kNodeWidth : n.x, y};
}

void NodeGraphView::refresh() {
    scene()->clear();
    items_.clear();
    curves_.clear();
    rubber_ = nullptr;
    movingNode_ = kNoNode;
    if (!graph_) return;
    for (NodeId id : graph_->nodeIds())
        addNodeItem(graph_->node(id));
    for (const Connection& c : graph_->connections())
        addConnectionItem(c);
    if (selected_ != kNoNode && !graph_->hasNode(selected_)) selected_ = kNoNode;
    if (selected_ != kNoNode) items_[selected_].box->setSelected(true);
    setStatusOnly();
    updateSceneRect();
}

void NodeGraphView::updateSceneRect() {
    // Room around the nodes to scroll and drop new ones; never smaller than the viewport, so the
    // nodes stay where they are on screen when one is added.
    QRectF rect = scene()->itemsBoundingRect().adjusted(-40, -40, 40, 40);
    rect = rect.united(sceneRect());
    setSceneRect(rect);
}

void NodeGraphView::setZoom(double scale) {
    scale = std::clamp(scale, kMinScale, kMaxScale);
    setTransform(QTransform::fromScale(scale, scale));
}

void NodeGraphView::fitGraph() {
    if (items_.empty()) return;
    const QRectF rect = scene()->itemsBoundingRect().adjusted(-12, -12, 12, 12);
    setSceneRect(rect);
    const QSize room = viewport()->size();
    const double fit = std::min(room.width() / rect.width(), room.height() / rect.height());
    setZoom(std::min(1.0, fit));
    centerOn(rect.center());
}

void NodeGraphView::selectNode(NodeId node) {
    selected_ = items_.count(node) ? node : kNoNode;
    scene()->clearSelection();
    if (selected_ != kNoNode) items_[selected_].box->setSelected(true);
    setStatusOnly();
}

void NodeGraphView::setShownNode(NodeId node) {
    if (node == shown_) return;
    shown_ = node;
    setStatusOnly();
}

NodeStatus NodeGraphView::shownStatus(NodeId node) const {
    return graph_ && graph_->hasNode(node) ? graph_->status(node) : NodeStatus::Pending;
}

void NodeGraphView::setProgress(NodeId node, double fraction, const QString& text) {
    progress_[node] = {fraction, text};
    setStatusOnly();
}

void NodeGraphView::clearProgress() {
    progress_.clear();
    setStatusOnly();
}

Connection NodeGraphView::connectionAt(const QPointF& p) const {
    QPainterPathStroker stroker;
    stroker.setWidth(10.0);
    for (const auto& [c, item] : curves_)
        if (stroker.createStroke(item->path()).contains(p)) return c;
    return {};
}

void NodeGraphView::addNodeItem(const GraphNode& n) {
    const QSizeF size = boxSize(n.kind);
    auto* box = new NodeBox(0, 0, size.width(), size.height());
    box->setPen(QPen(QColor(60, 60, 60)));
    box->setBrush(QColor(248, 248, 248));
    scene()->addItem(box);
    box->setPos(n.x, n.y);
    box->setData(kNodeIdRole, n.id);
    box->setFlag(QGraphicsItem::ItemIsSelectable);
    auto* header = new QGraphicsRectItem(0, 0, kNodeWidth, kHeaderHeight, box);
    header->setPen(Qt::NoPen);
    auto* bar = new QGraphicsRectItem(0, kHeaderHeight - 4, 0, 4, header);
    bar->setPen(Qt::NoPen);
    bar->setBrush(QColor(255, 255, 255, 200));
    auto* text = new QGraphicsSimpleTextItem(title(n), header);
    text->setBrush(Qt::white);
    QFont bold = font();
    bold.setBold(true);
    text->setFont(bold);
    text->setPos(8, (kHeaderHeight - text->boundingRect().height()) / 2);
    auto* status = new QGraphicsSimpleTextItem(header);
    status->setBrush(QColor(255, 255, 255, 235));
    status->setFont(font());
    auto addPorts = [&](const std::vector<Port>& ports, bool output) {
        for (std::size_t i = 0; i < ports.size(); ++i) {
            const double y = kHeaderHeight + kFirstPort + kPortSpacing * double(i);
            const double x = output ? kNodeWidth : 0.0;
            auto* dot = new QGraphicsEllipseItem(x - kPortRadius, y - kPortRadius, 2 * kPortRadius,
                                                 2 * kPortRadius, box);
            dot->setBrush(portColor(ports[i].type));
            dot->setPen(QPen(QColor(60, 60, 60)));
            dot->setToolTip(QString::fromStdString(ports[i].name));
            auto* label = new QGraphicsSimpleTextItem(QString::fromStdString(ports[i].name), box);
            label->setFont(font());
            label->setBrush(QColor(70, 70, 70));
            const QRectF r = label->boundingRect();
            label->setPos(output ? x - r.width() - 12 : x + 12, y - r.height() / 2);
        }
    };
    addPorts(inputPorts(n.kind), false);
    addPorts(outputPorts(n.kind), true);
    // The name (bold) and the parameters that tell this node from another of its kind.
    QStringList lines;
    if (!n.name.empty()) lines << QString::fromStdString(n.name);
    lines << summary(n);
    double y = bodyTop(n.kind);
    for (int i = 0; i < lines.size(); ++i) {
        auto* line = new QGraphicsSimpleTextItem(lines[i], box);
        QFont f = font();
        f.setBold(i == 0 && !n.name.empty());
        line->setFont(f);
        line->setBrush(QColor(30, 30, 30));
        const QFontMetricsF metrics(f);
        line->setText(metrics.elidedText(lines[i], Qt::ElideRight, kNodeWidth - 16));
        line->setPos(8, y);
        y += kLineHeight;
    }
    items_[n.id] = {box, header, bar, status};
}

void NodeGraphView::addConnectionItem(const Connection& c) {
    const QPointF a = portPosition(c.from, true, c.fromPort);
    const QPointF b = portPosition(c.to, false, c.toPort);
    QPainterPath path(a);
    // Forward wires bend gently; a wire to a node on the left goes out and comes back in wide
    // loops, so it never crosses its own boxes.
    const double dx = b.x() >= a.x() ? std::max(40.0, (b.x() - a.x()) / 2) : 80.0;
    path.cubicTo(a + QPointF(dx, 0), b - QPointF(dx, 0), b);
    const PortType t = outputPorts(graph_->node(c.from).kind)[c.fromPort].type;
    auto* item = scene()->addPath(path, QPen(portColor(t), 2.5));
    item->setZValue(-1);
    curves_.emplace_back(c, item);
}

void NodeGraphView::setStatusOnly() {
    if (!graph_) return;
    const QColor highlight = palette().color(QPalette::Highlight);
    for (auto& [id, it] : items_) {
        if (!graph_->hasNode(id)) continue;
        const NodeStatus s = shownStatus(id);
        it.header->setBrush(statusColor(s));
        // The shown node in the highlight colour, the selected one in black, both thick.
        it.box->setPen(id == shown_      ? QPen(highlight, 3.5)
                       : id == selected_ ? QPen(QColor(20, 20, 20), 2.5)
                                         : QPen(QColor(60, 60, 60), 1.0));
        QString text = statusName(s);
        QString tip = text;
        double fraction = 0.0;
        if (const auto p = progress_.find(id); p != progress_.end() && s == NodeStatus::Running) {
            fraction = std::clamp(p->second.first, 0.0, 1.0);
            if (p->second.first >= 0.0)
                text = tr("running %1%").arg(static_cast<int>(std::floor(fraction * 100.0)));
            if (!p->second.second.isEmpty()) tip = p->second.second;
        }
        if (s == NodeStatus::Failed) tip = QString::fromStdString(graph_->error(id));
        if (s == NodeStatus::UpToDate && graph_->node(id).kind == NodeKind::Export) {
            if (const NodeOutput* out = graph_->output(id); out && out->exported)
                tip = tr("Package written to %1")
                          .arg(QString::fromStdString(out->exported->output.string()));
        }
        if (id == shown_) tip += QLatin1Char('\n') + tr("Shown in the 3D view");
        it.box->setToolTip(tip);
        it.bar->setRect(0, kHeaderHeight - 4, kNodeWidth * fraction, 4);
        it.status->setText(text);
        it.status->setPos(kNodeWidth - it.status->boundingRect().width() - 8,
                          (kHeaderHeight - it.status->boundingRect().height()) / 2);
    }
}

NodeGraphView::PortHit NodeGraphView::portAt(const QPointF& p) const {
    if (!graph_) return {};
    // kPortHitPx screen pixels, whatever the zoom, and never less than the dot itself.
    const double scale = std::max(1e-6, transform().m11());
    const double r = std::max(kPortRadius + 3.0, kPortHitPx / scale);
    PortHit best;
    double bestD2 = r * r;
    for (NodeId id : graph_->nodeIds()) {
        const NodeKind kind = graph_->node(id).kind;
        for (bool output : {false, true}) {
            const auto n = (output ? outputPorts(kind) : inputPorts(kind)).size();
            for (std::size_t i = 0; i < n; ++i) {
                const QPointF d = portPosition(id, output, static_cast<int>(i)) - p;
                const double d2 = d.x() * d.x() + d.y() * d.y();
                if (d2 <= bestD2) {
                    bestD2 = d2;
                    best = {id, output, static_cast<int>(i)};
                }
            }
        }
    }
    return best;
}

NodeId NodeGraphView::nodeAt(const QPointF& p) const {
    for (const auto& [id, it] : items_) {
        if (it.box->sceneBoundingRect().contains(p)) return id;
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
        items_[movingNode_].box->setPos(QPointF(n.x, n.y) + (p - moveStart_));
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
            const QPointF pos = items_[id].box->pos();
            Q_EMIT nodeMoved(id, pos.x(), pos.y());
        }
        return;
    }
    QGraphicsView::mouseReleaseEvent(event);
}

void NodeGraphView::fillNodeMenu(QMenu& menu, NodeId id) {
    const QString name = title(graph_->node(id));
    menu.addAction(tr("D&uplicate %1").arg(name), this,
                   [this, id] { Q_EMIT duplicateRequested(id, false); });
    QAction* branch = menu.addAction(tr("Duplicate &Branch"), this,
                                     [this, id] { Q_EMIT duplicateRequested(id, true); });
    branch->setToolTip(tr("Copy this node and everything downstream of it: a second variant fed "
                          "by the same input"));
    QAction* disconnect =
        menu.addAction(tr("&Disconnect"), this, [this, id] { Q_EMIT disconnectNodeRequested(id); });
    disconnect->setEnabled(!graph_->connectionsOf(id).empty());
    menu.addAction(tr("&Rename…"), this, [this, id] { Q_EMIT renameRequested(id); });
    menu.addSeparator();
    QAction* remove = menu.addAction(tr("&Remove %1").arg(name), this,
                                     [this, id] { Q_EMIT removeRequested(id); });
    remove->setShortcut(QKeySequence::Delete);
}

void NodeGraphView::contextMenuEvent(QContextMenuEvent* event) {
    if (!graph_) return;
    const QPointF p = mapToScene(event->pos());
    QMenu menu(this);
    menu.setObjectName(QStringLiteral("NodeGraphMenu"));
    if (const NodeId id = nodeAt(p); id != kNoNode) {
        selectNode(id);
        Q_EMIT nodeSelected(id);
        fillNodeMenu(menu, id);
    } else if (const Connection c = connectionAt(p); c.from != kNoNode) {
        menu.addAction(tr("&Disconnect"), this, [this, c] { Q_EMIT disconnectRequested(c); });
    } else {
        for (NodeKind kind :
             {NodeKind::Import, NodeKind::Cluster, NodeKind::Bake, NodeKind::Export})
            menu.addAction(tr("Add %1 Node").arg(kindName(kind)), this, [this, kind, p] {
                Q_EMIT addRequested(static_cast<int>(kind), p.x(), p.y());
            });
        menu.addSeparator();
        menu.addAction(tr("&Fit View"), this, &NodeGraphView::fitGraph)
            ->setShortcut(QKeySequence(Qt::Key_F));
    }
    menu.exec(event->globalPos());
}

bool NodeGraphView::event(QEvent* event) {
    if (event->type() == QEvent::ShortcutOverride) {
        auto* key = static_cast<QKeyEvent*>(event);
        const bool own = key->modifiers() == Qt::NoModifier &&
                         (key->key() == Qt::Key_F || key->key() == Qt::Key_Delete ||
                          key->key() == Qt::Key_Backspace);
        if (own) {
            event->accept();
            return true;
        }
    }
    return QGraphicsView::event(event);
}

void NodeGraphView::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Delete || event->key() == Qt::Key_Backspace) {
        if (selected_ != kNoNode) {
            Q_EMIT removeRequested(selected_);
            return;
        }
    }
    if (event->key() == Qt::Key_F && event->modifiers() == Qt::NoModifier) {
        fitGraph();
        return;
    }
    QGraphicsView::keyPressEvent(event);
}

void NodeGraphView::wheelEvent(QWheelEvent* event) {
    if (event->modifiers() & Qt::ControlModifier) {
        const double steps = event->angleDelta().y() / 120.0;
        setZoom(transform().m11() * std::pow(1.15, steps));
        return;
    }
    QGraphicsView::wheelEvent(event);
}

} // namespace hlod::widgets
