// The editor's main window (see MainWindow.h).
#include "MainWindow.h"

#include <algorithm>
#include <cstdio>
#include <functional>

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDesktopServices>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressBar>
#include <QSettings>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>
#include <QTreeView>
#include <QWindow>
#include <vtkVersion.h>

#include "pipeline/doc/ProjectFile.h"
#include "pipeline/io/Import.h"
#include "widgets/DisplayController.h"
#include "widgets/LogView.h"
#include "widgets/SceneActors.h"
#include "widgets/SceneLoader.h"
#include "widgets/SceneTreeModel.h"
#include "widgets/StudioModel.h"
#include "widgets/Viewport.h"
#include "widgets/compare/CompareView.h"
#include "widgets/doc/ProjectSession.h"

using hlod::widgets::LoadedScene;

namespace {

QString sceneName(const QStringList& files) {
    if (files.isEmpty()) return QCoreApplication::translate("MainWindow", "Sample scene");
    return RecentScenes::label(files);
}

QString layoutName(hlod::widgets::SceneActors::Layout layout) {
    using Layout = hlod::widgets::SceneActors::Layout;
    switch (layout) {
    case Layout::PerInstance:
        return QCoreApplication::translate("MainWindow", "one actor per instance");
    case Layout::PerMaterial:
        return QCoreApplication::translate("MainWindow", "merged per material");
    case Layout::ByOpacity:
        return QCoreApplication::translate("MainWindow", "merged by opacity");
    }
    return {};
}

QString seconds(double s) { return QLocale().toString(s, 'f', 2); }

} // namespace

MainWindow::MainWindow(const QString& glProblem, QWidget* parent)
    : QMainWindow(parent), glProblem_(glProblem) {
    setWindowIcon(QIcon(QStringLiteral(":/icons/hlod-studio.png")));
    setAcceptDrops(true);
    setObjectName(QStringLiteral("MainWindow"));

    if (glProblem_.isEmpty()) {
        viewport_ = new hlod::widgets::Viewport(this);
        connect(viewport_, &hlod::widgets::Viewport::frameRendered, this,
                &MainWindow::onFrameRendered);
        setCentralWidget(viewport_);
    } else {
        auto* message = new QLabel(glProblem_, this);
        message->setWordWrap(true);
        message->setAlignment(Qt::AlignCenter);
        message->setMargin(32);
        setCentralWidget(message);
    }

    model_ = new hlod::widgets::StudioModel(this);
    if (viewport_) display_ = new hlod::widgets::DisplayController(model_, viewport_, this);
    loader_ = new hlod::widgets::SceneLoader(this);
    connect(loader_, &hlod::widgets::SceneLoader::started, this, &MainWindow::onLoadStarted);
    connect(loader_, &hlod::widgets::SceneLoader::progressed, this, &MainWindow::onLoadProgress);
    connect(loader_, &hlod::widgets::SceneLoader::loaded, this, &MainWindow::onLoaded);
    connect(loader_, &hlod::widgets::SceneLoader::failed, this, &MainWindow::onLoadFailed);

    createSession();
    createDocks();
    createHlodDocks();
    createActions();
    createStatusBar();
    createBuildStatus();
    updateTitle();
    updateCounts();
    resize(1280, 800);
    // Once every dock is in place: the scene dock wide enough for the Clusters tab's names
    // next to its four number columns, the right column for the parameter editors.
    resizeDocks({findChild<QDockWidget*>(QStringLiteral("SceneDock")),
                 findChild<QDockWidget*>(QStringLiteral("BuildDock"))},
                {380, 400}, Qt::Horizontal);
    resizeDocks({findChild<QDockWidget*>(QStringLiteral("BuildDock")),
                 findChild<QDockWidget*>(QStringLiteral("StatsDock"))},
                {390, 400}, Qt::Vertical);
    if (viewport_)
        connect(viewport_, &hlod::widgets::Viewport::glFailed, log_,
                [this](const QString& m) { log_->error(m); });
    if (!glProblem_.isEmpty()) log_->error(glProblem_);
}

