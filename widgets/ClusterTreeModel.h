// Item model over the cluster tree of an HLOD build, for the "Clusters" tab of the scene dock.
//
// One row per cluster node (the root is the single top-level row), children in tree order.
// Columns: name (inner nodes "Cluster N", leaves the name of the scene node holding the
// instance), original triangles of the subtree (instanced), level (0 = leaf), bounding volume
// in cubic metres (of the tree's volume type: the sphere for sphere trees, the box otherwise)
// and proxy triangles (inner nodes; leaves draw their original mesh and show none).
// The model shows a build it is given (shared, immutable); it owns no pipeline state.
#pragma once

#include <memory>
#include <vector>

#include <QAbstractItemModel>

#include "pipeline/doc/HlodBuild.h"
#include "pipeline/scene/Scene.h"

namespace hlod::widgets {

class ClusterTreeModel : public QAbstractItemModel {
    Q_OBJECT
public:
    enum Column {
        NameColumn = 0,
        TrianglesColumn,
        LevelColumn,
        VolumeColumn,
        ProxyTrianglesColumn,
        ColumnCount
    };
    // Custom roles: the cluster node id (hlod::Id) of an index; the raw number of a column.
    static constexpr int NodeIdRole = Qt::UserRole + 1;
    static constexpr int ValueRole = Qt::UserRole + 2;

    explicit ClusterTreeModel(QObject* parent = nullptr);

    // Shows `build` of `scene`; null clears the model.
    void setBuild(std::shared_ptr<const Scene> scene, std::shared_ptr<const HlodBuild> build);

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    QModelIndex indexOfNode(Id node) const;
    Id nodeOf(const QModelIndex& index) const;

    // Values shown for a node (also used by tests).
    QString name(Id node) const;
    double volume(Id node) const;

private:
    std::shared_ptr<const Scene> scene_;
    std::shared_ptr<const HlodBuild> build_;
    std::vector<std::uint64_t> triangles_;
    std::vector<int> rowInParent_;
};

} // namespace hlod::widgets
