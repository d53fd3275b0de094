// Hand edits of clusters (issue #7) from the "Clusters" tab and the viewport: Merge, Split,
// Lock, Unlock, Exclude from HLOD and Include in HLOD on the selected clusters (a context menu on
// the tree rows and on the viewport), and Move: by dragging rows onto another cluster in the tree
// (ClusterTreeModel::moveRequested), or with "Move to Cluster" in the menu, which moves the
// other selected rows into the current one (the row clicked last; a right click on a selected
// row, in the tree or on its cluster in the viewport, makes it current and keeps the
// selection). Both go through moveTo and refuse what a drop refuses (acceptsMove).
// Each is one document command (Commands.h: MergeClusters, LockCluster, UnlockCluster,
// ExcludeInstance, IncludeInstance, MoveToCluster; SplitClusterOfTree for splits) executed through
// the UndoAdapter, so it is undoable; the rebuild that follows every change of the hand edits (undo
// and redo included) is AutoRebuild's. Clusters are named by their leaf sets in the current build
// (HandEdits.h), so the actions need a build; without one (or while one runs) they are disabled.
//
// Enabled only when they apply (issue 20 #7), kept current on every selection, build and
// document change so their shortcuts (issue 20 #9, window-wide, shown in the menus and the
// context menu) act only then: Merge (Ctrl+G) two or more clusters, neither the root nor one
// inside another; Split (Ctrl+Shift+G) a cluster below the root; Lock (Ctrl+L) a cluster below
// the root that is not locked; Unlock (Ctrl+Shift+L) a cluster that is a locked group; Exclude
// (Ctrl+Shift+X) meshes not yet excluded (not the root); Include (Ctrl+Shift+I) excluded meshes;
// Move to Cluster (Ctrl+M) when a drop would be accepted. None without a build or during one.
//
// Selection: the tree's selected rows are the clusters the actions act on; the tree allows
// extended selection (Ctrl/Shift-click; SelectionSync keeps the extra rows). In the viewport
// (attachViewport), Ctrl+click adds the cluster under the cursor to those rows (or removes it
// when it is already selected) and a right click without dragging opens the same menu for the
// cluster under the cursor (the selection stays when that cluster is part of it). "The cluster
// under the cursor" is what a click selects (DisplayController::pickAt: the mesh's leaf, or the
// drawn cluster of the HLOD preview); in Clusters mode it is the coloured cluster of the shown
// level holding that mesh.
#pragma once

#include <vector>

#include <QObject>
#include <QPoint>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/graph/HandEdits.h"

class QAction;
class QMenu;
class QTreeView;

namespace hlod::widgets {

class ClusterTreeModel;
class DisplayController;
class ProjectSession;
class StudioModel;
class Viewport;

class ClusterEditActions : public QObject {
    Q_OBJECT
public:
    ClusterEditActions(ProjectSession* session, StudioModel* model, QTreeView* tree,
                       ClusterTreeModel* treeModel, QObject* parent = nullptr);

    // Ctrl+click and the context menu in the viewport (both may be null: nothing happens).
    void attachViewport(Viewport* viewport, DisplayController* display);

    QAction* mergeAction() const { return merge_; }
    QAction* splitAction() const { return split_; }
    QAction* lockAction() const { return lock_; }
    QAction* unlockAction() const { return unlock_; }
    QAction* excludeAction() const { return exclude_; }
    QAction* includeAction() const { return include_; }
    QAction* moveAction() const { return move_; }
    QList<QAction*> actions() const;
    // The leaf sets of the selected rows (sorted by first instance).
    std::vector<InstanceSet> selectedClusters() const;
    // The cluster nodes of the selected rows in the current build (ascending).
    std::vector<Id> selectedNodes() const;
    // Enables the actions for the current selection and build.
    void updateActions();
    // Fills `menu` with the actions (enabled for the current selection).
    void fillMenu(QMenu* menu);

    bool merge();
    bool split();
    bool lock();
    bool unlock();
    bool exclude();
    bool include();
    // Moves `items` (leaf sets) into the cluster `target` (a leaf set).
    bool moveTo(const std::vector<InstanceSet>& items, const InstanceSet& target);
    // "Move to Cluster": moves the selected rows other than the current row into the current
    // row's cluster, when a drop of those rows onto it would be accepted.
    bool moveToCurrent();

    // Viewport gestures at `pos` (viewport coordinates); public for tests. The node the gesture
    // picked, kNoId when nothing is under the cursor.
    Id toggleAt(const QPoint& pos);
    Id selectForMenuAt(const QPoint& pos);

Q_SIGNALS:
    void failed(const QString& message);

private:
    void showTreeMenu(const QPoint& pos);
    void showViewportMenu(const QPoint& pos);
    Id pickCluster(const QPoint& pos);
    void selectRows(const std::vector<Id>& nodes, Id current);
    InstanceSet excludedInSelection() const;
    // The leaf sets "Move to Cluster" would move and its target; false when it cannot.
    bool moveToCurrentSets(std::vector<InstanceSet>& items, InstanceSet& target) const;

    ProjectSession* session_;
    StudioModel* model_;
    QTreeView* tree_;
    ClusterTreeModel* treeModel_;
    Viewport* viewport_ = nullptr;
    DisplayController* display_ = nullptr;
    QAction* merge_ = nullptr;
    QAction* split_ = nullptr;
    QAction* lock_ = nullptr;
    QAction* unlock_ = nullptr;
    QAction* exclude_ = nullptr;
    QAction* include_ = nullptr;
    QAction* move_ = nullptr;
};

} // namespace hlod::widgets