MainWindow::~MainWindow() = default;

void MainWindow::createActions() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* open = file->addAction(tr("&Open…"), this, &MainWindow::openDialog);
    open->setObjectName(QStringLiteral("actionOpen"));
    open->setShortcut(QKeySequence::Open);
    open->setStatusTip(tr("Open a project, or one or more scene files (several files form one "
                          "scene)"));
    QAction* folder = file->addAction(tr("Open &Folder…"), this, &MainWindow::openFolderDialog);
    folder->setStatusTip(tr("Open every loadable file in a folder as one scene"));
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    rebuildRecentMenu();
    file->addAction(tr("Open &Sample Scene"), this, [this] { openFiles({}); });
    file->addSeparator();
    addProjectActions(file);
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

    createEditMenu();
    createBuildMenu();

    viewMenu_ = menuBar()->addMenu(tr("&View"));
    QAction* fit = viewMenu_->addAction(tr("&Fit View"));
    fit->setShortcut(QKeySequence(Qt::Key_F));
    fit->setStatusTip(tr("Show the whole scene"));
    QAction* reset = viewMenu_->addAction(tr("&Reset View"));
    reset->setShortcut(QKeySequence(Qt::Key_Home));
    reset->setStatusTip(tr("Look at the whole scene from the front, right and above"));
    if (viewport_) {
        connect(fit, &QAction::triggered, viewport_, &hlod::widgets::Viewport::fitView);
        connect(reset, &QAction::triggered, viewport_, &hlod::widgets::Viewport::resetView);
    }
    // The view actions apply to a scene in a working 3D view.
    auto updateView = [this, fit, reset] {
        fit->setEnabled(viewport_ && scene());
        reset->setEnabled(viewport_ && scene());
    };
    connect(model_, &hlod::widgets::StudioModel::sceneChanged, this, updateView);
    updateView();
    addCompareActions(viewMenu_);
    viewMenu_->addSeparator();
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        viewMenu_->addAction(dock->toggleViewAction());

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* guide = help->addAction(tr("&User Guide (README)"), this, &MainWindow::openUserGuide);
    guide->setObjectName(QStringLiteral("actionUserGuide"));
    guide->setShortcut(QKeySequence::HelpContents);
    guide->setStatusTip(tr("Open the README, the user guide of HLOD Studio"));
    QAction* keys = help->addAction(tr("&Keyboard Shortcuts"), this, &MainWindow::showShortcuts);
    keys->setObjectName(QStringLiteral("actionShortcuts"));
    keys->setStatusTip(tr("Every shortcut of the menus and the viewport"));
    help->addSeparator();
    help->addAction(tr("&About HLOD Studio"), this, &MainWindow::showAbout);
    help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
}

void MainWindow::createDocks() {
    treeModel_ = new hlod::widgets::SceneTreeModel(this);
    tree_ = new QTreeView;
    tree_->setModel(treeModel_);
    tree_->setUniformRowHeights(true); // thousands of rows (TORCS) scroll smoothly
    tree_->setAlternatingRowColors(true);
    tree_->header()->setStretchLastSection(false);
    tree_->header()->setSectionResizeMode(hlod::widgets::SceneTreeModel::NameColumn,
                                          QHeaderView::Stretch);
    tree_->header()->setSectionResizeMode(hlod::widgets::SceneTreeModel::MeshesColumn,
                                          QHeaderView::ResizeToContents);
    tree_->header()->setSectionResizeMode(hlod::widgets::SceneTreeModel::TrianglesColumn,
                                          QHeaderView::ResizeToContents);
    treeTabs_ = new QTabWidget;
    treeTabs_->setDocumentMode(true);
    treeTabs_->addTab(tree_, tr("Scene"));
    auto* sceneDock = new QDockWidget(tr("Scene"), this);
    sceneDock->setObjectName(QStringLiteral("SceneDock"));
    sceneDock->setWidget(treeTabs_);
    addDockWidget(Qt::LeftDockWidgetArea, sceneDock);

    log_ = new hlod::widgets::LogView;
    auto* logDock = new QDockWidget(tr("Log"), this);
    logDock->setObjectName(QStringLiteral("LogDock"));
    logDock->setWidget(log_);
    addDockWidget(Qt::BottomDockWidgetArea, logDock);
    resizeDocks({logDock}, {130}, Qt::Vertical);
}

