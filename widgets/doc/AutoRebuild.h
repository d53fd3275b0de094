// Reruns the shown branch when the document changes (issue #7: "changing a parameter reruns
// only what is downstream, reusing the bake cache"; "proxies of edited clusters are rebaked, the
// rest reused"; issue 29: the editor runs the document's graph).
//
// After every document change (a parameter edit, a hand edit, a graph edit, an undo, a redo)
// and whenever another Bake node is shown, the shown Bake node's status in the graph is looked
// at: when it is Pending (the change reached it, or it was never built), a run of it starts
// after delay() ms; further changes within the delay restart the timer, so a slider drag or a
// burst of edits is one run. What the run then redoes is the graph's business: only the Pending
// nodes upstream of the shown one run, and the baker takes every unchanged proxy from the disk
// cache. A change that does not reach the shown branch (another branch's parameter) starts
// nothing.
// A run that writes packages (File ▸ Export) is not interrupted: the rebuild waits for it.
// Nothing is built before the scene's first build (StudioModel::everBuilt), nor for a document
// being replaced (new, open: the scene reloads). A failed run is not retried until a change
// makes the node Pending again; a cancelled one waits for the next change.
#pragma once

#include <QObject>
#include <QTimer>

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
    // Whether the shown Bake node needs a run (Pending in the graph, none running for it).
    bool shownNeedsRun() const;

Q_SIGNALS:
    void rebuildScheduled();

private:
    void onChange();
    void fire();

    ProjectSession* session_;
    StudioModel* model_;
    QTimer timer_;
};

} // namespace hlod::widgets
