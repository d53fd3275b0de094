// Reruns the HLOD build when the document's build settings change (issue #7: "changing a
// parameter reruns only what is downstream, reusing the bake cache"; "proxies of edited
// clusters are rebaked, the rest reused").
//
// After every document change (a parameter edit, a hand edit, an undo, a redo) the settings the
// document gives (settingsOf: parameters and hand edits) are compared with those of the last
// build the model started, or, before any, of the build it shows. When they differ, a build
// starts after delay() ms; further changes within the delay restart it, so a slider drag or a
// burst of edits is one build, and a change back to the built settings cancels it. What the
// build then redoes is HlodBuilder's business: the tree is reused when only bake parameters
// changed, and the baker takes every unchanged proxy from the disk cache.
// Nothing is built before the scene's first build (none shown and none started), nor for a
// document being replaced (new, open: the scene reloads). A failed or cancelled build is not
// retried until the settings change again.
#pragma once

#include <optional>

#include <QObject>
#include <QTimer>

#include "pipeline/doc/HlodBuild.h"

namespace hlod::widgets {

class ProjectSession;
class StudioModel;

class AutoRebuild : public QObject {
    Q_OBJECT
public:
    static constexpr int kDefaultDelayMs = 300;

    AutoRebuild(ProjectSession* session, StudioModel* model, QObject* parent = nullptr);

    void setDelay(int ms) { timer_.setInterval(ms); }
    int delay() const { return timer_.interval(); }
    // A rebuild is scheduled and has not started yet.
    bool pending() const { return timer_.isActive(); }
    // Whether the document's settings differ from the last build's (started or shown).
    bool settingsChanged() const;

Q_SIGNALS:
    void rebuildScheduled();

private:
    void onDocumentChanged();
    void fire();

    ProjectSession* session_;
    StudioModel* model_;
    QTimer timer_;
    std::optional<HlodSettings> requested_; // settings of the last build started
};

} // namespace hlod::widgets
