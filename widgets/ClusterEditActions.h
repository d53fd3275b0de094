// Hand edits of clusters from the "Clusters" tab (issue #7): a context menu on the selected
// rows of the cluster tree with Merge, Lock, Unlock and Exclude from HLOD. Each is a document
// command (Commands.h: MergeClusters, LockCluster, UnlockCluster, ExcludeInstance) executed
// through the UndoAdapter, so it is undoable; the HLOD is rebuilt afterwards. Undo and redo of
// hand edits rebuild as well (whenever the document's locked groups or exclusions differ from
// those of the current build).
// Clusters are named by their leaf sets in the current build (HandEdits.h), so the actions need
// a build; without one they are disabled. The tree allows extended selection.
#pragma once

#include <vector>

#include <QObject>

#include "pipeline/graph/HandEdits.h"

class QAction;
class QMenu;
class QTreeView;

namespace hlod::widgets {

class ClusterTreeModel;
class ProjectSession;
class StudioModel;

class ClusterEditActions : public QObject {
    Q_OBJECT
public:
    ClusterEditActions(ProjectSession* session, StudioModel* model, QTreeView* tree,
                       ClusterTreeModel* treeModel, QObject* parent = nullptr);

    QAction* mergeAction() const { return merge_; }
    QAction* lockAction() const { return lock_; }
    QAction* unlockAction() const { return unlock_; }
    QAction* excludeAction() const { return exclude_; }
    // The leaf sets of the selected rows (sorted by first instance).
    std::vector<InstanceSet> selectedClusters() const;
    // Enables the actions for the current selection and build.
    void updateActions();

    bool merge();
    bool lock();
    bool unlock();
    bool exclude();

Q_SIGNALS:
    void failed(const QString& message);

private:
    void showMenu(const QPoint& pos);
    void rebuildWhenEditsChanged();

    ProjectSession* session_;
    StudioModel* model_;
    QTreeView* tree_;
    ClusterTreeModel* treeModel_;
    QAction* merge_ = nullptr;
    QAction* lock_ = nullptr;
    QAction* unlock_ = nullptr;
    QAction* exclude_ = nullptr;
};

} // namespace hlod::widgets