void MainWindow::createStatusBar() {
    busyLabel_ = new QLabel;
    busyBar_ = new QProgressBar;
    busyBar_->setMaximumWidth(160);
    busyBar_->setTextVisible(false);
    counts_ = new QLabel;
    statusBar()->addWidget(busyLabel_);
    statusBar()->addWidget(busyBar_);
    statusBar()->addPermanentWidget(counts_);
    setBusy(false);
}

void MainWindow::rebuildRecentMenu() {
    recentMenu_->clear();
    const QList<QStringList>& entries = recent_.entries();
    for (int i = 0; i < entries.size(); ++i) {
        const QStringList files = entries[i];
        QAction* action = recentMenu_->addAction(
            QStringLiteral("&%1 %2").arg(i + 1).arg(RecentScenes::label(files)), this,
            [this, files] { openFiles(files); });
        action->setToolTip(files.join(QLatin1Char('\n')));
        action->setStatusTip(files.join(QStringLiteral(", ")));
    }
    if (!entries.isEmpty()) {
        recentMenu_->addSeparator();
        recentMenu_->addAction(tr("&Clear List"), this, [this] {
            recent_.clear();
            rebuildRecentMenu();
        });
    }
    recentMenu_->setEnabled(!entries.isEmpty());
}

void MainWindow::openFiles(const QStringList& files) {
    const auto project = std::find_if(files.begin(), files.end(), [](const QString& f) {
        return f.endsWith(QLatin1String(hlod::kProjectExtension), Qt::CaseInsensitive);
    });
    if (project != files.end()) {
        if (files.size() == 1) {
            openProject(*project);
            return;
        }
        const QString message =
            tr("%1 is a project: open it on its own (its scene is in the project), not "
               "together with other files")
                .arg(QFileInfo(*project).fileName());
        log_->error(message);
        if (screenshotPath_.isEmpty())
            QMessageBox::warning(this, tr("Could not open %1").arg(sceneName(files)), message);
        else
            exitScreenshotMode(2, message);
        return;
    }
    if (!maybeSave()) return;
    pendingProject_.reset();
    QStringList absolute;
    for (const QString& file : files)
        absolute << QFileInfo(file).absoluteFilePath();
    reloading_ = false;
    loadOptions_ = {};
    loader_->load(absolute);
}

void MainWindow::onDocumentEdited() {
    // A shown Bake node that was removed (or none shown while there is one): show the first.
    const std::vector<hlod::NodeId> bakes = model_->bakeNodes();
    if (!session_->replacing() &&
        std::find(bakes.begin(), bakes.end(), model_->shownBake()) == bakes.end())
        model_->setShownBake(bakes.empty() ? hlod::kNoNode : bakes.front());
    // An edit of the Import node (its files, its import parameters) reads the scene again: what
    // the view shows is that node's output.
    if (session_->replacing() || pendingProject_ || !model_->scene() || loader_->busy()) return;
    const hlod::Document& doc = session_->document();
    const hlod::NodeId import = doc.importNode();
    if (import == hlod::kNoNode || doc.graph().definition(import) == loadedImport_) return;
    reloadScene();
}

