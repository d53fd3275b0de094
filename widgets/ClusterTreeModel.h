// Item model over the cluster tree of an HLOD build, for the "Clusters" tab of the scene dock.
//
// One row per cluster node (the root is the single top-level row), children in tree order.
// Columns, what matters first (issue 20 #5): name (inner nodes "Cluster N" with N the cluster's
// label, stable across rebuilds (ClusterIdentity.h), locked ones marked; leaves the name of the
// scene node holding the instance), original triangles of the subtree (instanced), proxy
// triangles (inner nodes; leaves draw their original mesh and show none), level (0 = leaf) and
// the size: the diameter of the bounding volume of the tree's volume type (the sphere for
// sphere trees, the box's diagonal otherwise), a length with its unit; the tooltip also gives
// that volume. Numbers are formatted for reading (NumberFormat.h), never in scientific
// notation; ValueRole gives the raw number (scene units for the size).
// The model shows a build it is given (shared, immutable); it owns no pipeline state.
//
// Drag and drop (the "move" hand edit of issue #7): rows below the root can be dragged (meshes
// and clusters) and dropped onto an inner cluster below the root. The model never moves rows
// itself: a drop emits moveRequested(items, target) with the leaf sets of the dragged rows and
// of the target (HandEdits.h names clusters by leaf set), the owner turns it into a
// MoveToCluster command and the rebuild shows the result. Refused drops: onto the root (that
// would lock the whole scene), a leaf, a dragged row or a row inside one, or the cluster every
// dragged row already hangs from. The payload (kMimeType) is JSON: an array of leaf sets.
#pragma once

#include <memory>
#include <unordered_map>
#include <vector>

#include <QAbstractItemModel>

#include "pipeline/graph/HandEdits.h"
#include "pipeline/graph/PipelineGraph.h"
#include "pipeline/scene/Scene.h"
#include "widgets/ClusterIdentity.h"

namespace hlod::widgets {

class ClusterTreeModel : public QAbstractItemModel {
    Q_OBJECT
public:
    enum Column {
        NameColumn = 0,
        TrianglesColumn,
        ProxyTrianglesColumn,
        LevelColumn,
        SizeColumn,
        ColumnCount
    };
    // Custom roles: the cluster node id (hlod::Id) of an index; the raw number of a column.
    static constexpr int NodeIdRole = Qt::UserRole + 1;
    static constexpr int ValueRole = Qt::UserRole + 2;

    explicit ClusterTreeModel(QObject* parent = nullptr);

    // Shows `build` of `scene`; null clears the model. `labels` (StudioModel::clusterLabels):
    // the number each cluster is called by; empty: its node id.
    void setBuild(std::shared_ptr<const Scene> scene, std::shared_ptr<const NodeOutput> build,
                  std::vector<int> labels = {});

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    QModelIndex indexOfNode(Id node) const;
    Id nodeOf(const QModelIndex& index) const;
    // The identity of a row's cluster (ClusterIdentity.h) and the row of an identity (invalid
    // when the shown tree has no such cluster): what keeps rows expanded across rebuilds.
    ClusterKey keyOf(const QModelIndex& index) const;
    QModelIndex indexOfKey(ClusterKey key) const;
    // The leaf set (sorted instance ids) below a node of the shown tree; empty when unknown.
    InstanceSet leafSetOf(Id node) const;
    // Whether moving `items` into `target` (leaf sets of the shown tree) is a drop this model
    // accepts (see the rules above).
    bool acceptsMove(const std::vector<InstanceSet>& items, const InstanceSet& target) const;

    static constexpr const char* kMimeType = "application/x-hlod-cluster-sets";
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    Qt::DropActions supportedDragActions() const override { return Qt::MoveAction; }
    Qt::DropActions supportedDropActions() const override { return Qt::MoveAction; }
    QStringList mimeTypes() const override;
    QMimeData* mimeData(const QModelIndexList& indexes) const override;
    bool canDropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                         const QModelIndex& parent) const override;
    bool dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                      const QModelIndex& parent) override;

    // Values shown for a node (also used by tests). name: the full label, "Cluster 12
    // (locked)", "wheel (excluded)" (the tooltip's and ValueRole's); shownName: the name
    // column's text, where a locked cluster's mark is the row's lock icon instead (short
    // enough for the dock's width).
    QString name(Id node) const;
    QString shownName(Id node) const;
    // Whether the shown build's Cluster node excludes `instance` (a hand edit).
    bool excluded(Id instance) const;
    double volume(Id node) const; // cubic scene units
    double size(Id node) const;   // scene units

Q_SIGNALS:
    // A drop asked to move `items` (leaf sets) into the cluster `target` (a leaf set).
    void moveRequested(const std::vector<hlod::InstanceSet>& items,
                       const hlod::InstanceSet& target);

private:
    // The dragged leaf sets in `data` and the cluster a drop at (row, parent) lands on.
    bool decodeDrop(const QMimeData* data, const QModelIndex& parent,
                    std::vector<InstanceSet>& items, InstanceSet& target) const;

    std::shared_ptr<const Scene> scene_;
    std::shared_ptr<const NodeOutput> build_;
    std::vector<std::uint64_t> triangles_;
    std::vector<int> rowInParent_;
    std::vector<int> labels_;
    std::vector<ClusterKey> keys_;
    std::unordered_map<ClusterKey, Id> nodeOfKey_;
};

} // namespace hlod::widgets
