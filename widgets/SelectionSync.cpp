// Two-way selection between the trees and the model (see SelectionSync.h).
#include "widgets/SelectionSync.h"

#include <QItemSelectionModel>
#include <QTreeView>

#include "widgets/ClusterTreeModel.h"
#include "widgets/SceneTreeModel.h"
#include "widgets/StudioModel.h"

namespace hlod::widgets {

SelectionSync::SelectionSync(StudioModel* model, QTreeView* sceneTree, SceneTreeModel* sceneModel,
                             QTreeView* clusterTree, ClusterTreeModel* clusterModel,
                             QObject* parent)
    : QObject(parent), model_(model), sceneTree_(sceneTree), sceneModel_(sceneModel),
      clusterTree_(clusterTree), clusterModel_(clusterModel) {
    connect(model_, &StudioModel::selectionChanged, this, &SelectionSync::showModelSelection);
    for (QTreeView* view : {sceneTree_, clusterTree_})
        connect(view->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
                [this, view] { onTreeCurrentChanged(view); });
    for (QAbstractItemModel* m : {static_cast<QAbstractItemModel*>(sceneModel_),
                                  static_cast<QAbstractItemModel*>(clusterModel_)})
        connect(m, &QAbstractItemModel::modelReset, this, &SelectionSync::showModelSelection);
}

void SelectionSync::showModelSelection() {
    const StudioSelection& s = model_->selection();
    syncing_ = true;
    auto show = [](QTreeView* view, const QModelIndex& index) {
        if (!index.isValid()) {
            view->selectionModel()->clear();
            return;
        }
        view->selectionModel()->setCurrentIndex(index, QItemSelectionModel::ClearAndSelect |
                                                           QItemSelectionModel::Rows);
        view->scrollTo(index);
    };
    show(sceneTree_, sceneModel_->indexOfNode(s.sceneNode));
    show(clusterTree_, clusterModel_->indexOfNode(s.clusterNode));
    syncing_ = false;
}

void SelectionSync::onTreeCurrentChanged(QTreeView* view) {
    if (syncing_) return;
    const QModelIndex current = view->selectionModel()->currentIndex();
    // A model reset clears the current row: that is not the user choosing nothing.
    if (!current.isValid()) return;
    if (view == sceneTree_)
        model_->selectSceneNode(sceneModel_->nodeOf(current));
    else
        model_->selectClusterNode(clusterModel_->nodeOf(current));
}

} // namespace hlod::widgets
