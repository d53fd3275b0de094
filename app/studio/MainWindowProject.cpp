// Project files and export in the main window (see MainWindow.h): File ▸ Open Project, Save
// Project (Ctrl+S), Save Project As, Export Package (the shown branch's Export node, added when
// the branch has none), Export All (every Export node); the "save changes?" prompt on close and
// before another scene or project replaces the document; the offer to recover a newer
// autosave when a project opens; opening a project in two steps (read it, load its scene, then
// adopt it, build and show it); the display (and the shown branch) kept in the project's view
// state.
#include "MainWindow.h"

#include <array>
#include <cmath>

#include <QAction>
#include <QCoreApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include "pipeline/doc/ProjectFile.h"
#include "pipeline/graph/Parameters.h"
#include "widgets/ExportDialog.h"
#include "widgets/LogView.h"
#include "widgets/NumberFormat.h"
#include "widgets/SceneLoader.h"
#include "widgets/StudioModel.h"
#include "widgets/Viewport.h"
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
        // Which Export node it writes (issue 31 #11), or that it adds one.
        const hlod::PipelineGraph& g = session_->document().graph();
        hlod::NodeId target = hlod::kNoNode;
        for (hlod::NodeId id : g.nodesOf(hlod::NodeKind::Export))
            if (model_->shownBake() != hlod::kNoNode && g.upstreamOf(id) == model_->shownBake() &&
                target == hlod::kNoNode)
                target = id;
        exportAction_->setText(target != hlod::kNoNode
                                   ? tr("&Export Package (%1)…")
                                         .arg(QString::fromStdString(describeNode(g.node(target))))
                                   : tr("&Export Package…"));
        exportAction_->setStatusTip(
            target != hlod::kNoNode
                ? tr("Write the shown branch's package with %1 as 3D Tiles")
                      .arg(QString::fromStdString(describeNode(g.node(target))))
                : tr("Add an Export node to the shown branch and write its package as 3D Tiles"));
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
    // Show what the project describes: build its HLOD, then its saved display and camera.
    const StartupView saved = viewFromProject();
    pendingCamera_ = cameraFromProject();
    if (!startupPending_) startup_ = {};
    startup_.build = true;
    if (!startup_.mode) startup_.mode = saved.mode;
    if (!startup_.level) startup_.level = saved.level;
    startup_.tintByDepth = startup_.tintByDepth || saved.tintByDepth;
    startupPending_ = true;
    statusBar()->showMessage(tr("Opened %1: building its HLOD…").arg(session_->displayName()),
                             8000);
}

std::optional<MainWindow::SavedCamera> MainWindow::cameraFromProject() const {
    const nlohmann::json& state = session_->document().viewState();
    const auto camera = state.find("camera");
    if (camera == state.end() || !camera->is_object()) return std::nullopt;
    auto read = [&](const char* key, std::array<double, 3>& out) {
        const auto v = camera->find(key);
        if (v == camera->end() || !v->is_array() || v->size() != 3) return false;
        for (std::size_t i = 0; i < 3; ++i) {
            if (!(*v)[i].is_number()) return false;
            out[i] = (*v)[i].get<double>();
            if (!std::isfinite(out[i])) return false;
        }
        return true;
    };
    SavedCamera saved;
    if (!read("position", saved.position) || !read("focal_point", saved.focalPoint) ||
        !read("view_up", saved.viewUp))
        return std::nullopt;
    saved.viewAngle = camera->value("view_angle", 30.0);
    if (!(saved.viewAngle > 0.0 && saved.viewAngle < 180.0) || saved.position == saved.focalPoint)
        return std::nullopt;
    return saved;
}

