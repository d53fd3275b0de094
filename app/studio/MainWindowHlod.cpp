// The HLOD parts of the main window (see MainWindow.h): cluster tree tab, Statistics dock, the
// display toolbar with the branch box, the Build menu (the shown branch, all branches), run
// progress with Cancel in the status bar, the two-way selection sync between the trees and the
// viewport (widgets::SelectionSync), and the command line's startup view (--build, --mode,
// --level).
#include "MainWindow.h"

#include <QAction>
#include <QCoreApplication>
#include <QDockWidget>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>
#include <QTreeView>

#include "widgets/BranchBox.h"
#include "widgets/BuildWarnings.h"
#include "widgets/ClusterTreeExpansion.h"
#include "widgets/ClusterTreeModel.h"
#include "widgets/DisplayController.h"
#include "widgets/DisplayToolBar.h"
#include "widgets/LogView.h"
#include "widgets/SceneTreeModel.h"
#include "widgets/SelectionSync.h"
#include "widgets/StatsPanel.h"
#include "widgets/StudioModel.h"
#include "widgets/Viewport.h"
#include "widgets/doc/ProjectSession.h"

using hlod::widgets::StudioModel;

void MainWindow::createHlodDocks() {
    clusterModel_ = new hlod::widgets::ClusterTreeModel(this);
    clusterTree_ = new QTreeView;
    clusterTree_->setModel(clusterModel_);
    clusterTree_->setUniformRowHeights(true);
    clusterTree_->setAlternatingRowColors(true);
    // The name takes what the numbers leave; the numbers are as wide as their contents.
    clusterTree_->header()->setStretchLastSection(false);
    clusterTree_->header()->setMinimumSectionSize(36);
    clusterTree_->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    clusterTree_->header()->setSectionResizeMode(hlod::widgets::ClusterTreeModel::NameColumn,
                                                 QHeaderView::Stretch);
    // Long names keep their end ("… (excluded)") and rows indent less: names stay readable
    // in the dock's default width (issue 31 #10).
    clusterTree_->setTextElideMode(Qt::ElideMiddle);
    clusterTree_->setIndentation(14);
    treeTabs_->addTab(clusterTree_, tr("Clusters"));
    new hlod::widgets::ClusterTreeExpansion(clusterTree_, clusterModel_, this);

    createEditDocks(); // the Parameters ("BuildDock") and History docks
    stats_ = new hlod::widgets::StatsPanel(model_);
    auto* statsDock = new QDockWidget(tr("Statistics"), this);
    statsDock->setObjectName(QStringLiteral("StatsDock"));
    statsDock->setWidget(stats_);
    addDockWidget(Qt::RightDockWidgetArea, statsDock);

    toolBar_ = new hlod::widgets::DisplayToolBar(model_, this);
    addToolBar(Qt::TopToolBarArea, toolBar_);
    toolBar_->addSeparator();
    toolBar_->addWidget(new QLabel(tr("Branch ")));
    toolBar_->addWidget(new hlod::widgets::BranchBox(model_, session_, toolBar_));

    connect(model_, &StudioModel::buildStarted, this, &MainWindow::onBuildStarted);
    connect(model_, &StudioModel::buildProgress, this, &MainWindow::onBuildProgress);
    connect(model_, &StudioModel::buildFinished, this, &MainWindow::onShownBuildChanged);
    connect(model_, &StudioModel::runFinished, this, &MainWindow::onBuildFinished);
    connect(model_, &StudioModel::buildFailed, this, &MainWindow::onBuildFailed);
    connect(model_, &StudioModel::buildCancelled, this, &MainWindow::onBuildCancelled);
    connect(model_, &StudioModel::sceneChanged, this, [this] {
        clusterModel_->setBuild(nullptr, nullptr);
        treeTabs_->setCurrentWidget(tree_);
    });
    new hlod::widgets::SelectionSync(model_, tree_, treeModel_, clusterTree_, clusterModel_, this);
    connect(session_, &hlod::widgets::ProjectSession::documentChanged, this,
            &MainWindow::markExcludedMeshes);
    connect(model_, &StudioModel::shownBakeChanged, this, &MainWindow::markExcludedMeshes);
    if (display_)
        connect(display_, &hlod::widgets::DisplayController::frameStats, stats_,
                &hlod::widgets::StatsPanel::showFrame);
}

