// Project files and export in the main window (see MainWindow.h): File ▸ Open Project, Save
// Project (Ctrl+S), Save Project As, Export Package (the shown branch's Export node, added when
// the branch has none), Export All (every Export node); the "save changes?" prompt on close and
// before another scene or project replaces the document; the offer to recover a newer
// autosave when a project opens; opening a project in two steps (read it, load its scene, then
// adopt it, build and show it); the display (and the shown branch) kept in the project's view
// state.
#include "MainWindow.h"

#include <QAction>
#include <QCoreApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QStatusBar>

#include "pipeline/doc/ProjectFile.h"
#include "pipeline/graph/Parameters.h"
#include "widgets/ExportDialog.h"
#include "widgets/LogView.h"
#include "widgets/SceneLoader.h"
#include "widgets/StudioModel.h"
#include "widgets/doc/ProjectSession.h"
#include "widgets/graph/PipelineEditor.h"

using hlod::widgets::ProjectSession;

namespace {

QString projectFilter() {
    return QCoreApplication::translate("MainWindow", "HLOD projects (*%1)")
        .arg(QLatin1String(hlod::kProjectExtension));
}

} // namespace

void MainWindow::addProjectActions(QMenu* file) {
    QAction* open = file->addAction(tr("Open &Project…"), this, &MainWindow::openProjectDialog);
    open->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O));
    open->setStatusTip(tr("Open a .hlodproj project: its scene, parameters and hand edits"));
    QAction* save = file->addAction(tr("&Save Project"), this, &MainWindow::saveProject);
    save->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_S));
    QAction* saveAs = file->addAction(tr("Save Project &As…"), this, &MainWindow::saveProjectAs);
    saveAs->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
    file->addSeparator();
    exportAction_ = file->addAction(tr("&Export Package…"), this, &MainWindow::exportDialog);
    exportAction_->setObjectName(QStringLiteral("actionExport"));
    exportAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    exportAction_->setStatusTip(tr("Write the shown branch's package (its Export node) as 3D "
                                   "Tiles"));
    exportAction_->setEnabled(false);
    exportAllAction_ = file->addAction(tr("Export &All Packages"), this, &MainWindow::exportAll);
    exportAllAction_->setObjectName(QStringLiteral("actionExportAll"));
    exportAllAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E));
    exportAllAction_->setStatusTip(tr("Run every Export node: each branch's package into its own "
                                      "folder"));
    exportAllAction_->setEnabled(false);
    // Export applies to an open scene while no run goes on (it would replace it).
    auto updateExport = [this] {
        const bool idle = model_->scene() && !model_->building();
        exportAction_->setEnabled(idle && model_->shownBake() != hlod::kNoNode);
        exportAllAction_->setEnabled(
            idle && !session_->document().graph().nodesOf(hlod::NodeKind::Export).empty());
    };
    using hlod::widgets::StudioModel;
    for (auto signal :
         {&StudioModel::runFinished, &StudioModel::sceneChanged, &StudioModel::buildStarted,
          &StudioModel::buildCancelled, &StudioModel::shownBakeChanged})
        connect(model_, signal, this, updateExport);
    connect(model_, &StudioModel::buildFailed, this, updateExport);
    connect(session_, &ProjectSession::documentChanged, this, updateExport);
}

void MainWindow::openProjectDialog() {
    const QString dir = session_->projectPath().isEmpty()
                            ? QDir::homePath()
                            : QFileInfo(session_->projectPath()).absolutePath();
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open Project"), dir, projectFilter());
    if (!path.isEmpty()) openProject(path);
}

