// The comparison parts of the main window (see MainWindow.h): View ▸ Compare Configurations
// opens a widgets::CompareView window over the open scene (left = the document's settings,
// right = AABB k=2, or sphere when the document uses AABB), starting from the editor's camera.
// The window follows the editor: a new scene is compared instead (with the same two
// configurations), a document change rebuilds the sides whose settings it changes, and "Use
// These Settings" edits the document through its undo stack. Closing the window cancels its
// builds; reopening it on the same scene keeps its results.
// Command line: --compare LEFT:RIGHT opens it once the scene has loaded; with --screenshot it
// saves the comparison window (not the main window) when both sides are built, exit code 1
// when a side fails.
#include "MainWindow.h"

#include <QAction>
#include <QLabel>
#include <QMenu>
#include <QTimer>
#include <QWindow>

#include "widgets/LogView.h"
#include "widgets/StudioModel.h"
#include "widgets/Viewport.h"
#include "widgets/compare/ComparePane.h"
#include "widgets/compare/CompareView.h"
#include "widgets/doc/ProjectSession.h"

using hlod::widgets::ComparePane;
using hlod::widgets::CompareView;

void MainWindow::addCompareActions(QMenu* view) {
    view->addSeparator();
    compareAction_ =
        view->addAction(tr("&Compare Configurations…"), this, &MainWindow::showCompare);
    compareAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_C));
    compareAction_->setStatusTip(tr("Build two configurations of this scene (e.g. sphere and "
                                    "AABB k=2) and compare them side by side with linked "
                                    "cameras and statistics"));
    compareAction_->setEnabled(false);
    // Deferred: the scene arrives before the document of a new scene is made (onLoaded).
    connect(model_, &hlod::widgets::StudioModel::sceneChanged, this,
            [this] { QTimer::singleShot(0, this, &MainWindow::onCompareSceneChanged); });
    connect(session_, &hlod::widgets::ProjectSession::documentChanged, this, [this] {
        // A hidden comparison catches up when shown again (showCompare).
        if (compare_ && compare_->isVisible() && compare_->scene())
            compare_->setBaseSettings(session_->settings());
    });
}

void MainWindow::setStartupCompare(const QString& spec) { compareSpec_ = spec; }

void MainWindow::createCompareView() {
    compare_ = new CompareView(this);
    compare_->setWindowFlag(Qt::Window);
    compare_->setUndo(session_->undo());
    connect(compare_, &CompareView::settingsUsed, this, [this](const QString& label) {
        log_->info(tr("The document now uses %1 (from the comparison)").arg(label));
    });
    for (ComparePane* pane : {compare_->left(), compare_->right()})
        connect(pane, &ComparePane::stateChanged, this, [this, pane] {
            const bool left = pane == compare_->left();
            if (pane->state() == ComparePane::State::Failed)
                log_->error(tr("Comparison, %1 side: %2")
                                .arg(left ? tr("left") : tr("right"), pane->statusLabel()->text()));
        });
}

void MainWindow::showCompare() {
    if (!viewport_ || !scene()) return;
    if (!compare_) createCompareView();
    const bool fresh = compare_->scene() != scene();
    if (fresh)
        compare_->open(scene(), session_->settings(),
                       hlod::widgets::defaultConfigs(session_->settings()));
    else
        compare_->setBaseSettings(session_->settings()); // rebuilds the sides it changes
    if (!fresh && !compare_->allBuilt() && !compare_->building())
        compare_->rebuildAll(); // closed mid-build earlier
    compare_->setWindowTitle(
        tr("Compare Configurations — %1").arg(windowTitle().remove(QStringLiteral("[*]"))));
    compare_->show();
    compare_->raise();
    compare_->activateWindow();
    if (fresh) compare_->copyCamera(viewport_->camera());
}

void MainWindow::onCompareSceneChanged() {
    compareAction_->setEnabled(viewport_ && scene());
    if (!compareSpec_.isEmpty() && !compareStarted_ && scene()) {
        openStartupCompare();
        return;
    }
    if (!compare_ || compare_->scene() == scene()) return;
    if (compare_->isVisible() && scene()) {
        // Compare the new scene with the same two configurations, from the editor's view.
        compare_->open(scene(), session_->settings(),
                       {compare_->left()->config(), compare_->right()->config()});
        compare_->copyCamera(viewport_->camera());
    } else {
        compare_->open(nullptr, session_->settings(),
                       {compare_->left()->config(), compare_->right()->config()});
    }
}

void MainWindow::openStartupCompare() {
    compareStarted_ = true;
    if (!viewport_) {
        if (!screenshotPath_.isEmpty()) exitScreenshotMode(2, glProblem_);
        return;
    }
    std::pair<hlod::widgets::CompareConfig, hlod::widgets::CompareConfig> configs;
    QString error;
    if (!hlod::widgets::parseConfigPair(compareSpec_, session_->settings(), configs, &error)) {
        log_->error(error);
        if (!screenshotPath_.isEmpty()) exitScreenshotMode(2, error);
        return;
    }
    if (!compare_) createCompareView();
    if (!screenshotPath_.isEmpty()) {
        compare_->resize(size()); // --size sets the picture's size
        connect(compare_, &CompareView::buildsFinished, this,
                [this] { takeCompareScreenshot(100); });
        for (ComparePane* pane : {compare_->left(), compare_->right()})
            connect(pane, &ComparePane::stateChanged, this, [this, pane] {
                if (pane->state() == ComparePane::State::Failed ||
                    pane->state() == ComparePane::State::Cancelled)
                    exitScreenshotMode(1, pane->statusLabel()->text());
            });
    }
    compare_->open(scene(), session_->settings(), configs);
    compare_->setWindowTitle(
        tr("Compare Configurations — %1").arg(windowTitle().remove(QStringLiteral("[*]"))));
    compare_->show();
    compare_->copyCamera(viewport_->camera());
    log_->info(tr("Comparing %1 with %2")
                   .arg(hlod::widgets::configLabel(configs.first, true),
                        hlod::widgets::configLabel(configs.second, true)));
}

void MainWindow::takeCompareScreenshot(int attemptsLeft) {
    const bool exposed = compare_->windowHandle() && compare_->windowHandle()->isExposed();
    if (!exposed && attemptsLeft > 0) {
        QTimer::singleShot(50, this,
                           [this, attemptsLeft] { takeCompareScreenshot(attemptsLeft - 1); });
        return;
    }
    // Laid out at its final size now: look at the whole scene in the panes' own aspect.
    compare_->fitView();
    for (ComparePane* pane : {compare_->left(), compare_->right()})
        pane->viewport()->grabFrame(); // renders: the preview and the table follow the camera
    const QImage image = compare_->grab().toImage();
    if (image.isNull() || !image.save(screenshotPath_)) {
        exitScreenshotMode(1, tr("%1: could not write the image").arg(screenshotPath_));
        return;
    }
    exitScreenshotMode(0, {});
}