void MainWindow::markExcludedMeshes() {
    // The Scene tab marks the meshes the shown branch excludes, as the document says now.
    const hlod::NodeId cluster = model_->shownCluster();
    const hlod::PipelineGraph& g = session_->document().graph();
    treeModel_->setExcluded(treeModel_->scene() && cluster != hlod::kNoNode && g.hasNode(cluster)
                                ? g.node(cluster).edits.excluded
                                : std::vector<hlod::Id>{});
}

void MainWindow::createBuildMenu() {
    QMenu* build = menuBar()->addMenu(tr("&Build"));
    buildAction_ = build->addAction(tr("&Build HLOD"), model_, &StudioModel::build);
    buildAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
    buildAction_->setStatusTip(tr("Run the shown branch (its Cluster and Bake nodes) in the "
                                  "background: only what changed runs"));
    buildAction_->setObjectName(QStringLiteral("actionBuild"));
    buildAllAction_ = build->addAction(tr("Build &All Branches"), model_, &StudioModel::buildAll);
    buildAllAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_B));
    buildAllAction_->setStatusTip(tr("Run every Bake node of the scene in the background"));
    buildAllAction_->setObjectName(QStringLiteral("actionBuildAll"));
    cancelAction_ = build->addAction(tr("&Cancel Build"), model_, &StudioModel::cancelBuild);
    cancelAction_->setEnabled(false);
    // Builds apply to an open scene with a branch to run and no run going on.
    auto updateBuild = [this] {
        const bool idle = model_->scene() && !model_->building();
        buildAction_->setEnabled(idle && model_->shownBake() != hlod::kNoNode);
        buildAllAction_->setEnabled(idle && !model_->bakeNodes().empty());
    };
    for (auto signal :
         {&StudioModel::sceneChanged, &StudioModel::buildStarted, &StudioModel::runFinished,
          &StudioModel::buildCancelled, &StudioModel::shownBakeChanged})
        connect(model_, signal, this, updateBuild);
    connect(session_, &hlod::widgets::ProjectSession::documentChanged, this, updateBuild);
    connect(model_, &StudioModel::buildFailed, this, updateBuild);
    updateBuild();
    build->addSeparator();
    build->addActions(
        {toolBar_->originalAction(), toolBar_->clustersAction(), toolBar_->hlodAction()});
}

void MainWindow::createBuildStatus() {
    buildLabel_ = new QLabel;
    buildBar_ = new QProgressBar;
    buildBar_->setMaximumWidth(180);
    buildBar_->setRange(0, 1000);
    cancelButton_ = new QPushButton(tr("Cancel"));
    connect(cancelButton_, &QPushButton::clicked, model_, &StudioModel::cancelBuild);
    statusBar()->addWidget(buildLabel_);
    statusBar()->addWidget(buildBar_);
    statusBar()->addWidget(cancelButton_);
    hideBuildProgress();
}

void MainWindow::onBuildStarted() {
    buildLabel_->setText(tr("Building HLOD…"));
    buildBar_->setRange(0, 0);
    for (QWidget* w : {static_cast<QWidget*>(buildLabel_), static_cast<QWidget*>(buildBar_),
                       static_cast<QWidget*>(cancelButton_)})
        w->show();
    cancelAction_->setEnabled(true);
    cancelButton_->setToolTip(model_->hasBuild()
                                  ? tr("Stop the running build; the HLOD shown now stays")
                                  : tr("Stop the running build (nothing has been built yet)"));
    QStringList targets;
    for (hlod::NodeId id : model_->runTargets()) {
        const hlod::PipelineGraph& g = session_->document().graph();
        const hlod::NodeKind kind = g.node(id).kind;
        targets << (kind == hlod::NodeKind::Bake
                        ? model_->branchLabel(id)
                        : QString::fromStdString(describeNode(g.node(id))));
    }
    log_->info(tr("Running %1").arg(targets.join(QStringLiteral(", "))));
}

void MainWindow::onBuildProgress(const QString& stage, qint64 done, qint64 total,
                                 const QString& detail) {
    const QString what = stage == QLatin1String("cluster") ? tr("Clustering")
                         : stage == QLatin1String("bake")  ? tr("Baking proxies")
                                                           : stage;
    buildLabel_->setText(total > 0 ? tr("%1 %2/%3").arg(what).arg(done).arg(total) : what);
    buildBar_->setToolTip(detail);
    if (total > 0) {
        buildBar_->setRange(0, 1000);
        buildBar_->setValue(static_cast<int>(1000.0 * double(done) / double(total)));
    } else {
        buildBar_->setRange(0, 0);
    }
}