bool MainWindow::openProject(const QString& path) {
    if (!maybeSave()) return false;
    const QString file = QFileInfo(path).absoluteFilePath();
    bool recover = false;
    if (ProjectSession::hasNewerAutosave(file) && screenshotPath_.isEmpty())
        recover = QMessageBox::question(
                      this, tr("Recover Project"),
                      tr("%1 has an autosave newer than the project (the editor may have "
                         "stopped before saving). Recover the autosaved changes?")
                          .arg(QFileInfo(file).fileName()),
                      QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes) == QMessageBox::Yes;
    std::unique_ptr<PendingProject> pending;
    try {
        pending.reset(new PendingProject{ProjectSession::read(file, recover), file, recover});
    } catch (const std::exception& e) {
        const QString message = QString::fromStdString(e.what());
        log_->error(message);
        if (!screenshotPath_.isEmpty())
            exitScreenshotMode(1, message);
        else
            QMessageBox::warning(this, tr("Could not open the project"), message);
        return false;
    }
    QStringList files;
    for (const std::filesystem::path& source : pending->doc.sources())
        files << QString::fromStdString(source.string());
    const hlod::PipelineGraph& graph = pending->doc.graph();
    const hlod::NodeId import = pending->doc.importNode();
    const hlod::ImportOptions options = import == hlod::kNoNode
                                            ? hlod::ImportOptions{}
                                            : hlod::importOptionsFrom(graph.node(import).params);
    log_->info(recover ? tr("Recovering %1 from its autosave").arg(file)
                       : tr("Opening project %1").arg(file));
    pendingProject_ = std::move(pending);
    reloading_ = false;
    loadOptions_ = options;
    loader_->load(files, options);
    return true;
}

void MainWindow::adoptPendingProject(const QStringList& files) {
    const std::unique_ptr<PendingProject> project = std::move(pendingProject_);
    session_->adopt(std::move(project->doc), project->path, project->recovered);
    log_->info(project->recovered ? tr("Recovered %1 from its autosave").arg(project->path)
                                  : tr("Opened project %1").arg(project->path));
    if (writeSettings_) {
        recent_.add({project->path});
        rebuildRecentMenu();
    }
    Q_UNUSED(files);
    // Show what the project describes: build its HLOD, then its saved display.
    const StartupView saved = viewFromProject();
    if (!startupPending_) startup_ = {};
    startup_.build = true;
    if (!startup_.mode) startup_.mode = saved.mode;
    if (!startup_.level) startup_.level = saved.level;
    startup_.tintByDepth = startup_.tintByDepth || saved.tintByDepth;
    startupPending_ = true;
    statusBar()->showMessage(tr("Opened %1: building its HLOD…").arg(session_->displayName()),
                             8000);
}

MainWindow::StartupView MainWindow::viewFromProject() const {
    StartupView view;
    view.mode = QStringLiteral("hlod");
    const nlohmann::json& state = session_->document().viewState();
    const auto display = state.find("display");
    if (display == state.end() || !display->is_object()) return view;
    const QString mode = QString::fromStdString(display->value("mode", std::string("hlod")));
    hlod::widgets::DisplayMode parsed;
    if (hlod::widgets::displayModeFromString(mode, parsed)) view.mode = mode;
    const auto level = display->find("level");
    if (level != display->end() && level->is_number_integer() && level->get<int>() >= 0)
        view.level = level->get<int>();
    view.tintByDepth = display->value("tint_depth", false);
    return view;
}

void MainWindow::storeViewState() {
    const hlod::widgets::ViewOptions& view = model_->view();
    const char* mode = view.mode == hlod::widgets::DisplayMode::Clusters ? "clusters"
                       : view.mode == hlod::widgets::DisplayMode::Hlod   ? "hlod"
                                                                         : "original";
    nlohmann::json state = session_->document().viewState();
    state["display"] = {{"mode", mode}, {"level", view.level}, {"tint_depth", view.tintByDepth}};
    if (model_->shownBake() != hlod::kNoNode) state["display"]["bake"] = model_->shownBake();
    session_->document().setViewState(std::move(state));
}

bool MainWindow::saveProject() {
    if (session_->projectPath().isEmpty()) return saveProjectAs();
    storeViewState();
    try {
        session_->save(session_->projectPath());
    } catch (const std::exception& e) {
        log_->error(QString::fromStdString(e.what()));
        QMessageBox::warning(this, tr("Could not save the project"),
                             QString::fromStdString(e.what()));
        return false;
    }
    log_->info(tr("Saved project %1").arg(session_->projectPath()));
    updateTitle();
    return true;
}

