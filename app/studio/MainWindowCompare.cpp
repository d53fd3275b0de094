// The comparison parts of the main window (see MainWindow.h): View ▸ Compare Configurations
// opens a widgets::CompareView window over the open scene (left = the shown branch; right =
// another branch of the document when there is one, else AABB k=2 over the shown branch, or
// sphere when it uses AABB, as a temporary branch), starting from the editor's camera.
// The window follows the editor: a new scene is compared instead (with the same two sides where
// the new document has them), a document change rebuilds the sides it changes, and "Use These
// Settings" edits the document through its undo stack. Closing the window cancels its builds;
// reopening it on the same scene keeps its results.
// Command line: --compare LEFT:RIGHT opens it once the scene has loaded (#N names Bake node N);
// with --screenshot it saves the comparison window (not the main window) when both sides are
// built, exit code 1 when a side fails.
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
    compareAction_->setStatusTip(tr("Compare two branches of this scene (two Bake nodes, or one "
                                    "and a quick configuration such as AABB k=2) side by side "
                                    "with linked cameras and statistics"));
    compareAction_->setEnabled(false);
    // Deferred: the scene arrives before the document of a new scene is made (onLoaded).
    connect(model_, &hlod::widgets::StudioModel::sceneChanged, this,
            [this] { QTimer::singleShot(0, this, &MainWindow::onCompareSceneChanged); });
    connect(session_, &hlod::widgets::ProjectSession::documentChanged, this, [this] {
        // A hidden comparison catches up when shown again (showCompare).
        if (compare_ && compare_->isVisible() && compare_->scene()) compare_->documentChanged();
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
    hlod::PipelineGraph* graph = &session_->document().graph();
    if (fresh)
        compare_->open(
            scene(), graph, model_->shownBake(),
            hlod::widgets::defaultSides(*graph, model_->shownBake(), model_->bakeNodes()));
    else
        compare_->documentChanged(); // rebuilds the sides it changes
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
    hlod::PipelineGraph* graph = &session_->document().graph();
    // The same two sides where the new document has them (a Bake node that is gone becomes its
    // configuration over the shown branch).
    auto keep = [graph](hlod::widgets::CompareSide side) {
        if (side.bake != hlod::kNoNode &&
            (!graph->hasNode(side.bake) || graph->node(side.bake).kind != hlod::NodeKind::Bake))
            side.bake = hlod::kNoNode;
        return side;
    };
    const std::pair<hlod::widgets::CompareSide, hlod::widgets::CompareSide> sides{
        keep(compare_->left()->side()), keep(compare_->right()->side())};
    if (compare_->isVisible() && scene()) {
        // Compare the new scene with the same two sides, from the editor's view.
        compare_->open(scene(), graph, model_->shownBake(), sides);
        compare_->copyCamera(viewport_->camera());
    } else {
        compare_->open(nullptr, graph, model_->shownBake(), sides);
    }
}

void MainWindow::openStartupCompare() {
    compareStarted_ = true;
    if (!viewport_) {
        if (!screenshotPath_.isEmpty()) exitScreenshotMode(2, glProblem_);
        return;
    }
    hlod::PipelineGraph* graph = &session_->document().graph();
    std::pair<hlod::widgets::CompareSide, hlod::widgets::CompareSide> sides;
    QString error;
    bool ok = hlod::widgets::parseSidePair(
        compareSpec_, hlod::widgets::configOf(*graph, model_->shownBake()), sides, &error);
    for (hlod::widgets::CompareSide* side : {&sides.first, &sides.second}) {
        if (!ok || side->bake == hlod::kNoNode) continue;
        if (!graph->hasNode(side->bake) || graph->node(side->bake).kind != hlod::NodeKind::Bake) {
            error = tr("--compare: the document has no Bake node #%1").arg(side->bake);
            ok = false;
        }
    }
    if (!ok) {
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
    compare_->open(scene(), graph, model_->shownBake(), sides);
    compare_->setWindowTitle(
        tr("Compare Configurations — %1").arg(windowTitle().remove(QStringLiteral("[*]"))));
    compare_->show();
    compare_->copyCamera(viewport_->camera());
    log_->info(tr("Comparing %1 with %2")
                   .arg(compare_->left()->label(true), compare_->right()->label(true)));
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
