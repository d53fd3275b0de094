// The HLOD parameter form (see BuildPanel.h).
#include "widgets/BuildPanel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include "widgets/StudioModel.h"

namespace hlod::widgets {

BuildPanel::BuildPanel(StudioModel* model, QWidget* parent) : QWidget(parent), model_(model) {
    volume_ = new QComboBox(this);
    for (VolumeType v :
         {VolumeType::Sphere, VolumeType::Aabb, VolumeType::Octree, VolumeType::Original})
        volume_->addItem(QString::fromLatin1(toString(v)), static_cast<int>(v));
    volume_->setToolTip(tr("Bounding volume of the clustering: spheres (Sappa & Garcia), AABBs "
                           "with the proportion constraint k, a loose octree, or the scene's "
                           "own hierarchy"));
    k_ = new QDoubleSpinBox(this);
    k_->setRange(0.0, 8.0);
    k_->setSingleStep(0.5);
    k_->setDecimals(1);
    k_->setToolTip(tr("AABB proportion constraint: cost × (max extent / min extent)^k"));
    maxChildren_ = new QSpinBox(this);
    maxChildren_->setRange(2, 64);
    maxChildren_->setToolTip(tr("Most children an inner node may have"));
    proxy_ = new QComboBox(this);
    for (ProxyMethod m : {ProxyMethod::Decimate, ProxyMethod::Remesh, ProxyMethod::Sloppy})
        proxy_->addItem(QString::fromLatin1(toString(m)), static_cast<int>(m));
    proxy_->setToolTip(tr("How inner nodes get their proxies: quadric decimation, voxel "
                          "remesh (watertight shell) or sloppy aggregate"));
    screenSize_ = new QDoubleSpinBox(this);
    screenSize_->setRange(1.0, 100000.0);
    screenSize_->setDecimals(0);
    screenSize_->setSuffix(tr(" px"));
    screenSize_->setToolTip(tr("S: a node is drawn once its bounding sphere projects to at most "
                               "this many pixels"));
    pixelError_ = new QDoubleSpinBox(this);
    pixelError_->setRange(0.01, 1000.0);
    pixelError_->setDecimals(2);
    pixelError_->setSuffix(tr(" px"));
    pixelError_->setToolTip(tr("How far a proxy may deviate on screen at its switch point"));

    auto* form = new QFormLayout;
    form->addRow(tr("Volume"), volume_);
    form->addRow(tr("k"), k_);
    form->addRow(tr("Max children"), maxChildren_);
    form->addRow(tr("Proxy"), proxy_);
    form->addRow(tr("Screen size S"), screenSize_);
    form->addRow(tr("Pixel error"), pixelError_);
    build_ = new QPushButton(tr("Build HLOD"), this);
    cancel_ = new QPushButton(tr("Cancel"), this);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(build_);
    buttons->addWidget(cancel_);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addLayout(buttons);
    layout->addStretch(1);

    load();
    for (QComboBox* box : {volume_, proxy_})
        connect(box, &QComboBox::currentIndexChanged, this, &BuildPanel::store);
    for (QDoubleSpinBox* spin : {k_, screenSize_, pixelError_})
        connect(spin, &QDoubleSpinBox::valueChanged, this, &BuildPanel::store);
    connect(maxChildren_, &QSpinBox::valueChanged, this, &BuildPanel::store);
    connect(model_, &StudioModel::settingsChanged, this, &BuildPanel::load);
    connect(build_, &QPushButton::clicked, model_, &StudioModel::build);
    connect(cancel_, &QPushButton::clicked, model_, &StudioModel::cancelBuild);
    for (auto signal : {&StudioModel::buildStarted, &StudioModel::buildFinished,
                        &StudioModel::buildCancelled, &StudioModel::sceneChanged})
        connect(model_, signal, this, &BuildPanel::updateButtons);
    connect(model_, &StudioModel::buildFailed, this, &BuildPanel::updateButtons);
    updateButtons();
}

void BuildPanel::load() {
    loading_ = true;
    const HlodSettings& s = model_->settings();
    volume_->setCurrentIndex(volume_->findData(static_cast<int>(s.cluster.volume)));
    k_->setValue(s.cluster.k);
    maxChildren_->setValue(s.cluster.maxChildren);
    proxy_->setCurrentIndex(proxy_->findData(static_cast<int>(s.bake.method)));
    screenSize_->setValue(s.bake.screen.screenSize);
    pixelError_->setValue(s.bake.screen.pixelError);
    k_->setEnabled(s.cluster.volume == VolumeType::Aabb);
    loading_ = false;
}

void BuildPanel::store() {
    if (loading_) return;
    HlodSettings s = model_->settings();
    s.cluster.volume = static_cast<VolumeType>(volume_->currentData().toInt());
    s.cluster.k = k_->value();
    s.cluster.maxChildren = maxChildren_->value();
    s.bake.method = static_cast<ProxyMethod>(proxy_->currentData().toInt());
    s.bake.screen.screenSize = screenSize_->value();
    s.bake.screen.pixelError = pixelError_->value();
    model_->setSettings(s);
}

void BuildPanel::updateButtons() {
    build_->setEnabled(model_->scene() != nullptr);
    cancel_->setEnabled(model_->building());
}

} // namespace hlod::widgets
