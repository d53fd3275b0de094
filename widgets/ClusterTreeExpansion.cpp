// Expanded rows of the Clusters tree kept across rebuilds (see ClusterTreeExpansion.h).
#include "widgets/ClusterTreeExpansion.h"

#include <QTreeView>

#include "widgets/ClusterTreeModel.h"

namespace hlod::widgets {

ClusterTreeExpansion::ClusterTreeExpansion(QTreeView* view, ClusterTreeModel* model,
                                           QObject* parent)
    : QObject(parent), view_(view), model_(model) {
    connect(model_, &QAbstractItemModel::modelAboutToBeReset, this,
            [this] { remembered_ = expandedKeys(); });
    connect(model_, &QAbstractItemModel::modelReset, this, [this] {
        for (ClusterKey key : remembered_) {
            const QModelIndex index = model_->indexOfKey(key);
            if (index.isValid()) view_->expand(index);
        }
        remembered_.clear();
    });
}

std::vector<ClusterKey> ClusterTreeExpansion::expandedKeys() const {
    std::vector<ClusterKey> out;
    collect(QModelIndex(), out);
    return out;
}

void ClusterTreeExpansion::collect(const QModelIndex& parent, std::vector<ClusterKey>& out) const {
    for (int row = 0; row < model_->rowCount(parent); ++row) {
        const QModelIndex index = model_->index(row, 0, parent);
        if (!view_->isExpanded(index)) continue;
        out.push_back(model_->keyOf(index));
        collect(index, out);
    }
}

} // namespace hlod::widgets
