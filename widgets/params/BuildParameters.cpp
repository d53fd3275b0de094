// The editor's "Parameters" dock (see BuildParameters.h).
#include "widgets/params/BuildParameters.h"

#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

#include "widgets/StudioModel.h"
#include "widgets/doc/UndoAdapter.h"
#include "widgets/params/ParameterPanel.h"

namespace hlod::widgets {

namespace {

QString kindTitle(NodeKind kind) {
    switch (kind) {
    case NodeKind::Import:
        return BuildParameters::tr("Import (reading the scene)");
    case NodeKind::Cluster:
        return BuildParameters::tr("Clustering");
    case NodeKind::Bake:
        return BuildParameters::tr("Proxies");
    case NodeKind::Export:
        return BuildParameters::tr("Package");
    }
    return {};
}

} // namespace

BuildParameters::BuildParameters(UndoAdapter& undo, StudioModel* model, QWidget* parent)
    : QWidget(parent), undo_(undo), model_(model) {
    panel_ = new ParameterPanel(undo);
    panel_->setObjectName(QStringLiteral("SelectedNodeParameters"));
    box_ = new QGroupBox;
    auto* boxLayout = new QVBoxLayout(box_);
    boxLayout->setContentsMargins(4, 4, 4, 4);
    boxLayout->addWidget(panel_);
    hint_ = new QLabel(tr("Click a node in the Pipeline dock to see and edit its parameters."));
    hint_->setWordWrap(true);
    auto* content = new QWidget;
    auto* column = new QVBoxLayout(content);
    column->addWidget(hint_);
    column->addWidget(box_);
    column->addStretch(1);
    scroll_ = new QScrollArea;
    scroll_->setWidgetResizable(true);
    scroll_->setFrameShape(QFrame::NoFrame);
    scroll_->setWidget(content);

    build_ = new QPushButton(tr("Build HLOD"));
    build_->setToolTip(tr("Run the shown branch (its Cluster and Bake nodes) with these "
                          "parameters"));
    cancel_ = new QPushButton(tr("Cancel"));
    connect(build_, &QPushButton::clicked, model_, &StudioModel::build);
    connect(cancel_, &QPushButton::clicked, model_, &StudioModel::cancelBuild);
    auto* buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(build_);
    buttons->addWidget(cancel_);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(scroll_, 1);
    layout->addLayout(buttons);

    for (auto signal :
         {&StudioModel::sceneChanged, &StudioModel::buildStarted, &StudioModel::runFinished,
          &StudioModel::buildCancelled, &StudioModel::shownBakeChanged})
        connect(model_, signal, this, &BuildParameters::updateButtons);
    connect(model_, &StudioModel::buildFailed, this, &BuildParameters::updateButtons);
    connect(&undo_, &UndoAdapter::documentChanged, this, &BuildParameters::followDocument);
    showNode(kNoNode);
    updateButtons();
}

void BuildParameters::showNode(NodeId node) {
    const PipelineGraph& g = undo_.document().graph();
    shown_ = g.hasNode(node) ? node : kNoNode;
    if (panel_->node() != shown_) panel_->setNode(shown_);
    box_->setVisible(shown_ != kNoNode);
    hint_->setVisible(shown_ == kNoNode);
    updateTitle();
}

void BuildParameters::followDocument() {
    const PipelineGraph& g = undo_.document().graph();
    if (shown_ != kNoNode && !g.hasNode(shown_)) showNode(kNoNode);
    updateTitle(); // a rename
    updateButtons();
}

void BuildParameters::updateTitle() {
    const PipelineGraph& g = undo_.document().graph();
    if (shown_ == kNoNode || !g.hasNode(shown_)) return;
    const GraphNode& n = g.node(shown_);
    box_->setTitle(tr("%1 — %2").arg(QString::fromStdString(describeNode(n)), kindTitle(n.kind)));
}

void BuildParameters::updateButtons() {
    const bool canBuild =
        model_->scene() != nullptr && !model_->building() && model_->shownBake() != kNoNode;
    build_->setEnabled(canBuild);
    cancel_->setEnabled(model_->building());
}

} // namespace hlod::widgets
