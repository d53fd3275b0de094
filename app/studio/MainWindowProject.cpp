// Project files and export in the main window (see MainWindow.h): File ▸ Open Project, Save
// Project (Ctrl+S), Save Project As, Export Package; the "save changes?" prompt on close and
// before another scene or project replaces the document; the offer to recover a newer
// autosave when a project opens.
#include "MainWindow.h"

#include <QAction>
#include <QCoreApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>

#include "pipeline/doc/ProjectFile.h"
#include "widgets/ExportDialog.h"
#include "widgets/LogView.h"
#include "widgets/SceneLoader.h"
#include "widgets/StudioModel.h"
#include "widgets/doc/ProjectSession.h"

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
    exportAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    exportAction_->setStatusTip(tr("Write the current HLOD as a 3D Tiles package"));
    exportAction_->setEnabled(false);
    connect(model_, &hlod::widgets::StudioModel::buildFinished, this,
            [this] { exportAction_->setEnabled(model_->hasBuild()); });
    connect(model_, &hlod::widgets::StudioModel::sceneChanged, this,
            [this] { exportAction_->setEnabled(model_->hasBuild()); });
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
    try {
        session_->open(file, recover);
    } catch (const std::exception& e) {
        log_->error(QString::fromStdString(e.what()));
        QMessageBox::warning(this, tr("Could not open the project"),
                             QString::fromStdString(e.what()));
        return false;
    }
    log_->info(recover ? tr("Recovered %1 from its autosave").arg(file)
                       : tr("Opened project %1").arg(file));
    QStringList files;
    for (const std::filesystem::path& source : session_->document().sources())
        files << QString::fromStdString(source.string());
    projectLoad_ = true;
    loader_->load(files);
    return true;
}

bool MainWindow::saveProject() {
    if (session_->projectPath().isEmpty()) return saveProjectAs();
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
    if (!model_->hasBuild()) return;
    hlod::widgets::ExportRequest request;
    request.built = model_->built();
    const hlod::Document& doc = session_->document();
    request.edits = doc.graph().node(doc.clusterNode()).edits;
    for (const std::filesystem::path& source : doc.sources())
        request.inputs.push_back(source.string());
    if (request.inputs.empty()) request.inputs.push_back("sample:plant");
    QString folder =
        session_->projectPath().isEmpty()
            ? QDir::home().filePath(QStringLiteral("hlod-package"))
            : QFileInfo(session_->projectPath()).absolutePath() + QStringLiteral("/package");
    hlod::widgets::ExportDialog dialog(std::move(request), folder, this);
    connect(dialog.exporter(), &hlod::widgets::PackageExporter::finished, this,
            [this](const QString& dir, qint64 files, qint64) {
                log_->info(tr("Exported the package to %1 (%2 files)").arg(dir).arg(files));
            });
    connect(dialog.exporter(), &hlod::widgets::PackageExporter::failed, this,
            [this](const QString& message) { log_->error(message); });
    dialog.exec();
}