void MainWindow::reloadScene() {
    const hlod::Document& doc = session_->document();
    QStringList files;
    for (const std::filesystem::path& source : doc.sources())
        files << QString::fromStdString(source.string());
    reloading_ = true;
    loadOptions_ = hlod::importOptionsFrom(doc.graph().node(doc.importNode()).params);
    log_->info(tr("The Import node changed: reading the scene again"));
    if (model_->everBuilt()) {
        // Show the shown branch again once the scene is back.
        const hlod::widgets::DisplayMode mode = model_->view().mode;
        startup_ = {};
        startup_.build = true;
        startup_.mode = mode == hlod::widgets::DisplayMode::Hlod       ? QStringLiteral("hlod")
                        : mode == hlod::widgets::DisplayMode::Clusters ? QStringLiteral("clusters")
                                                                       : QStringLiteral("original");
        startupPending_ = true;
    }
    loader_->load(files, loadOptions_);
}

void MainWindow::adoptLoadedScene(const LoadedScene& result) {
    hlod::PipelineGraph& g = session_->document().graph();
    const hlod::NodeId import = session_->document().importNode();
    if (import == hlod::kNoNode) return;
    // The step the loader ran: the document's Import node with these files and options.
    hlod::GraphNode ran = g.node(import);
    ran.sources.clear();
    for (const QString& file : result.files)
        ran.sources.emplace_back(file.toStdString());
    ran.params = hlod::paramsFrom(loadOptions_);
    hlod::PipelineGraph step;
    step.insertNode(ran);
    hlod::NodeOutput out;
    out.scene = result.scene;
    for (const auto& source : ran.sources)
        out.inputs.push_back(source.string());
    if (out.inputs.empty()) out.inputs = {"sample:plant"};
    loadedImport_ = step.definition(import);
    g.adopt(import, loadedImport_, hlod::NodeStatus::UpToDate,
            std::make_shared<const hlod::NodeOutput>(std::move(out)));
}

void MainWindow::openDialog() {
    QStringList patterns;
    for (const std::string& pattern : hlod::loadablePatterns())
        patterns << QString::fromStdString(pattern);
    const QString project = QStringLiteral("*") + QLatin1String(hlod::kProjectExtension);
    const QString filter = tr("Scenes and projects (%1)")
                               .arg(patterns.join(QLatin1Char(' ')) + QLatin1Char(' ') + project) +
                           QStringLiteral(";;") + tr("HLOD projects (%1)").arg(project) +
                           QStringLiteral(";;") + tr("All files (*)");
    const QString dir =
        sceneFiles_.isEmpty() ? QDir::homePath() : QFileInfo(sceneFiles_.front()).absolutePath();
    const QStringList files =
        QFileDialog::getOpenFileNames(this, tr("Open Scene or Project"), dir, filter);
    if (!files.isEmpty()) openFiles(files);
}

void MainWindow::openFolderDialog() {
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Open Folder as Scene"));
    if (!dir.isEmpty()) openFiles({dir});
}

void MainWindow::showAbout() {
    const QString gl = viewport_ && viewport_->glAvailable() ? tr("OpenGL: available")
                                                             : tr("OpenGL: not available");
    QMessageBox::about(
        this, tr("About HLOD Studio"),
        tr("<h3>HLOD Studio %1</h3>"
           "<p>Builds Hierarchical Level-of-Detail for 3D scenes: clusters of meshes with "
           "simplified proxies, exported as 3D Tiles for any engine.</p>"
           "<p>Qt %2, VTK %3. %4</p>")
            .arg(QStringLiteral(HLOD_VERSION), QString::fromLatin1(qVersion()),
                 QString::fromLatin1(vtkVersion::GetVTKVersion()), gl));
}

QString MainWindow::userGuidePath() {
    // Installed by the .deb; next to the binary's source tree in a build (build/app/..).
    const QString app = QCoreApplication::applicationDirPath();
    for (const QString& candidate : {app + QStringLiteral("/../share/doc/hlod-studio/README.md"),
                                     QStringLiteral("/usr/share/doc/hlod-studio/README.md"),
                                     app + QStringLiteral("/../../README.md")})
        if (QFileInfo(candidate).isFile()) return QFileInfo(candidate).canonicalFilePath();
    return {};
}

