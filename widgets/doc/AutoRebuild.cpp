// Reruns after document changes (see AutoRebuild.h).
#include "widgets/doc/AutoRebuild.h"

#include "widgets/StudioModel.h"
#include "widgets/doc/ProjectSession.h"

namespace hlod::widgets {

AutoRebuild::AutoRebuild(ProjectSession* session, StudioModel* model, QObject* parent)
    : QObject(parent), session_(session), model_(model) {
    timer_.setSingleShot(true);
    timer_.setInterval(kDefaultDelayMs);
    connect(&timer_, &QTimer::timeout, this, &AutoRebuild::fire);
    connect(session_, &ProjectSession::documentChanged, this, &AutoRebuild::onChange);
    connect(model_, &StudioModel::shownBakeChanged, this, &AutoRebuild::onChange);
    connect(model_, &StudioModel::sceneChanged, this, [this] { timer_.stop(); });
}

bool AutoRebuild::shownNeedsRun() const {
    const PipelineGraph* g = model_->graph();
    const NodeId shown = model_->shownBake();
    if (!g || shown == kNoNode || !g->hasNode(shown)) return false;
    if (g->status(shown) != NodeStatus::Pending) return false;
    // An edited Import node: the window reads the scene again first (MainWindow::reloadScene)
    // and builds once it has.
    const NodeId import = g->upstreamOfKind(shown, NodeKind::Import);
    if (import != kNoNode && g->status(import) != NodeStatus::UpToDate) return false;
    // A run that brings this very node up to date (a node moved meanwhile, another branch
    // edited) would only be thrown away by a new one.
    return !model_->runCovers(shown);
}

void AutoRebuild::onChange() {
    if (session_->replacing() || !model_->scene() || !model_->everBuilt() || !shownNeedsRun()) {
        timer_.stop();
        return;
    }
    timer_.start();
    Q_EMIT rebuildScheduled();
}

void AutoRebuild::fire() {
    if (session_->replacing() || !model_->scene() || !model_->everBuilt() || !shownNeedsRun())
        return;
    if (model_->exporting()) {
        // Packages are being written: a new run would drop that one. Look again later.
        timer_.start();
        return;
    }
    model_->build();
}

} // namespace hlod::widgets
