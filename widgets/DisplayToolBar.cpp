// The display toolbar (see DisplayToolBar.h).
#include "widgets/DisplayToolBar.h"

#include <QAction>
#include <QActionGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QSlider>

#include "widgets/StudioModel.h"

namespace hlod::widgets {

DisplayToolBar::DisplayToolBar(StudioModel* model, QWidget* parent)
    : QToolBar(tr("Display"), parent), model_(model) {
    setObjectName(QStringLiteral("DisplayToolBar"));
    modes_ = new QActionGroup(this);
    auto mode = [this](const QString& text, const QString& key, const QString& tip, DisplayMode m) {
        QAction* action = addAction(text);
        action->setCheckable(true);
        action->setShortcut(QKeySequence(key));
        action->setStatusTip(tip);
        action->setToolTip(QStringLiteral("%1 (%2)").arg(tip, key));
        modes_->addAction(action);
        connect(action, &QAction::triggered, this, [this, m] { model_->setMode(m); });
        return action;
    };
    original_ = mode(tr("Original"), QStringLiteral("1"), tr("Show the original scene"),
                     DisplayMode::Original);
    clustersTip_ = tr("Colour the meshes by their cluster at the chosen level");
    clusters_ = mode(tr("Clusters"), QStringLiteral("2"), clustersTip_, DisplayMode::Clusters);
    hlodTip_ = tr("Draw what an engine draws for this camera: proxies and leaves");
    hlod_ = mode(tr("HLOD preview"), QStringLiteral("3"), hlodTip_, DisplayMode::Hlod);
    addSeparator();
    addWidget(new QLabel(tr(" Level "), this));
    level_ = new QSlider(Qt::Horizontal, this);
    level_->setMaximumWidth(140);
    level_->setPageStep(1);
    level_->setToolTip(tr("Cluster level shown in Clusters mode (0 = single meshes)"));
    addWidget(level_);
    levelLabel_ = new QLabel(this);
    levelLabel_->setMinimumWidth(28);
    addWidget(levelLabel_);
    bounds_ = new QComboBox(this);
    bounds_->addItem(tr("No bounds"), static_cast<int>(BoundsShape::None));
    bounds_->addItem(tr("Spheres"), static_cast<int>(BoundsShape::Spheres));
    bounds_->addItem(tr("Boxes"), static_cast<int>(BoundsShape::Boxes));
    bounds_->setToolTip(tr("Bounding volumes drawn as wireframes in Clusters mode"));
    addWidget(bounds_);
    selectionOnly_ = new QCheckBox(tr("Selected only"), this);
    selectionOnly_->setToolTip(tr("Draw the bounds of the selected cluster's subtree only"));
    addWidget(selectionOnly_);
    addSeparator();
    tint_ = new QCheckBox(tr("Tint by depth"), this);
    tint_->setToolTip(tr("HLOD preview: colour every drawn node by its depth in the tree"));
    addWidget(tint_);

    connect(level_, &QSlider::valueChanged, this, [this](int v) {
        if (!loading_) model_->setLevel(v);
    });
    connect(bounds_, &QComboBox::currentIndexChanged, this, [this] {
        if (!loading_) model_->setBounds(static_cast<BoundsShape>(bounds_->currentData().toInt()));
    });
    connect(selectionOnly_, &QCheckBox::toggled, this, [this](bool on) {
        if (!loading_) model_->setBoundsOfSelectionOnly(on);
    });
    connect(tint_, &QCheckBox::toggled, this, [this](bool on) {
        if (!loading_) model_->setTintByDepth(on);
    });
    for (auto signal :
         {&StudioModel::viewChanged, &StudioModel::buildFinished, &StudioModel::sceneChanged})
        connect(model_, signal, this, &DisplayToolBar::load);
    load();
}

void DisplayToolBar::load() {
    loading_ = true;
    const ViewOptions& v = model_->view();
    const bool built = model_->hasBuild();
    clusters_->setEnabled(built);
    hlod_->setEnabled(built);
    // Greyed modes say why (issue 31 #4): they show a build.
    const QString needsBuild = model_->scene()
                                   ? tr("Build the HLOD first (Build ▸ Build HLOD, Ctrl+B)")
                                   : tr("Open a scene and build its HLOD first");
    clusters_->setToolTip(built ? tr("%1 (2)").arg(clustersTip_)
                                : tr("%1 (2). %2").arg(clustersTip_, needsBuild));
    hlod_->setToolTip(built ? tr("%1 (3)").arg(hlodTip_)
                            : tr("%1 (3). %2").arg(hlodTip_, needsBuild));
    (v.mode == DisplayMode::Clusters ? clusters_
     : v.mode == DisplayMode::Hlod   ? hlod_
                                     : original_)
        ->setChecked(true);
    level_->setRange(0, model_->maxLevel());
    level_->setValue(v.level);
    level_->setEnabled(built);
    levelLabel_->setText(built ? QString::number(v.level) : QString());
    bounds_->setCurrentIndex(bounds_->findData(static_cast<int>(v.bounds)));
    bounds_->setEnabled(built);
    selectionOnly_->setChecked(v.boundsOfSelectionOnly);
    selectionOnly_->setEnabled(built);
    tint_->setChecked(v.tintByDepth);
    tint_->setEnabled(built);
    loading_ = false;
}

} // namespace hlod::widgets