void MainWindow::openUserGuide() {
    const QString path = userGuidePath();
    if (!path.isEmpty() && QDesktopServices::openUrl(QUrl::fromLocalFile(path))) {
        log_->info(tr("Opened the user guide %1").arg(path));
        return;
    }
    const QString text =
        path.isEmpty()
            ? tr("The user guide is README.md of HLOD Studio (installed as "
                 "/usr/share/doc/hlod-studio/README.md by the .deb); it was not found here.")
            : tr("No program opens %1 here; open it in a text editor or a Markdown viewer.")
                  .arg(path);
    log_->warning(text);
    if (screenshotPath_.isEmpty()) QMessageBox::information(this, tr("User Guide"), text);
}

QString MainWindow::shortcutsHtml() const {
    // Collected from the menus (what they hold now), then the viewport's own keys and mouse.
    QString html = tr("<h3>Keyboard shortcuts</h3><table cellspacing='0' cellpadding='2'>");
    auto row = [&](const QString& keys, const QString& what) {
        html += QStringLiteral("<tr><td><b>%1</b></td><td>&nbsp;&nbsp;%2</td></tr>")
                    .arg(keys.toHtmlEscaped(), what.toHtmlEscaped());
    };
    std::function<void(QMenu*, const QString&)> walk = [&](QMenu* menu, const QString& path) {
        for (QAction* action : menu->actions()) {
            const QString name =
                path + QStringLiteral(" ▸ ") + QString(action->text()).remove(QLatin1Char('&'));
            if (action->menu()) {
                walk(action->menu(), name);
                continue;
            }
            if (!action->shortcut().isEmpty())
                row(action->shortcut().toString(QKeySequence::NativeText), name);
        }
    };
    for (QAction* top : menuBar()->actions())
        if (top->menu()) walk(top->menu(), QString(top->text()).remove(QLatin1Char('&')));
    html += QStringLiteral("</table><h3>%1</h3><table cellspacing='0' cellpadding='2'>")
                .arg(tr("Viewport"));
    row(tr("Left drag"), tr("Orbit"));
    row(tr("Middle drag, Shift+left drag"), tr("Pan"));
    row(tr("Wheel, right drag"), tr("Zoom"));
    row(tr("Click"), tr("Select the mesh or cluster under the cursor"));
    row(tr("Ctrl+click"), tr("Add or remove the cluster under the cursor"));
    row(tr("Right click"), tr("The cluster edit menu"));
    html += QStringLiteral("</table>");
    const QString guide = userGuidePath();
    html += tr("<p>More in the user guide: Help ▸ User Guide (%1).</p>")
                .arg(guide.isEmpty() ? QStringLiteral("README.md") : guide.toHtmlEscaped());
    return html;
}

void MainWindow::showShortcuts() {
    auto* box = new QMessageBox(QMessageBox::NoIcon, tr("Keyboard Shortcuts"), shortcutsHtml(),
                                QMessageBox::Close, this);
    box->setObjectName(QStringLiteral("ShortcutsDialog"));
    box->setTextFormat(Qt::RichText);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    const QList<QUrl> urls = event->mimeData()->urls();
    const bool local = !urls.isEmpty() && std::all_of(urls.begin(), urls.end(), [](const QUrl& u) {
        return u.isLocalFile();
    });
    if (local) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    QStringList files;
    for (const QUrl& url : event->mimeData()->urls())
        if (url.isLocalFile()) files << url.toLocalFile();
    if (files.isEmpty()) return;
    event->acceptProposedAction();
    openFiles(files);
}

const std::shared_ptr<const hlod::Scene>& MainWindow::scene() const { return model_->scene(); }

void MainWindow::closeEvent(QCloseEvent* event) {
    if (writeSettings_ && !maybeSave()) {
        event->ignore();
        return;
    }
    loader_->cancel();
    model_->cancelBuild();
    if (writeSettings_) {
        QSettings settings;
        settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
        settings.setValue(QStringLiteral("window/state"), saveState());
    }
    QMainWindow::closeEvent(event);
}

