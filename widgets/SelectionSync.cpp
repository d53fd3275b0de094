// Two-way selection between the trees and the model (see SelectionSync.h).
#include "widgets/SelectionSync.h"

#include <vector>

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
    // Qt moves the current row before it updates the selection of a click: follow both.
    for (QTreeView* view : {sceneTree_, clusterTree_}) {
        connect(view->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
                [this, view] { onTreeCurrentChanged(view); });
        connect(view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
                [this, view] { onTreeCurrentChanged(view); });
    }
    for (QAbstractItemModel* m : {static_cast<QAbstractItemModel*>(sceneModel_),
                                  static_cast<QAbstractItemModel*>(clusterModel_)})
        connect(m, &QAbstractItemModel::modelReset, this, &SelectionSync::showModelSelection);
}

void SelectionSync::showModelSelection() {
    const StudioSelection& s = model_->selection();
    syncing_ = true;
    auto show = [this](QTreeView* view, const QModelIndex& index, const QItemSelection& rows) {
        // The clicked tree already shows the user's rows (one or several): keep them.
        if (view == userTree_) return;
        if (!index.isValid()) {
            view->selectionModel()->clear();
            return;
        }
        view->selectionModel()->setCurrentIndex(index, QItemSelectionModel::ClearAndSelect |
                                                           QItemSelectionModel::Rows);
        if (!rows.isEmpty())
            view->selectionModel()->select(rows,
                                           QItemSelectionModel::Select | QItemSelectionModel::Rows);
        view->scrollTo(index);
    };
    show(sceneTree_, sceneModel_->indexOfNode(s.sceneNode), {});
    QItemSelection clusterRows;
    for (Id node : s.clusterNodes) {
        const QModelIndex row = clusterModel_->indexOfNode(node);
        if (row.isValid()) clusterRows.select(row, row);
    }
    show(clusterTree_, clusterModel_->indexOfNode(s.clusterNode), clusterRows);
    syncing_ = false;
}

void SelectionSync::onTreeCurrentChanged(QTreeView* view) {
    if (syncing_) return;
    QModelIndex current = view->selectionModel()->currentIndex();
    // A model reset clears the current row: that is not the user choosing nothing.
    if (!current.isValid()) return;
    userTree_ = view;
    // A Ctrl-click that deselects the current row: the model shows another selected row.
    if (!view->selectionModel()->isSelected(current)) {
        const QModelIndexList rows = view->selectionModel()->selectedIndexes();
        current = rows.isEmpty() ? QModelIndex() : rows.front();
    }
    if (!current.isValid()) {
        model_->clearSelection();
    } else if (view == sceneTree_) {
        model_->selectSceneNode(sceneModel_->nodeOf(current));
    } else {
        std::vector<Id> nodes;
        // Any selected cell counts (a row may be selected in its first column only).
        for (const QModelIndex& cell : view->selectionModel()->selectedIndexes())
            nodes.push_back(clusterModel_->nodeOf(cell));
        model_->setSelection(nodes, clusterModel_->nodeOf(current));
    }
    userTree_ = nullptr;
}

} // namespace hlod::widgets
