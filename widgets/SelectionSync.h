// Keeps the scene tree, the cluster tree and the StudioModel's selection in step: choosing a
// row in either tree selects its instances in the model (and so highlights them in the
// viewport); a selection made elsewhere (a click in the viewport) selects and reveals the
// matching rows, or clears a tree that has no row for it.
// It holds no selection of its own: the model is the one source; a guard stops the echo.
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
};

} // namespace hlod::widgets