void MainWindow::setBusy(bool busy, const QString& text) {
    busyLabel_->setText(text);
    busyLabel_->setVisible(busy);
    busyBar_->setVisible(busy);
    busyBar_->setRange(0, 0); // indeterminate until the importer reports a total
    if (busy)
        QApplication::setOverrideCursor(Qt::BusyCursor);
    else
        while (QApplication::overrideCursor())
            QApplication::restoreOverrideCursor();
}

void MainWindow::onLoadStarted(const QStringList& files) {
    setBusy(false);
    setBusy(true, tr("Loading %1…").arg(sceneName(files)));
    log_->info(files.isEmpty() ? tr("Opening the sample scene")
                               : tr("Opening %1").arg(files.join(QStringLiteral(", "))));
}

void MainWindow::onLoadProgress(const QString& stage, qint64 done, qint64 total) {
    if (total > 0) {
        // QProgressBar takes int: scale large totals (triangle counts) to per mille.
        busyBar_->setRange(0, 1000);
        busyBar_->setValue(static_cast<int>(1000.0 * static_cast<double>(done) / total));
    }
    if (stage.isEmpty()) return;
    // CAD import reports "transfer" (STEP/IGES to shapes, per mille), then "tessellate" per
    // face (faces meshed / all distinct faces).
    const QString what = stage == QLatin1String("tessellate") ? tr("Meshing CAD faces")
                         : stage == QLatin1String("transfer") ? tr("Converting CAD shapes (‰)")
                         : stage == QLatin1String("import")   ? tr("Reading")
                                                              : stage;
    busyBar_->setToolTip(total > 0 ? tr("%1 %2/%3").arg(what).arg(done).arg(total) : what);
}

void MainWindow::onLoaded(const LoadedScene& result) {
    setBusy(false);
    sceneFiles_ = result.files;
    firstBuildOfScene_ = true;
    const hlod::NodeId keep = model_->shownBake();
    // Nothing may bring a run of the old content into the document about to be replaced.
    if (compare_) compare_->detach();
    model_->setScene(result.scene);
    if (pendingProject_) {
        adoptPendingProject(result.files);
    } else if (!reloading_) {
        std::vector<std::filesystem::path> sources;
        for (const QString& file : result.files)
            sources.emplace_back(file.toStdString());
        session_->newDocument(std::move(sources), keep);
        if (!result.files.isEmpty() && writeSettings_) {
            recent_.add(result.files);
            rebuildRecentMenu();
        }
    }
    reloading_ = false;
    adoptLoadedScene(result);
    const std::shared_ptr<const hlod::Scene>& loadedScene = model_->scene();
    treeModel_->setScene(loadedScene);
    markExcludedMeshes();
    tree_->expandToDepth(0);
    if (viewport_) {
        firstFramePending_ = true;
        shownAt_ = std::chrono::steady_clock::now();
        viewport_->setSceneActors(result.actors, hlod::widgets::suggestedUpAxis(*loadedScene));
        if (initialAzimuth_ != 0.0 || initialElevation_ != 0.0) {
            viewport_->orbit(initialAzimuth_, initialElevation_);
            viewport_->fitView();
        }
    }
    const hlod::SceneStats stats = loadedScene->stats();
    const QLocale locale;
    log_->info(tr("Loaded %1: %2 instances, %3 triangles, %4 materials (import %5 s, render "
                  "data %6 s, %7)")
                   .arg(sceneName(result.files))
                   .arg(locale.toString(static_cast<qulonglong>(stats.instances)))
                   .arg(locale.toString(static_cast<qulonglong>(stats.triangles)))
                   .arg(locale.toString(static_cast<qulonglong>(stats.materials)))
                   .arg(seconds(result.importSeconds), seconds(result.buildSeconds))
                   .arg(layoutName(result.actors->layout())));
    updateTitle();
    updateCounts();
    if (startupPending_) {
        applyStartupView();
        return;
    }
    screenshotWhenReady();
}

