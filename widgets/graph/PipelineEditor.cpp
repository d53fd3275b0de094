// The Pipeline dock: node graph, edits as commands, statuses of the runs (see PipelineEditor.h).
#include "widgets/graph/PipelineEditor.h"

#include <algorithm>
#include <cmath>

#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QRectF>
#include <QToolButton>
#include <QVBoxLayout>

#include "pipeline/doc/Commands.h"
#include "widgets/StudioModel.h"
#include "widgets/doc/ProjectSession.h"
#include "widgets/graph/NodeGraphView.h"

namespace hlod::widgets {

namespace {

constexpr double kGap = 30.0;  // between boxes, both ways
constexpr double kSnap = 10.0; // positions are kept on a 10-unit grid

double snap(double v) { return std::round(v / kSnap) * kSnap; }

QRectF boxAt(NodeKind kind, QPointF topLeft) { return {topLeft, NodeGraphView::boxSize(kind)}; }

// Whether a box of `kind` at `topLeft` keeps kGap from every node of `g` but `ignore`.
bool isFree(const PipelineGraph& g, NodeKind kind, QPointF topLeft,
            const std::vector<NodeId>& ignore = {}) {
    const QRectF box = boxAt(kind, topLeft).adjusted(-kGap / 2, -kGap / 2, kGap / 2, kGap / 2);
    for (NodeId id : g.nodeIds()) {
        if (std::find(ignore.begin(), ignore.end(), id) != ignore.end()) continue;
        const GraphNode& n = g.node(id);
        if (box.intersects(
                boxAt(n.kind, {n.x, n.y}).adjusted(-kGap / 2, -kGap / 2, kGap / 2, kGap / 2)))
            return false;
    }
    return true;
}

} // namespace

PipelineEditor::PipelineEditor(ProjectSession* session, StudioModel* model, QWidget* parent)
    : QWidget(parent), session_(session), model_(model) {
    view_ = new NodeGraphView(this);
    view_->setObjectName(QStringLiteral("PipelineGraph"));
    view_->setGraph(&session_->document().graph());

    add_ = new QToolButton(this);
    add_->setText(tr("Add Node"));
    add_->setToolTip(tr("Add a node: after the selected node when it can take its output"));
    add_->setPopupMode(QToolButton::InstantPopup);
    auto* menu = new QMenu(add_);
    const std::pair<NodeKind, QString> kinds[] = {{NodeKind::Import, tr("Import")},
                                                  {NodeKind::Cluster, tr("Cluster")},
                                                  {NodeKind::Bake, tr("Bake")},
                                                  {NodeKind::Export, tr("Export")}};
    for (const auto& [kind, name] : kinds)
        menu->addAction(name, this, [this, kind] { addFromButton(kind); });
    add_->setMenu(menu);
    fit_ = new QToolButton(this);
    fit_->setText(tr("Fit"));
    fit_->setToolTip(tr("Show the whole graph (F)"));
    connect(fit_, &QToolButton::clicked, view_, &NodeGraphView::fitGraph);
    auto* help = new QLabel(tr("Click: parameters (a Bake node: shown) · drag output to input: "
                               "connect · right-click: duplicate branch, rename, remove · F: fit"),
                            this);
    help->setWordWrap(true);
    QPalette dimmed = help->palette(); // a hint, quieter than the graph
    dimmed.setColor(QPalette::WindowText, dimmed.color(QPalette::Disabled, QPalette::WindowText));
    help->setPalette(dimmed);
    auto* top = new QHBoxLayout;
    top->setContentsMargins(4, 2, 4, 0);
    top->addWidget(add_);
    top->addWidget(fit_);
    top->addWidget(help, 1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addLayout(top);
    layout->addWidget(view_, 1);

    connect(view_, &NodeGraphView::nodeSelected, this, &PipelineEditor::onNodeSelected);
    connect(view_, &NodeGraphView::nodeMoved, this,
            [this](quint32 node, double x, double y) { moveNode(node, x, y); });
    connect(view_, &NodeGraphView::connectRequested, this, &PipelineEditor::connectNodes);
    connect(view_, &NodeGraphView::disconnectRequested, this, &PipelineEditor::disconnectNodes);
    connect(view_, &NodeGraphView::disconnectNodeRequested, this,
            [this](quint32 node) { disconnectNode(node); });
    connect(view_, &NodeGraphView::removeRequested, this,
            [this](quint32 node) { removeNode(node); });
    connect(view_, &NodeGraphView::duplicateRequested, this,
            [this](quint32 node, bool branch) { duplicate(node, branch); });
    connect(view_, &NodeGraphView::renameRequested, this,
            [this](quint32 node) { askRename(node); });
    connect(view_, &NodeGraphView::addRequested, this, [this](int kind, double x, double y) {
        // The click is the middle of the new box's header.
        addNode(static_cast<NodeKind>(kind), x - NodeGraphView::kNodeWidth / 2,
                y - NodeGraphView::kHeaderHeight / 2);
    });

    connect(session_, &ProjectSession::documentChanged, this, &PipelineEditor::onDocumentChanged);
    connect(session_, &ProjectSession::projectChanged, view_, &NodeGraphView::fitGraph);
    connect(model_, &StudioModel::shownBakeChanged, this,
            [this] { view_->setShownNode(model_->shownBake()); });
    connect(model_, &StudioModel::nodeStatusChanged, view_, &NodeGraphView::setStatusOnly);
    connect(model_, &StudioModel::nodeProgress, this,
            [this](quint32 node, const QString& stage, qint64 done, qint64 total) {
                const double fraction = total > 0 ? double(done) / double(total) : -1.0;
                const QString text =
                    total > 0 ? tr("%1 %2/%3").arg(stage).arg(done).arg(total) : stage;
                view_->setProgress(node, fraction, text);
            });
    for (auto signal :
         {&StudioModel::runFinished, &StudioModel::buildCancelled, &StudioModel::sceneChanged})
        connect(model_, signal, view_, &NodeGraphView::clearProgress);
    connect(model_, &StudioModel::buildFailed, view_, &NodeGraphView::clearProgress);
    view_->setShownNode(model_->shownBake());
}

void PipelineEditor::onDocumentChanged() { view_->refresh(); }

void PipelineEditor::onNodeSelected(quint32 node) {
    const PipelineGraph& g = session_->document().graph();
    if (g.hasNode(node) && g.node(node).kind == NodeKind::Bake) model_->setShownBake(node);
    Q_EMIT nodeSelected(node);
}

QPointF PipelineEditor::freeSpot(NodeKind kind, QPointF wanted) const {
    const PipelineGraph& g = session_->document().graph();
    const QPointF start(snap(wanted.x()), snap(wanted.y()));
    const double down = NodeGraphView::boxSize(kind).height() / 2;
    for (int column = 0; column < 20; ++column) {
        for (int row = 0; row < 40; ++row) {
            const QPointF p =
                start + QPointF(column * (NodeGraphView::kNodeWidth + kGap), snap(row * down));
            if (isFree(g, kind, p)) return p;
        }
    }
    return start;
}

void PipelineEditor::addFromButton(NodeKind kind) {
    const PipelineGraph& g = session_->document().graph();
    const NodeId selected = view_->selectedNode();
    if (selected != kNoNode && g.hasNode(selected)) {
        const auto& outs = outputPorts(g.node(selected).kind);
        const auto& ins = inputPorts(kind);
        if (!outs.empty() && !ins.empty() && outs[0].type == ins[0].type) {
            addAfter(kind, selected);
            return;
        }
    }
    // Below the graph, at its left edge.
    double x = 0.0, y = 0.0;
    bool any = false;
    for (NodeId id : g.nodeIds()) {
        const GraphNode& n = g.node(id);
        x = any ? std::min(x, n.x) : n.x;
        y = any ? std::max(y, n.y + NodeGraphView::boxSize(n.kind).height() + kGap) : n.y;
        any = true;
    }
    addNode(kind, x, y);
}

bool PipelineEditor::addNode(NodeKind kind, double x, double y) {
    const QPointF at = freeSpot(kind, {x, y});
    return session_->undo()->execute(std::make_unique<AddNode>(kind, at.x(), at.y()));
}

bool PipelineEditor::addAfter(NodeKind kind, NodeId input) {
    const PipelineGraph& g = session_->document().graph();
    if (!g.hasNode(input)) return false;
    const GraphNode& in = g.node(input);
    const QPointF at = freeSpot(kind, {in.x + NodeGraphView::kNodeWidth + kGap, in.y});
    return session_->undo()->execute(std::make_unique<AddNode>(kind, at.x(), at.y(), input));
}

bool PipelineEditor::removeNode(NodeId node) {
    return session_->undo()->execute(std::make_unique<RemoveNode>(node));
}

bool PipelineEditor::connectNodes(const Connection& c) {
    return session_->undo()->execute(std::make_unique<ConnectNodes>(c));
}

bool PipelineEditor::disconnectNodes(const Connection& c) {
    return session_->undo()->execute(std::make_unique<DisconnectNodes>(c));
}

bool PipelineEditor::disconnectNode(NodeId node) {
    return session_->undo()->execute(std::make_unique<DisconnectNode>(node));
}

bool PipelineEditor::duplicate(NodeId node, bool branch) {
    const PipelineGraph& g = session_->document().graph();
    if (!g.hasNode(node)) return false;
    const std::vector<NodeId> nodes =
        branch ? DuplicateNodes::branchFrom(g, node) : std::vector<NodeId>{node};
    // The copies keep their layout, moved down by the least step that overlaps nothing.
    double step = 0.0;
    for (NodeId id : nodes)
        step = std::max(step, NodeGraphView::boxSize(g.node(id).kind).height() + kGap);
    std::vector<std::pair<double, double>> positions;
    for (int tries = 0; tries < 100; ++tries, step += kSnap * 2) {
        positions.clear();
        bool free = true;
        for (NodeId id : nodes) {
            const GraphNode& n = g.node(id);
            positions.emplace_back(n.x, snap(n.y + step));
            free = free && isFree(g, n.kind, {positions.back().first, positions.back().second});
        }
        if (free) break;
    }
    return session_->undo()->execute(std::make_unique<DuplicateNodes>(nodes, positions, branch));
}

bool PipelineEditor::renameNode(NodeId node, const QString& name) {
    return session_->undo()->execute(
        std::make_unique<RenameNode>(node, name.trimmed().toStdString()));
}

void PipelineEditor::askRename(NodeId node) {
    const PipelineGraph& g = session_->document().graph();
    if (!g.hasNode(node)) return;
    bool ok = false;
    const QString name = QInputDialog::getText(
        this, tr("Rename Node"),
        tr("Name of %1 (empty for none; hlod build --export NAME picks an Export by it):")
            .arg(view_->titleOf(node)),
        QLineEdit::Normal, QString::fromStdString(g.node(node).name), &ok);
    if (ok && name.trimmed().toStdString() != g.node(node).name) renameNode(node, name);
}

bool PipelineEditor::moveNode(NodeId node, double x, double y) {
    return session_->undo()->execute(std::make_unique<MoveNode>(node, x, y));
}

} // namespace hlod::widgets
