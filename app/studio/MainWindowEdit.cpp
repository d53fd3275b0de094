// The editing parts of the main window (see MainWindow.h): the ProjectSession that owns the
// document, the Edit menu (Undo / Redo from the document's history), the History dock
// (QUndoView), the Parameters dock (the ParameterPanel of the node selected in the graph: every
// edit a document command), the Pipeline dock (the node graph of the document: add, remove,
// connect, duplicate branches, rename; the statuses of the runs; a click on a Bake node shows its
// branch), the automatic rerun of the shown branch after edits (AutoRebuild), and the cluster
// hand edits of the Clusters tab and the viewport (Ctrl+click adds to the selection, right click
// opens the edit menu), which act on the shown branch's Cluster node.
#include "MainWindow.h"

#include <algorithm>

#include <QAction>
#include <QDockWidget>
#include <QMenuBar>
#include <QStatusBar>
#include <QTreeView>
#include <QUndoStack>
#include <QUndoView>

#include "widgets/ClusterEditActions.h"
#include "widgets/ClusterTreeModel.h"
#include "widgets/LogView.h"
#include "widgets/StudioModel.h"
#include "widgets/doc/AutoRebuild.h"
#include "widgets/doc/ProjectSession.h"
#include "widgets/graph/NodeGraphView.h"
#include "widgets/graph/PipelineEditor.h"
#include "widgets/params/BuildParameters.h"

using hlod::widgets::ProjectSession;

void MainWindow::createSession() {
    session_ = new ProjectSession(this);
    model_->setGraph(&session_->document().graph());
    connect(session_, &ProjectSession::documentChanged, this, &MainWindow::onDocumentEdited);
    connect(session_, &ProjectSession::dirtyChanged, this, [this] { updateTitle(); });
    connect(session_, &ProjectSession::projectChanged, this, &MainWindow::onDocumentReplaced);
    // Parameter and hand edits (and their undo) rebuild the HLOD once there is one.
    new hlod::widgets::AutoRebuild(session_, model_, this);
}

void MainWindow::createEditDocks() {
    buildParams_ = new hlod::widgets::BuildParameters(*session_->undo(), model_);
    auto* paramsDock = new QDockWidget(tr("Parameters"), this);
    paramsDock->setObjectName(QStringLiteral("BuildDock"));
    paramsDock->setWidget(buildParams_);
    addDockWidget(Qt::RightDockWidgetArea, paramsDock);

    auto* history = new QUndoView(session_->undo()->stack());
    history->setEmptyLabel(tr("<opened>"));
    auto* historyDock = new QDockWidget(tr("History"), this);
    historyDock->setObjectName(QStringLiteral("HistoryDock"));
    historyDock->setWidget(history);
    addDockWidget(Qt::RightDockWidgetArea, historyDock);
    tabifyDockWidget(paramsDock, historyDock);
    paramsDock->raise();

    // The node graph shares the bottom with the log (tabs, the graph in front); the right
    // column (parameters, statistics) keeps the full height of the window.
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    auto* pipeline = new hlod::widgets::PipelineEditor(session_, model_);
    auto* pipelineDock = new QDockWidget(tr("Pipeline"), this);
    pipelineDock->setObjectName(QStringLiteral("PipelineDock"));
    pipelineDock->setWidget(pipeline);
    addDockWidget(Qt::BottomDockWidgetArea, pipelineDock);
    if (auto* logDock = findChild<QDockWidget*>(QStringLiteral("LogDock")))
        tabifyDockWidget(pipelineDock, logDock);
    pipelineDock->raise();
    // Two branches (Import and two rows of Cluster -> Bake -> Export) without scrolling.
    resizeDocks({pipelineDock}, {290}, Qt::Vertical);
    pipeline_ = pipeline;
    connect(pipeline, &hlod::widgets::PipelineEditor::nodeSelected, this,
            [this, paramsDock](quint32 node) {
                buildParams_->showNode(node);
                paramsDock->show();
                paramsDock->raise();
            });

    clusterEdits_ =
        new hlod::widgets::ClusterEditActions(session_, model_, clusterTree_, clusterModel_, this);
    clusterEdits_->attachViewport(viewport_, display_);
    connect(session_->undo(), &hlod::widgets::UndoAdapter::commandFailed, this,
            [this](const QString& message) {
                log_->error(message);
                statusBar()->showMessage(message, 8000);
            });
    onDocumentReplaced();
}

void MainWindow::createEditMenu() {
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QUndoStack* stack = session_->undo()->stack();
    QAction* undo = stack->createUndoAction(this, tr("&Undo"));
    undo->setShortcuts({QKeySequence(Qt::CTRL | Qt::Key_Z)});
    QAction* redo = stack->createRedoAction(this, tr("&Redo"));
    redo->setShortcuts(
        {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    QMenu* clusters = edit->addMenu(tr("&Clusters"));
    connect(clusters, &QMenu::aboutToShow, clusterEdits_, [this, clusters] {
        clusters->clear();
        clusterEdits_->fillMenu(clusters);
    });
    clusterEdits_->fillMenu(clusters);
}

void MainWindow::onDocumentReplaced() {
    // The branch the project was saved showing, else the one shown (a save under a new name
    // replaces nothing), else the first one.
    const std::vector<hlod::NodeId> bakes = model_->bakeNodes();
    const bool known = std::find(bakes.begin(), bakes.end(), model_->shownBake()) != bakes.end();
    hlod::NodeId shown = known           ? model_->shownBake()
                         : bakes.empty() ? hlod::kNoNode
                                         : bakes.front();
    const nlohmann::json& state = session_->document().viewState();
    if (const auto display = state.find("display");
        display != state.end() && display->is_object() && display->contains("bake")) {
        const nlohmann::json& bake = (*display)["bake"];
        if (bake.is_number_unsigned() &&
            std::find(bakes.begin(), bakes.end(), bake.get<hlod::NodeId>()) != bakes.end())
            shown = bake.get<hlod::NodeId>();
    }
    model_->setShownBake(shown);
    if (pipeline_) pipeline_->view()->selectNode(shown);
    if (buildParams_) buildParams_->showNode(shown);
    updateTitle();
}
