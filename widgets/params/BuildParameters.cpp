// The editor's "Parameters" dock (see BuildParameters.h).
#include "widgets/params/BuildParameters.h"

#include <QGroupBox>
#include <QHBoxLayout>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

#include "widgets/StudioModel.h"
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

} // namespace

BuildParameters::BuildParameters(UndoAdapter& undo, StudioModel* model, QWidget* parent)
    : QWidget(parent), model_(model) {
    cluster_ = new ParameterPanel(undo);
    cluster_->setObjectName(QStringLiteral("ClusterParameters"));
    bake_ = new ParameterPanel(undo);
    bake_->setObjectName(QStringLiteral("BakeParameters"));
    auto* content = new QWidget;
    auto* column = new QVBoxLayout(content);
    column->addWidget(group(tr("Clustering"), cluster_));
    column->addWidget(group(tr("Proxies"), bake_));
    column->addStretch(1);
    auto* scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(content);

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
    layout->addWidget(scroll, 1);
    layout->addLayout(buttons);

    for (auto signal : {&StudioModel::sceneChanged, &StudioModel::buildStarted,
                        &StudioModel::buildFinished, &StudioModel::buildCancelled})
        connect(model_, signal, this, &BuildParameters::updateButtons);
    connect(model_, &StudioModel::buildFailed, this, &BuildParameters::updateButtons);
    updateButtons();
}

void BuildParameters::setNodes(NodeId clusterNode, NodeId bakeNode) {
    cluster_->setNode(clusterNode);
    bake_->setNode(bakeNode);
}

void BuildParameters::updateButtons() {
    build_->setEnabled(model_->scene() != nullptr && !model_->building());
    cancel_->setEnabled(model_->building());
}

} // namespace hlod::widgets
