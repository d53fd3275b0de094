// The editor's main window: the VTK viewport in the centre; docks for the scene and cluster
// trees (two tabs), the build parameters, the statistics and the log; the display toolbar;
// counts, load and build progress (with Cancel) in the status bar; File / Edit / Build / View /
// Help.
// Editing (issue #7): the window owns a ProjectSession (the hlod::Document, its undo history,
// the project file). The Parameters dock edits the selected node's parameters through commands,
// builds are runs of the document's graph (issue 29: the runner `hlod build` uses; the shown
// branch reruns after every change once there is a build), the Pipeline dock shows the
// document's node graph with the statuses of the runs, the Edit menu and the History dock follow
// its undo stack, the Clusters tab and the viewport hand-edit the shown branch's clusters
// (MainWindowEdit.cpp), File saves and opens `.hlodproj` projects (dirty mark in the title, save
// prompt on close, autosave and recovery) and exports packages (the shown branch's Export node,
// or every Export node).
// Branches: the view, the Clusters tab, Statistics and File ▸ Export Package follow the shown
// Bake node (a click on it in the Pipeline dock, or the toolbar's branch box); Build ▸ Build
// HLOD runs the shown branch, Build All Branches every Bake node of the scene.
// The scene: the loader (SceneLoader) runs the Import step of the document's Import node and
// its output is taken into the graph (PipelineGraph::adopt), so runs do not read the scene again;
// an edit of the Import node (files, import parameters) reloads the scene the same way.
// Opening a scene (not a project) starts a new untitled project over it, keeping parameters.
// Opening a project (issue 20: the command line, File ▸ Open, Open Project, Open Recent, drag
// and drop, with the offer to recover a newer autosave) reads it first, then loads its scene
// with its import parameters; only once the scene has loaded does the project replace the open
// document (a project whose scene cannot be read leaves the window as it was, and says which
// file failed). The project's HLOD is then built and shown in the display mode it was saved in
// (HLOD preview by default): the window shows what the project describes.
//
// Ownership: the open scene, the HLOD build, the selection and the display options live in one
// widgets::StudioModel; the viewport, trees, panels and the DisplayController only show them.
// Building runs in the background (Build ▸ Build HLOD, Ctrl+B); errors go to the log and a
// message box. Selecting a row in either tree selects in the viewport and back.
// Loading runs on a worker thread (widgets::SceneLoader); failures go to a message box and the
// log, and the previous scene stays open.
// Screenshot mode (--screenshot) waits until the scene is loaded (and, with --build, the HLOD
// built and the requested mode shown) and rendered, saves the image and quits with exit code 0,
// or 1 with a message on stderr when loading, building or saving fails, or 2 without OpenGL
// (after saving the window as it looks then).
#pragma once

#include <array>
#include <chrono>
#include <memory>
#include <optional>

#include <QMainWindow>
#include <QStringList>

#include "RecentScenes.h"
#include "pipeline/doc/Document.h"
#include "pipeline/io/Import.h"
#include "pipeline/scene/Scene.h"

class QAction;
class QLabel;
class QMenu;
class QProgressBar;
class QPushButton;
class QTabWidget;
class QTreeView;