void MainWindow::onShownBuildChanged() {
    if (!model_->hasBuild()) {
        clusterModel_->setBuild(nullptr, nullptr);
        return;
    }
    const hlod::widgets::BuiltHlod& built = model_->built();
    clusterModel_->setBuild(built.scene, built.build, model_->clusterLabels());
    if (firstBuildOfScene_) {
        // Later builds (edits, parameters, other branches) keep the level and mode the user
        // chose. The first shows what was built: the HLOD preview (issue 31 #4), unless the
        // command line or the project asks for a mode (applyStartupView sets it next).
        clusterTree_->expandToDepth(0);
        model_->setLevel(model_->suggestedLevel());
        if (model_->view().mode == hlod::widgets::DisplayMode::Original &&
            !(startupPending_ && startup_.mode))
            model_->setMode(hlod::widgets::DisplayMode::Hlod);
        firstBuildOfScene_ = false;
    }
}

void MainWindow::onBuildFinished() {
    hideBuildProgress();
    if (model_->hasBuild()) {
        const hlod::widgets::BuiltHlod& built = model_->built();
        const QLocale locale;
        log_->info(
            tr("%1: %2 nodes, height %3, %4 proxy triangles (cluster %5 s, bake %6 s: %7 "
               "baked, %8 reused)")
                .arg(model_->branchLabel(built.bakeNode))
                .arg(built.build->tree->nodes.size())
                .arg(built.build->tree->height())
                .arg(locale.toString(static_cast<qulonglong>(built.build->bake->proxyTriangles)))
                .arg(locale.toString(built.build->clusterSeconds, 'f', 2))
                .arg(locale.toString(built.build->bake->seconds, 'f', 2))
                .arg(built.build->bake->baked)
                .arg(built.build->bake->reused));
        // Visible where one looks after a build, not only at the bottom of Statistics.
        // Once per new warning: every rebuild of the same tree would repeat it.
        const QString warning = hlod::widgets::dissolveWarning(built, model_->clusterLabels());
        if (!warning.isEmpty() && warning != lastWarning_) {
            log_->warning(warning);
            statusBar()->showMessage(warning, 15000);
        }
        lastWarning_ = warning;
    }
    if (startupPending_) applyStartupView();
}

void MainWindow::onBuildFailed(const QString& message) {
    hideBuildProgress();
    log_->error(message);
    if (!screenshotPath_.isEmpty()) {
        exitScreenshotMode(1, message);
        return;
    }
    QMessageBox::warning(this, tr("Could not build the HLOD"), message);
}

void MainWindow::hideBuildProgress() {
    for (QWidget* w : {static_cast<QWidget*>(buildLabel_), static_cast<QWidget*>(buildBar_),
                       static_cast<QWidget*>(cancelButton_)})
        w->hide();
    cancelAction_->setEnabled(false);
}

void MainWindow::onBuildCancelled() {
    hideBuildProgress();
    // Only a build that exists can stay (issue 31 #3).
    log_->warning(model_->hasBuild()
                      ? tr("HLOD build cancelled; the previous result stays")
                      : tr("HLOD build cancelled; nothing has been built yet (Build ▸ Build "
                           "HLOD, Ctrl+B, starts again)"));
    if (!screenshotPath_.isEmpty()) exitScreenshotMode(1, tr("the build was cancelled"));
}

void MainWindow::setStartupView(const StartupView& view) {
    startup_ = view;
    startupPending_ = view.build || view.buildAll || view.mode || view.level || view.tintByDepth;
}

void MainWindow::applyStartupView() {
    if (startup_.buildAll && !model_->bakeNodes().empty()) {
        startup_.buildAll = false; // once: onBuildFinished comes back here
        model_->buildAll();
        return;
    }
    if (startup_.build && !model_->hasBuild() && model_->shownBake() != hlod::kNoNode) {
        model_->build();
        return; // onBuildFinished comes back here
    }
    startupPending_ = false;
    if (startup_.level) model_->setLevel(*startup_.level);
    if (startup_.tintByDepth) model_->setTintByDepth(true);
    hlod::widgets::DisplayMode mode;
    if (startup_.mode && hlod::widgets::displayModeFromString(*startup_.mode, mode))
        model_->setMode(mode);
    applySavedCamera();
    screenshotWhenReady();
}

void MainWindow::screenshotWhenReady() {
    if (!screenshotPath_.isEmpty()) QTimer::singleShot(0, this, [this] { takeScreenshot(100); });
}
