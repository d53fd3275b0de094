// The editing parts of the main window (see MainWindow.h): the ProjectSession that owns the
// document, the Edit menu (Undo / Redo from the document's history), the History dock
// (QUndoView), the Parameters dock (ParameterPanels of the Cluster and Bake nodes: every edit a
// document command) and the cluster hand edits of the Clusters tab.
#include "MainWindow.h"

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
#include "widgets/doc/ProjectSession.h"
#include "widgets/params/BuildParameters.h"

using hlod::widgets::ProjectSession;

void MainWindow::createSession() {
    session_ = new ProjectSession(this);
    model_->setDocument(&session_->document());
    connect(session_, &ProjectSession::documentChanged, model_,
            &hlod::widgets::StudioModel::syncSettings);
    connect(session_, &ProjectSession::dirtyChanged, this, [this] { updateTitle(); });
    connect(session_, &ProjectSession::projectChanged, this, &MainWindow::onDocumentReplaced);
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

    clusterEdits_ =
        new hlod::widgets::ClusterEditActions(session_, model_, clusterTree_, clusterModel_, this);
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
    clusters->addActions({clusterEdits_->mergeAction(), clusterEdits_->lockAction(),
                          clusterEdits_->unlockAction(), clusterEdits_->excludeAction()});
    connect(clusters, &QMenu::aboutToShow, clusterEdits_,
            &hlod::widgets::ClusterEditActions::updateActions);
}

void MainWindow::onDocumentReplaced() {
    const hlod::Document& doc = session_->document();
    if (buildParams_) buildParams_->setNodes(doc.clusterNode(), doc.bakeNode());
    model_->syncSettings();
    updateTitle();
}