namespace hlod::widgets {
struct LoadedScene;
class BuildParameters;
class CompareView;
class ClusterEditActions;
class ProjectSession;
class ClusterTreeModel;
class DisplayController;
class DisplayToolBar;
class StatsPanel;
class StudioModel;
class LogView;
class PipelineEditor;
class SceneLoader;
class SceneTreeModel;
class Viewport;
} // namespace hlod::widgets

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    // `glProblem` non-empty: OpenGL 3.2 is missing; the centre shows that message instead of
    // the viewport (the rest of the window works).
    explicit MainWindow(const QString& glProblem = {}, QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opens files or folders as one scene; an empty list opens the embedded sample scene. A
    // single `.hlodproj` opens as a project (openProject).
    void openFiles(const QStringList& files);
    // Window geometry and dock layout of the last session (not used for screenshots, which
    // must look the same on every machine).
    void restoreSettings();
    // After the next load: save a screenshot to `path` (the whole window, or only the 3D view
    // when `viewportOnly`) and quit. Also stops the window from writing settings.
    void requestScreenshot(const QString& path, bool viewportOnly);

    // Every scene opened from now on starts from the default view turned by these angles
    // (degrees; see Viewport::orbit) and fitted again.
    void setInitialOrbit(double azimuth, double elevation);
    // What to do once a scene has loaded (command line): build the HLOD, then show `mode` at
    // `level` (the suggested level when unset), optionally tinting the HLOD preview by depth.
    // Used with and without --screenshot.
    struct StartupView {
        bool build = false;
        bool buildAll = false;       // every branch, not only the shown one
        std::optional<QString> mode; // "original", "clusters", "hlod"
        std::optional<int> level;
        bool tintByDepth = false;
    };
    void setStartupView(const StartupView& view);
    // MainWindowCompare.cpp: once a scene has loaded, open View ▸ Compare Configurations with
    // `spec` ("LEFT:RIGHT", CompareConfig.h); with --screenshot, the comparison window is saved
    // once both sides are built, instead of the main window.
    void setStartupCompare(const QString& spec);
    // The comparison window; null until first opened.
    hlod::widgets::CompareView* compareView() const { return compare_; }
    // View ▸ Compare Configurations: opens (or raises) the comparison of the open scene.
    void showCompare();

    hlod::widgets::Viewport* viewport() const { return viewport_; }
    hlod::widgets::StudioModel* model() const { return model_; }
    hlod::widgets::DisplayController* display() const { return display_; }
    QTreeView* sceneTree() const { return tree_; }
    QTreeView* clusterTree() const { return clusterTree_; }
    QTabWidget* treeTabs() const { return treeTabs_; }
    hlod::widgets::StatsPanel* statsPanel() const { return stats_; }
    hlod::widgets::BuildParameters* buildParameters() const { return buildParams_; }
    hlod::widgets::ProjectSession* session() const { return session_; }
    hlod::widgets::ClusterEditActions* clusterEdits() const { return clusterEdits_; }
    // Opens a `.hlodproj` (offering to recover a newer autosave), loads its scene, builds and
    // shows its HLOD. False when the project cannot be read (a message says why).
    bool openProject(const QString& path);
    QMenu* recentMenu() const { return recentMenu_; }
    // Saves to the current project path (asks for one when untitled); false when not saved.
    bool saveProject();
    bool saveProjectAs();
    // Saves the document (with the view state: display, shown branch, camera) to `path`, as
    // both do once they have a path; false (and a message) when it cannot be written.
    bool saveProjectTo(const QString& path);
    // Where Save Project As proposes to save: the project's path; for an untitled one the
    // scene's name in the folder of the last project saved, else Documents.
    QString defaultProjectPath() const;
    hlod::widgets::LogView* log() const { return log_; }
    const std::shared_ptr<const hlod::Scene>& scene() const;

protected:
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;
    void closeEvent(QCloseEvent* event) override;

private:
    void createActions();
    void createDocks();
    void createStatusBar();
    // MainWindowHlod.cpp: the HLOD parts (cluster tab, build and statistics docks, toolbar,
    // Build menu, build progress, selection sync).
    void createHlodDocks();
    void createBuildMenu();
    void createBuildStatus();
    void markExcludedMeshes();
    void onBuildStarted();
    void onBuildProgress(const QString& stage, qint64 done, qint64 total, const QString& detail);
    void onShownBuildChanged();
    void onBuildFinished();
    void onBuildFailed(const QString& message);
    void onBuildCancelled();
    void hideBuildProgress();
    void applyStartupView();
    void screenshotWhenReady();
    void rebuildRecentMenu();
    // MainWindowEdit.cpp: the document (ProjectSession), Edit menu, History and Parameters
    // docks, cluster hand edits.
    void createSession();
    void createEditMenu();
    void createEditDocks();
    // MainWindowProject.cpp: project files, the close prompt, autosave recovery, export.
    void addProjectActions(QMenu* file);
    void openProjectDialog();
    bool maybeSave();
    void exportDialog();
    void exportAll();
    void onDocumentReplaced();
    // A document edit: reloads the scene when the Import node changed (MainWindow.cpp).
    void onDocumentEdited();
    void reloadScene();
    // The loaded scene as the output of the document's Import node (see The scene above).
    void adoptLoadedScene(const hlod::widgets::LoadedScene& result);
    // The display (mode, level, tint) kept in the document's view state when saving, and the
    // startup view that shows it again after opening.
    void storeViewState();
    StartupView viewFromProject() const;
    // The camera kept in the project's view state ("camera"; absent in older projects), applied
    // once the opened project's view is shown (applyStartupView).
    struct SavedCamera {
        std::array<double, 3> position{}, focalPoint{}, viewUp{};
        double viewAngle = 30.0;
    };
    std::optional<SavedCamera> cameraFromProject() const;
    void applySavedCamera();
    // A non-blocking message box saying an export finished (not in screenshot mode).
    void exportedMessage(const QString& title, const QString& text);
    // onLoaded for a project: adopt its document, then build and show it.
    void adoptPendingProject(const QStringList& files);
    // MainWindowCompare.cpp: the comparison window (View menu, scene and document changes,
    // --compare startup and screenshot).
    void addCompareActions(QMenu* view);
    void createCompareView();
    void onCompareSceneChanged();
    void openStartupCompare();
    void takeCompareScreenshot(int attemptsLeft);

    void openDialog();
    void openFolderDialog();
    void showAbout();
    void openUserGuide();

public:
    // Help ▸ Keyboard Shortcuts: every menu shortcut (collected from the menus) and the
    // viewport's mouse and keys, with the user guide's path; the dialog shows this text.
    QString shortcutsHtml() const;
    void showShortcuts();
    // README.md, the user guide: installed (share/doc/hlod-studio) or in the source tree;
    // empty when neither is found.
    static QString userGuidePath();

private:
    void onLoadStarted(const QStringList& files);
    void onLoadProgress(const QString& stage, qint64 done, qint64 total);
    void onLoaded(const hlod::widgets::LoadedScene& result);
    void onLoadFailed(const QStringList& files, const QString& message);
    void onFrameRendered();

    void setBusy(bool busy, const QString& text = {});
    void updateTitle();
    void updateCounts();
    void takeScreenshot(int attemptsLeft);
    void exitScreenshotMode(int code, const QString& message);

    QStringList sceneFiles_; // what scene_ was opened from; empty for the sample

    hlod::widgets::Viewport* viewport_ = nullptr; // null without OpenGL
    hlod::widgets::StudioModel* model_ = nullptr;
    hlod::widgets::DisplayController* display_ = nullptr; // null without OpenGL
    hlod::widgets::SceneTreeModel* treeModel_ = nullptr;
    hlod::widgets::ClusterTreeModel* clusterModel_ = nullptr;
    QTreeView* clusterTree_ = nullptr;
    QTabWidget* treeTabs_ = nullptr;
    hlod::widgets::StatsPanel* stats_ = nullptr;
    hlod::widgets::BuildParameters* buildParams_ = nullptr;
    hlod::widgets::ProjectSession* session_ = nullptr;
    hlod::widgets::ClusterEditActions* clusterEdits_ = nullptr;
    QAction* exportAction_ = nullptr;
    QAction* exportAllAction_ = nullptr;
    QAction* buildAllAction_ = nullptr;
    hlod::widgets::PipelineEditor* pipeline_ = nullptr;
    hlod::ImportOptions loadOptions_; // what the running or last load was given
    std::string loadedImport_;        // definition of the Import node the scene was loaded for
    bool reloading_ = false;          // the running load reads the document's Import again
    struct PendingProject {
        hlod::Document doc;
        QString path;
        bool recovered = false;
    };
    std::unique_ptr<PendingProject> pendingProject_; // read, waiting for its scene to load
    std::optional<SavedCamera> pendingCamera_;       // an opened project's, until shown
    bool firstBuildOfScene_ = true;                  // the next finished build is the scene's first
    QString lastWarning_; // the last build's dissolve warning (logged when it changes)
    hlod::widgets::DisplayToolBar* toolBar_ = nullptr;
    QLabel* buildLabel_ = nullptr;
    QProgressBar* buildBar_ = nullptr;
    QPushButton* cancelButton_ = nullptr;
    QAction* buildAction_ = nullptr;
    QAction* cancelAction_ = nullptr;
    StartupView startup_;         // what applyStartupView does next
    bool startupPending_ = false; // applyStartupView runs once the scene has loaded
    hlod::widgets::SceneLoader* loader_ = nullptr;
    hlod::widgets::LogView* log_ = nullptr;
    QTreeView* tree_ = nullptr;
    QLabel* counts_ = nullptr;
    QLabel* busyLabel_ = nullptr;
    QProgressBar* busyBar_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QMenu* viewMenu_ = nullptr;
    QString glProblem_;
    hlod::widgets::CompareView* compare_ = nullptr;
    QAction* compareAction_ = nullptr;
    QString compareSpec_;         // --compare: kept so the main window's screenshot defers
    bool compareStarted_ = false; // the --compare comparison has been opened

    RecentScenes recent_;
    bool writeSettings_ = true;
    QString screenshotPath_;
    bool screenshotViewportOnly_ = false;
    bool firstFramePending_ = false;
    double initialAzimuth_ = 0.0;
    double initialElevation_ = 0.0;
    std::chrono::steady_clock::time_point shownAt_;
};