void MainWindow::onLoadFailed(const QStringList& files, const QString& message) {
    setBusy(false);
    reloading_ = false;
    // A project whose scene cannot be read is not opened: the open document stays.
    const QString title =
        pendingProject_
            ? tr("Could not open the project %1").arg(QFileInfo(pendingProject_->path).fileName())
            : tr("Could not open %1").arg(sceneName(files));
    const QString text =
        pendingProject_ ? tr("Its scene could not be read: %1").arg(message) : message;
    pendingProject_.reset();
    log_->error(text);
    if (!screenshotPath_.isEmpty()) {
        exitScreenshotMode(1, text);
        return;
    }
    QMessageBox::warning(this, title, text);
}

void MainWindow::onFrameRendered() {
    if (!firstFramePending_) return;
    firstFramePending_ = false;
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - shownAt_)
            .count();
    log_->info(tr("First frame in %1 ms").arg(QLocale().toString(ms, 'f', 0)));
}

void MainWindow::updateTitle() {
    // "[*]" is where Qt shows the dirty mark "*" while the window is modified.
    const QString app = tr("HLOD Studio");
    const QString project = session_->displayName() + QStringLiteral("[*]");
    setWindowTitle(scene() ? tr("%1 (%2) — %3").arg(project, sceneName(sceneFiles_), app)
                           : tr("%1 — %2").arg(project, app));
    setWindowModified(session_->isDirty());
}

void MainWindow::updateCounts() {
    if (!scene()) {
        counts_->setText(tr("No scene"));
        return;
    }
    const hlod::SceneStats stats = scene()->stats();
    const QLocale locale;
    counts_->setText(tr("Instances: %1   Triangles: %2   Materials: %3")
                         .arg(locale.toString(static_cast<qulonglong>(stats.instances)))
                         .arg(locale.toString(static_cast<qulonglong>(stats.triangles)))
                         .arg(locale.toString(static_cast<qulonglong>(stats.materials))));
}

void MainWindow::restoreSettings() {
    const QSettings settings;
    restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
}

void MainWindow::setInitialOrbit(double azimuth, double elevation) {
    initialAzimuth_ = azimuth;
    initialElevation_ = elevation;
}

void MainWindow::requestScreenshot(const QString& path, bool viewportOnly) {
    screenshotPath_ = path;
    screenshotViewportOnly_ = viewportOnly;
    writeSettings_ = false;
}

void MainWindow::takeScreenshot(int attemptsLeft) {
    if (viewport_ && !compareSpec_.isEmpty()) return; // the comparison window is saved instead
    // The window must be mapped and laid out before a grab means anything; poll briefly.
    const bool exposed = windowHandle() && windowHandle()->isExposed();
    if (!exposed && attemptsLeft > 0) {
        QTimer::singleShot(50, this, [this, attemptsLeft] { takeScreenshot(attemptsLeft - 1); });
        return;
    }
    if (!viewport_) {
        // No 3D view: still save what the user would see, then report the missing OpenGL.
        if (!grab().toImage().save(screenshotPath_))
            exitScreenshotMode(1, tr("%1: could not write the image").arg(screenshotPath_));
        else
            exitScreenshotMode(2, glProblem_);
        return;
    }
    // grabFrame() renders the current scene synchronously, so the image is up to date.
    QImage image = viewport_->grabFrame();
    if (!screenshotViewportOnly_) image = grab().toImage();
    if (image.isNull()) {
        exitScreenshotMode(1, tr("%1: nothing was rendered").arg(screenshotPath_));
        return;
    }
    if (!image.save(screenshotPath_)) {
        exitScreenshotMode(1, tr("%1: could not write the image").arg(screenshotPath_));
        return;
    }
    exitScreenshotMode(0, {});
}

void MainWindow::exitScreenshotMode(int code, const QString& message) {
    if (!message.isEmpty())
        std::fprintf(stderr, "hlod-studio: %s\n", message.toLocal8Bit().constData());
    QCoreApplication::exit(code);
}