void MainWindow::applySavedCamera() {
    if (!pendingCamera_ || !viewport_) return;
    vtkCamera* camera = viewport_->camera();
    camera->SetPosition(pendingCamera_->position.data());
    camera->SetFocalPoint(pendingCamera_->focalPoint.data());
    camera->SetViewUp(pendingCamera_->viewUp.data());
    camera->SetViewAngle(pendingCamera_->viewAngle);
    viewport_->renderer()->ResetCameraClippingRange();
    pendingCamera_.reset();
    viewport_->update();
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
    // The camera (issue 31 #11): opening the project shows the scene from where it was saved.
    // A key older projects lack: they open with the fitted default view.
    if (viewport_ && scene()) {
        vtkCamera* camera = viewport_->camera();
        auto vec = [](const double* v) { return nlohmann::json::array({v[0], v[1], v[2]}); };
        state["camera"] = {{"position", vec(camera->GetPosition())},
                           {"focal_point", vec(camera->GetFocalPoint())},
                           {"view_up", vec(camera->GetViewUp())},
                           {"view_angle", camera->GetViewAngle()}};
    }
    session_->document().setViewState(std::move(state));
}

bool MainWindow::saveProject() {
    if (session_->projectPath().isEmpty()) return saveProjectAs();
    return saveProjectTo(session_->projectPath());
}

QString MainWindow::defaultProjectPath() const {
    if (!session_->projectPath().isEmpty()) return session_->projectPath();
    // Named after the scene ("spring.hlodproj"; a folder's name for a folder), in the folder
    // of the last project saved or opened, else Documents: not the scene's folder, which is
    // often shared or read-only data (issue 31 #11).
    QString name = QStringLiteral("sample");
    if (!sceneFiles_.isEmpty()) {
        const QFileInfo first(sceneFiles_.front());
        name = first.isDir() ? first.fileName() : first.completeBaseName();
    }
    if (name.isEmpty()) name = QStringLiteral("project");
    QString dir = QSettings().value(QStringLiteral("projects/lastFolder")).toString();
    if (dir.isEmpty() || !QFileInfo(dir).isDir())
        dir = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    if (dir.isEmpty() || !QFileInfo(dir).isDir()) dir = QDir::homePath();
    return QDir(dir).filePath(name + QLatin1String(hlod::kProjectExtension));
}

bool MainWindow::saveProjectAs() {
    QString path = QFileDialog::getSaveFileName(this, tr("Save Project As"), defaultProjectPath(),
                                                projectFilter());
    if (path.isEmpty()) return false;
    if (!path.endsWith(QLatin1String(hlod::kProjectExtension)))
        path += QLatin1String(hlod::kProjectExtension);
    return saveProjectTo(path);
}

bool MainWindow::saveProjectTo(const QString& path) {
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
    if (writeSettings_)
        QSettings().setValue(QStringLiteral("projects/lastFolder"), QFileInfo(path).absolutePath());
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
            [this, exportNode](const QString& dir, qint64 files, qint64 bytes) {
                const hlod::PipelineGraph& graph = session_->document().graph();
                const QString node =
                    graph.hasNode(exportNode)
                        ? QString::fromStdString(describeNode(graph.node(exportNode)))
                        : tr("Export");
                const QString text =
                    tr("%1 wrote the package to %2: %3 files, %4")
                        .arg(node, dir)
                        .arg(files)
                        .arg(hlod::widgets::formatMegabytes(static_cast<std::uint64_t>(bytes)));
                log_->info(text);
                statusBar()->showMessage(text, 15000);
                exportedMessage(tr("Package Exported"), text);
            });
    dialog.exec();
}

void MainWindow::exportedMessage(const QString& title, const QString& text) {
    if (!screenshotPath_.isEmpty()) return;
    // Window-modal but not blocking: the run's end is not held up, tests can read and close it.
    auto* box = new QMessageBox(QMessageBox::Information, title, text, QMessageBox::Ok, this);
    box->setObjectName(QStringLiteral("ExportedMessage"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
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
        statusBar()->showMessage(tr("Exported %1 packages").arg(exports.size()), 15000);
        exportedMessage(
            tr("Packages Exported"),
            tr("Exported %1 packages; the log lists their folders").arg(exports.size()));
        context->deleteLater();
    };
    using hlod::widgets::StudioModel;
    connect(model_, &StudioModel::runFinished, context, done);
    connect(model_, &StudioModel::buildFailed, context, [context] { context->deleteLater(); });
    connect(model_, &StudioModel::buildCancelled, context, [context] { context->deleteLater(); });
    model_->runExports(exports);
    if (!model_->building()) context->deleteLater();
}
