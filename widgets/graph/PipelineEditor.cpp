// The Pipeline dock: node graph, edits as commands, build statuses (see PipelineEditor.h).
#include "widgets/graph/PipelineEditor.h"

#include <algorithm>

#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QToolButton>
#include <QVBoxLayout>

#include "pipeline/doc/Commands.h"
#include "widgets/StudioModel.h"
#include "widgets/doc/ProjectSession.h"
#include "widgets/graph/NodeGraphView.h"

namespace hlod::widgets {

PipelineEditor::PipelineEditor(ProjectSession* session, StudioModel* model, QWidget* parent)
    : QWidget(parent), session_(session), model_(model) {
    view_ = new NodeGraphView(this);
    view_->setObjectName(QStringLiteral("PipelineGraph"));
    view_->setGraph(&session_->document().graph());

    add_ = new QToolButton(this);
    add_->setText(tr("Add Node"));
    add_->setPopupMode(QToolButton::InstantPopup);
    auto* menu = new QMenu(add_);
    const std::pair<NodeKind, QString> kinds[] = {{NodeKind::Import, tr("Import")},
                                                  {NodeKind::Cluster, tr("Cluster")},
                                                  {NodeKind::Bake, tr("Bake")},
                                                  {NodeKind::Export, tr("Export")}};
    for (const auto& [kind, name] : kinds)
        menu->addAction(name, this, [this, kind] {
            const QPointF at = freeSpot();
            addNode(kind, at.x(), at.y());
        });
    add_->setMenu(menu);
    auto* help = new QLabel(tr("Click a node: its parameters · drag output to input: connect · "
                               "right-click: add, remove, disconnect"),
                            this);
    help->setWordWrap(true);
    QPalette dimmed = help->palette(); // a hint, quieter than the graph
    dimmed.setColor(QPalette::WindowText, dimmed.color(QPalette::Disabled, QPalette::WindowText));
    help->setPalette(dimmed);
    auto* top = new QHBoxLayout;
    top->setContentsMargins(4, 2, 4, 0);
    top->addWidget(add_);
    top->addWidget(help, 1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addLayout(top);
    layout->addWidget(view_, 1);

    connect(view_, &NodeGraphView::nodeSelected, this, &PipelineEditor::nodeSelected);
    connect(view_, &NodeGraphView::nodeMoved, this,
            [this](quint32 node, double x, double y) { moveNode(node, x, y); });
    connect(view_, &NodeGraphView::connectRequested, this, &PipelineEditor::connectNodes);
    connect(view_, &NodeGraphView::disconnectRequested, this, &PipelineEditor::disconnectNodes);
    connect(view_, &NodeGraphView::removeRequested, this,
            [this](quint32 node) { removeNode(node); });
    connect(view_, &NodeGraphView::addRequested, this, [this](int kind, double x, double y) {
        // The click is the middle of the new box's header.
        addNode(static_cast<NodeKind>(kind), x - NodeGraphView::kNodeWidth / 2,
                y - NodeGraphView::kHeaderHeight / 2);
    });

    connect(session_, &ProjectSession::documentChanged, this, &PipelineEditor::onDocumentChanged);
    connect(model_, &StudioModel::sceneChanged, this, &PipelineEditor::updateStatuses);
    connect(model_, &StudioModel::exportChanged, this, &PipelineEditor::updateStatuses);
    connect(model_, &StudioModel::buildStarted, this, [this] {
        // HlodBuilder reuses the shown tree when the clustering settings did not change.
        const bool reuse = model_->hasBuild() &&
                           sameClustering(model_->settings(), model_->built().build->settings);
        stage_ = reuse ? QStringLiteral("bake") : QStringLiteral("cluster");
        failedStage_.clear();
        failedSettings_.reset();
        updateStatuses();
    });
    connect(model_, &StudioModel::buildProgress, this, [this](const QString& stage) {
        if (stage == stage_ || stage.isEmpty()) return;
        stage_ = stage;
        updateStatuses();
    });
    for (auto signal : {&StudioModel::buildFinished, &StudioModel::buildCancelled})
        connect(model_, signal, this, [this] {
            stage_.clear();
            updateStatuses();
        });
    connect(model_, &StudioModel::buildFailed, this, [this](const QString& message) {
        failedStage_ = stage_.isEmpty() ? QStringLiteral("cluster") : stage_;
        failedMessage_ = message;
        failedSettings_ = model_->settings();
        stage_.clear();
        updateStatuses();
    });
    updateStatuses();
}

void PipelineEditor::onDocumentChanged() {
    view_->refresh();
    updateStatuses();
}

void PipelineEditor::updateStatuses() {
    const Document& doc = session_->document();
    const NodeId import = doc.importNode();
    const NodeId cluster = doc.clusterNode();
    const NodeId bake = doc.bakeNode();
    const HlodSettings wanted = session_->settings();
    const HlodSettings* built = model_->hasBuild() ? &model_->built().build->settings : nullptr;
    const bool clusterDone = built && sameClustering(wanted, *built);
    const bool bakeDone = clusterDone && sameBaking(wanted, *built);

    std::map<NodeId, NodeStatus> statuses;
    std::map<NodeId, QString> messages;
    if (import != kNoNode)
        statuses[import] = model_->scene() ? NodeStatus::UpToDate : NodeStatus::Pending;
    auto set = [&](NodeId node, const QString& stage, bool done) {
        if (node == kNoNode) return;
        if (!stage_.isEmpty()) {
            // Clustering runs first: while the bake runs, the tree is done.
            const bool bakeRunning = stage_ == QLatin1String("bake");
            statuses[node] = stage == stage_ ? NodeStatus::Running
                             : stage == QLatin1String("cluster") && bakeRunning
                                 ? NodeStatus::UpToDate
                                 : NodeStatus::Pending;
        } else if (failedSettings_ && failedStage_ == stage &&
                   sameClustering(wanted, *failedSettings_) &&
                   sameBaking(wanted, *failedSettings_)) {
            statuses[node] = NodeStatus::Failed;
            messages[node] = failedMessage_;
        } else {
            statuses[node] = done ? NodeStatus::UpToDate : NodeStatus::Pending;
        }
    };
    set(cluster, QStringLiteral("cluster"), clusterDone);
    set(bake, QStringLiteral("bake"), bakeDone);
    if (const NodeId exp = doc.exportNode(); exp != kNoNode) {
        const ExportState& ex = model_->exportState();
        const bool sameBuild = ex.build && ex.build == model_->built().build && bakeDone;
        if (ex.status == ExportState::Status::Running && sameBuild) {
            statuses[exp] = NodeStatus::Running;
        } else if (ex.status == ExportState::Status::Done && sameBuild) {
            statuses[exp] = NodeStatus::UpToDate;
            messages[exp] = tr("Exported to %1").arg(ex.folder);
        } else if (ex.status == ExportState::Status::Failed && sameBuild) {
            statuses[exp] = NodeStatus::Failed;
            messages[exp] = ex.message;
        } else {
            statuses[exp] = NodeStatus::Pending;
            messages[exp] = ex.status == ExportState::Status::Done
                                ? tr("The package in %1 is older than the HLOD shown: export "
                                     "again (File ▸ Export Package)")
                                      .arg(ex.folder)
                                : tr("Runs on File ▸ Export Package");
        }
    }
    view_->setStatuses(std::move(statuses), std::move(messages));
}

QPointF PipelineEditor::freeSpot() const {
    const PipelineGraph& g = session_->document().graph();
    double x = 0.0, y = 0.0;
    bool any = false;
    for (NodeId id : g.nodeIds()) {
        const GraphNode& n = g.node(id);
        y = any ? std::max(y, n.y) : n.y;
        x = any ? std::min(x, n.x) : n.x;
        any = true;
    }
    return any ? QPointF(x, y + 120.0) : QPointF(0.0, 0.0);
}

bool PipelineEditor::addNode(NodeKind kind, double x, double y) {
    return session_->undo()->execute(std::make_unique<AddNode>(kind, x, y));
}

bool PipelineEditor::removeNode(NodeId node) {
    const PipelineGraph& g = session_->document().graph();
    if (!g.hasNode(node)) return false;
    const NodeKind kind = g.node(node).kind;
    const auto ids = g.nodeIds();
    const auto sameKind =
        std::count_if(ids.begin(), ids.end(), [&](NodeId id) { return g.node(id).kind == kind; });
    if (sameKind < 2) {
        // The editor builds and exports with the first node of each kind.
        Q_EMIT session_->undo()->commandFailed(
            tr("The pipeline needs a %1 node: add another one before removing this one")
                .arg(QString::fromLatin1(toString(kind))));
        return false;
    }
    return session_->undo()->execute(std::make_unique<RemoveNode>(node));
}

bool PipelineEditor::connectNodes(const Connection& c) {
    return session_->undo()->execute(std::make_unique<ConnectNodes>(c));
}

bool PipelineEditor::disconnectNodes(const Connection& c) {
    return session_->undo()->execute(std::make_unique<DisconnectNodes>(c));
}

bool PipelineEditor::moveNode(NodeId node, double x, double y) {
    return session_->undo()->execute(std::make_unique<MoveNode>(node, x, y));
}

} // namespace hlod::widgets
