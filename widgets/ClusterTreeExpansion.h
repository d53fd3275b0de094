// Keeps the rows of the Clusters tree expanded across rebuilds (issue 20 #4): every edit, undo
// or parameter change gives a new tree (new node ids, a model reset), which would collapse the
// tree and lose the artist's place. Before the model resets, the identities (leaf sets,
// ClusterIdentity.h) of the expanded rows are noted; after, the rows of the new tree with those
// identities are expanded again. A cluster an edit changed (other meshes) is a new cluster and
// starts collapsed; the selection is made visible by SelectionSync.
#pragma once

#include <vector>

#include <QObject>

#include "widgets/ClusterIdentity.h"

class QModelIndex;
class QTreeView;

namespace hlod::widgets {

class ClusterTreeModel;

class ClusterTreeExpansion : public QObject {
    Q_OBJECT
public:
    // `view` must show `model`.
    ClusterTreeExpansion(QTreeView* view, ClusterTreeModel* model, QObject* parent = nullptr);

    // The identities of the rows now expanded.
    std::vector<ClusterKey> expandedKeys() const;

private:
    void collect(const QModelIndex& parent, std::vector<ClusterKey>& out) const;

    QTreeView* view_;
    ClusterTreeModel* model_;
    std::vector<ClusterKey> remembered_;
};

} // namespace hlod::widgets
