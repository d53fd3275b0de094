// Keeps the scene tree, the cluster tree and the StudioModel's selection in step: choosing a
// row in either tree selects its instances in the model (and so highlights them in the
// viewport); a selection made elsewhere (a click in the viewport) selects and reveals the
// matching rows, or clears a tree that has no row for it.
// It holds no selection of its own: the model is the one source; a guard stops the echo.
// Multi-selection: a Ctrl- or Shift-click in the Clusters tree passes all its selected rows to
// the model (StudioModel::setSelection; the clicked row is the current one), so the viewport
// highlights every selected cluster and the hand edits act on them (ClusterEditActions reads
// the tree's selection). In the Scene tree the clicked row is the model's selection and the
// tree's other selected rows stay. A selection made elsewhere replaces the rows of both trees
// (the Clusters tree selects every cluster node of the model's selection).
#pragma once

#include <QObject>

class QTreeView;

namespace hlod::widgets {

class ClusterTreeModel;
class SceneTreeModel;
class StudioModel;

class SelectionSync : public QObject {
    Q_OBJECT
public:
    // The views must already show `sceneModel` and `clusterModel`.
    SelectionSync(StudioModel* model, QTreeView* sceneTree, SceneTreeModel* sceneModel,
                  QTreeView* clusterTree, ClusterTreeModel* clusterModel,
                  QObject* parent = nullptr);

    // Shows the model's selection in both trees (also after a tree model was reset).
    void showModelSelection();

private:
    void onTreeCurrentChanged(QTreeView* view);

    StudioModel* model_;
    QTreeView* sceneTree_;
    SceneTreeModel* sceneModel_;
    QTreeView* clusterTree_;
    ClusterTreeModel* clusterModel_;
    bool syncing_ = false;
    QTreeView* userTree_ = nullptr; // the tree whose click is being passed to the model
};

} // namespace hlod::widgets