bool MainWindow::saveProjectAs() {
    QString dir = session_->projectPath();
    if (dir.isEmpty())
        dir = sceneFiles_.isEmpty() ? QDir::homePath()
                                    : QFileInfo(sceneFiles_.front()).absolutePath();
    QString path = QFileDialog::getSaveFileName(this, tr("Save Project As"), dir, projectFilter());
    if (path.isEmpty()) return false;
    if (!path.endsWith(QLatin1String(hlod::kProjectExtension)))
        path += QLatin1String(hlod::kProjectExtension);
    storeViewState();
    try {
        session_->save(path);
    } catch (const std::exception& e) {
        log_->error(QString::fromStdString(e.what()));
        QMessageBox::warning(this, tr("Could not save the project"),
                             QString::fromStdString(e.what()));
        return false;
    }
    log_->info(tr("Saved project %1").arg(path));
    updateTitle();
    return true;
}

bool MainWindow::maybeSave() {
    if (!session_->shouldPromptOnClose() || !screenshotPath_.isEmpty()) return true;
    const auto answer = QMessageBox::warning(
        this, tr("Unsaved Changes"),
        tr("%1 has unsaved changes. Save them?").arg(session_->displayName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save) return saveProject();
    if (answer == QMessageBox::Discard && !session_->projectPath().isEmpty())
        hlod::removeAutosave(session_->projectPath().toStdString());
    return answer == QMessageBox::Discard;
}

void MainWindow::exportDialog() {
    const hlod::NodeId bake = model_->shownBake();
    hlod::PipelineGraph& g = session_->document().graph();
    if (bake == hlod::kNoNode || !g.hasNode(bake) || model_->building()) return;
    // The shown branch's Export node; a branch without one gets one (an undoable step).
    hlod::NodeId exportNode = hlod::kNoNode;
    for (hlod::NodeId id : g.nodesOf(hlod::NodeKind::Export))
        if (g.upstreamOf(id) == bake && exportNode == hlod::kNoNode) exportNode = id;
    if (exportNode == hlod::kNoNode) {
        const hlod::NodeId next = g.nextId();
        if (!pipeline_->addAfter(hlod::NodeKind::Export, bake)) return;
        exportNode = next;
    }
    QString folder =
        session_->projectPath().isEmpty()
            ? QDir::home().filePath(QStringLiteral("hlod-package"))
            : QFileInfo(session_->projectPath()).absolutePath() + QStringLiteral("/package");
    if (g.nodesOf(hlod::NodeKind::Export).size() > 1)
        folder += QStringLiteral("-%1").arg(exportNode); // every branch its own folder
    hlod::widgets::ExportDialog dialog(*session_->undo(), model_, exportNode, folder, this);
    dialog.setObjectName(QStringLiteral("ExportDialog"));
    connect(&dialog, &hlod::widgets::ExportDialog::exported, this,
            [this](const QString& dir, qint64 files, qint64) {
                log_->info(tr("Exported the package to %1 (%2 files)").arg(dir).arg(files));
            });
    dialog.exec();
}

void MainWindow::exportAll() {
    const hlod::PipelineGraph& g = session_->document().graph();
    const std::vector<hlod::NodeId> exports = g.nodesOf(hlod::NodeKind::Export);
    if (exports.empty() || model_->building()) return;
    // The outcome, once: each package written, or the one line of the node that failed.
    auto* context = new QObject(this);
    auto done = [this, context, exports] {
        const hlod::PipelineGraph& graph = session_->document().graph();
        for (hlod::NodeId id : exports) {
            const hlod::NodeOutput* out = graph.hasNode(id) ? graph.output(id) : nullptr;
            if (out && out->exported && graph.status(id) == hlod::NodeStatus::UpToDate)
                log_->info(tr("%1: wrote the package to %2 (%3 files)")
                               .arg(QString::fromStdString(describeNode(graph.node(id))),
                                    QString::fromStdString(out->exported->output.string()))
                               .arg(out->exported->written.files));
        }
        statusBar()->showMessage(tr("Exported %1 packages").arg(exports.size()), 8000);
        context->deleteLater();
    };
    using hlod::widgets::StudioModel;
    connect(model_, &StudioModel::runFinished, context, done);
    connect(model_, &StudioModel::buildFailed, context, [context] { context->deleteLater(); });
    connect(model_, &StudioModel::buildCancelled, context, [context] { context->deleteLater(); });
    model_->runExports(exports);
    if (!model_->building()) context->deleteLater();
}
