// The editor's "Parameters" dock (see BuildParameters.h).
#include "widgets/params/BuildParameters.h"

#include <QGroupBox>
#include <QHBoxLayout>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

#include "widgets/StudioModel.h"
#include "widgets/doc/UndoAdapter.h"
#include "widgets/params/ParameterPanel.h"

namespace hlod::widgets {

namespace {

QGroupBox* group(const QString& title, QWidget* content) {
    auto* box = new QGroupBox(title);
    auto* layout = new QVBoxLayout(box);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(content);
    return box;
}

QString nodeTitle(const PipelineGraph& g, NodeId id) {
    if (id == kNoNode || !g.hasNode(id)) return {};
    QString kind;
    switch (g.node(id).kind) {
    case NodeKind::Import:
        kind = BuildParameters::tr("Import");
        break;
    case NodeKind::Cluster:
        kind = BuildParameters::tr("Cluster");
        break;
    case NodeKind::Bake:
        kind = BuildParameters::tr("Bake");
        break;
    case NodeKind::Export:
        kind = BuildParameters::tr("Export");
        break;
    }
    return QStringLiteral("%1 #%2").arg(kind).arg(id);
}

} // namespace

BuildParameters::BuildParameters(UndoAdapter& undo, StudioModel* model, QWidget* parent)
    : QWidget(parent), undo_(undo), model_(model) {
    cluster_ = new ParameterPanel(undo);
    cluster_->setObjectName(QStringLiteral("ClusterParameters"));
    bake_ = new ParameterPanel(undo);
    bake_->setObjectName(QStringLiteral("BakeParameters"));
    other_ = new ParameterPanel(undo);
    other_->setObjectName(QStringLiteral("SelectedNodeParameters"));
    auto* content = new QWidget;
    auto* column = new QVBoxLayout(content);
    otherBox_ = group({}, other_);
    clusterBox_ = group(tr("Clustering"), cluster_);
    bakeBox_ = group(tr("Proxies"), bake_);
    column->addWidget(otherBox_);
    column->addWidget(clusterBox_);
    column->addWidget(bakeBox_);
    column->addStretch(1);
    otherBox_->hide();
    scroll_ = new QScrollArea;
    scroll_->setWidgetResizable(true);
    scroll_->setFrameShape(QFrame::NoFrame);
    scroll_->setWidget(content);

    build_ = new QPushButton(tr("Build HLOD"));
    build_->setToolTip(tr("Cluster the scene and bake the proxies with these parameters"));
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

    for (auto signal : {&StudioModel::sceneChanged, &StudioModel::buildStarted,
                        &StudioModel::buildFinished, &StudioModel::buildCancelled})
        connect(model_, signal, this, &BuildParameters::updateButtons);
    connect(model_, &StudioModel::buildFailed, this, &BuildParameters::updateButtons);
    connect(&undo_, &UndoAdapter::documentChanged, this, &BuildParameters::followDocument);
    updateButtons();
}

void BuildParameters::setNodes(NodeId clusterNode, NodeId bakeNode) {
    cluster_->setNode(clusterNode);
    bake_->setNode(bakeNode);
    updateGroups();
}

void BuildParameters::showNode(NodeId node) {
    const PipelineGraph& g = undo_.document().graph();
    shown_ = g.hasNode(node) ? node : kNoNode;
    const bool other = shown_ != kNoNode && shown_ != cluster_->node() && shown_ != bake_->node();
    if (other_->node() != (other ? shown_ : kNoNode)) other_->setNode(other ? shown_ : kNoNode);
    updateGroups();
    if (QWidget* box = selectedPanel() ? selectedPanel()->parentWidget() : nullptr)
        scroll_->ensureWidgetVisible(box, 0, 0);
}

ParameterPanel* BuildParameters::selectedPanel() const {
    if (shown_ == kNoNode) return nullptr;
    if (shown_ == cluster_->node()) return cluster_;
    if (shown_ == bake_->node()) return bake_;
    return other_;
}

void BuildParameters::followDocument() {
    const Document& doc = undo_.document();
    if (cluster_->node() != doc.clusterNode()) cluster_->setNode(doc.clusterNode());
    if (bake_->node() != doc.bakeNode()) bake_->setNode(doc.bakeNode());
    showNode(shown_); // the selected node may be gone, or now be the Cluster or Bake node
}

void BuildParameters::updateGroups() {
    const PipelineGraph& g = undo_.document().graph();
    const ParameterPanel* selected = selectedPanel();
    // The selected node's group title is drawn in the highlight colour.
    const QString marked = QStringLiteral("QGroupBox::title { color: palette(highlight); }");
    auto mark = [](QGroupBox* box, const QString& sheet) {
        if (box->styleSheet() != sheet) box->setStyleSheet(sheet); // restyling is not free
    };
    auto title = [&](QGroupBox* box, const QString& what, ParameterPanel* panel) {
        const QString node = nodeTitle(g, panel->node());
        box->setTitle(node.isEmpty() ? what : tr("%1 (%2)").arg(what, node));
        mark(box, panel == selected ? marked : QString());
    };
    title(clusterBox_, tr("Clustering"), cluster_);
    title(bakeBox_, tr("Proxies"), bake_);
    otherBox_->setVisible(selected == other_);
    if (selected == other_) {
        otherBox_->setTitle(nodeTitle(g, shown_));
        mark(otherBox_, marked);
    }
}

void BuildParameters::updateButtons() {
    build_->setEnabled(model_->scene() != nullptr && !model_->building());
    cancel_->setEnabled(model_->building());
}

} // namespace hlod::widgets
