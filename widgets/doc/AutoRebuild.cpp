// Rebuilds after document changes (see AutoRebuild.h).
#include "widgets/doc/AutoRebuild.h"

#include "widgets/StudioModel.h"
#include "widgets/doc/ProjectSession.h"

namespace hlod::widgets {

AutoRebuild::AutoRebuild(ProjectSession* session, StudioModel* model, QObject* parent)
    : QObject(parent), session_(session), model_(model) {
    timer_.setSingleShot(true);
    timer_.setInterval(kDefaultDelayMs);
    connect(&timer_, &QTimer::timeout, this, &AutoRebuild::fire);
    connect(session_, &ProjectSession::documentChanged, this, &AutoRebuild::onDocumentChanged);
    // StudioModel::build() copies the document's settings before it starts: those are built.
    connect(model_, &StudioModel::buildStarted, this, [this] { requested_ = model_->settings(); });
    connect(model_, &StudioModel::sceneChanged, this, [this] {
        timer_.stop();
        requested_.reset();
    });
}

bool AutoRebuild::settingsChanged() const {
    const HlodSettings* built = nullptr;
    if (requested_)
        built = &*requested_;
    else if (model_->hasBuild())
        built = &model_->built().build->settings;
    if (!built) return false;
    const HlodSettings wanted = session_->settings();
    return !sameClustering(wanted, *built) || !sameBaking(wanted, *built);
}

void AutoRebuild::onDocumentChanged() {
    if (session_->replacing() || !model_->scene() || !settingsChanged()) {
        timer_.stop();
        return;
    }
    timer_.start();
    Q_EMIT rebuildScheduled();
}

void AutoRebuild::fire() {
    if (session_->replacing() || !model_->scene() || !settingsChanged()) return;
    model_->build();
}

} // namespace hlod::widgets
