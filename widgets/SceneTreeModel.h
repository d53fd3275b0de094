// Item model over the node hierarchy of an hlod::Scene, for the scene tree dock.
//
// One row per node (the root node is the single top-level row), columns: name, meshes, triangles.
// Counts are for the node's whole subtree (a group node shows what it contains; the tooltip
// also gives the node's own share), computed once when the scene is set.
// The model shows a scene it is given (shared, immutable); it owns no scene state of its own.
#pragma once

#include <memory>
#include <vector>

#include <QAbstractItemModel>

#include "pipeline/scene/Scene.h"

namespace hlod::widgets {

class SceneTreeModel : public QAbstractItemModel {
    Q_OBJECT
public:
    enum Column { NameColumn = 0, MeshesColumn, TrianglesColumn, ColumnCount };
    // Custom role: the node id (hlod::Id) of an index.
    static constexpr int NodeIdRole = Qt::UserRole + 1;

    explicit SceneTreeModel(QObject* parent = nullptr);

    void setScene(std::shared_ptr<const Scene> scene);
    const std::shared_ptr<const Scene>& scene() const { return scene_; }

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    // The index of node `node` in column 0; invalid for unknown ids.
    QModelIndex indexOfNode(Id node) const;
    Id nodeOf(const QModelIndex& index) const;

    struct Counts {
        std::size_t ownMeshes = 0;
        std::size_t ownTriangles = 0;
        std::size_t meshes = 0; // subtree
        std::size_t triangles = 0;
    };
    const Counts& counts(Id node) const { return counts_[node]; }

    // The instances the shown branch's Cluster node excludes from HLOD (sorted): a node whose
    // own meshes are all excluded reads "name (excluded)" (issue 31 #10), one with some of
    // them says how many in its tooltip.
    void setExcluded(std::vector<Id> instances);
    // Own meshes of `node` that are excluded.
    std::size_t excludedMeshes(Id node) const;

private:
    std::shared_ptr<const Scene> scene_;
    std::vector<Counts> counts_;
    std::vector<int> rowInParent_;      // position of each node among its parent's children
    std::vector<std::size_t> excluded_; // per node: own meshes excluded (empty: none)
};

} // namespace hlod::widgets
