// The editor's main window: the VTK viewport in the centre, the scene tree and the log as docks,
// counts and a busy indicator in the status bar, and the File / View / Help menus.
//
// Ownership: the window holds the open scene as std::shared_ptr<const hlod::Scene> (the seed of
// the pipeline document to come); the viewport and the tree model only show it.
// Loading runs on a worker thread (widgets::SceneLoader); failures go to a message box and the
// log, and the previous scene stays open.
// Screenshot mode (--screenshot) waits until the scene is loaded and rendered, saves the image
// and quits with exit code 0, or 1 with a message on stderr when loading or saving fails, or 2
// without OpenGL (after saving the window as it looks then).
#pragma once

#include <chrono>
#include <memory>

#include <QMainWindow>
#include <QStringList>

#include "RecentScenes.h"
#include "pipeline/scene/Scene.h"

class QLabel;
class QMenu;
class QProgressBar;
class QTreeView;

namespace hlod::widgets {
struct LoadedScene;
class LogView;
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

    // Opens files or folders as one scene; an empty list opens the embedded sample scene.
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

    hlod::widgets::Viewport* viewport() const { return viewport_; }
    const std::shared_ptr<const hlod::Scene>& scene() const { return scene_; }

protected:
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;
    void closeEvent(QCloseEvent* event) override;

private:
    void createActions();
    void createDocks();
    void createStatusBar();
    void rebuildRecentMenu();

    void openDialog();
    void openFolderDialog();
    void showAbout();

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

    std::shared_ptr<const hlod::Scene> scene_;
    QStringList sceneFiles_; // what scene_ was opened from; empty for the sample

    hlod::widgets::Viewport* viewport_ = nullptr; // null without OpenGL
    hlod::widgets::SceneTreeModel* treeModel_ = nullptr;
    hlod::widgets::SceneLoader* loader_ = nullptr;
    hlod::widgets::LogView* log_ = nullptr;
    QTreeView* tree_ = nullptr;
    QLabel* counts_ = nullptr;
    QLabel* busyLabel_ = nullptr;
    QProgressBar* busyBar_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QMenu* viewMenu_ = nullptr;
    QString glProblem_;

    RecentScenes recent_;
    bool writeSettings_ = true;
    QString screenshotPath_;
    bool screenshotViewportOnly_ = false;
    bool firstFramePending_ = false;
    double initialAzimuth_ = 0.0;
    double initialElevation_ = 0.0;
    std::chrono::steady_clock::time_point shownAt_;
};
