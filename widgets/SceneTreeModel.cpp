// Item model over the node hierarchy of an hlod::Scene (see SceneTreeModel.h).
#include "widgets/SceneTreeModel.h"

#include <QLocale>

namespace hlod::widgets {

SceneTreeModel::SceneTreeModel(QObject* parent) : QAbstractItemModel(parent) {}

void SceneTreeModel::setScene(std::shared_ptr<const Scene> scene) {
    beginResetModel();
    scene_ = std::move(scene);
    counts_.clear();
    rowInParent_.clear();
    excluded_.clear();
    if (scene_) {
        const std::size_t n = scene_->nodes.size();
        counts_.assign(n, {});
        rowInParent_.assign(n, 0);
        for (const MeshInstance& instance : scene_->instances) {
            if (instance.node >= n || instance.mesh >= scene_->meshes.size()) continue;
            counts_[instance.node].ownMeshes += 1;
            counts_[instance.node].ownTriangles += scene_->meshes[instance.mesh].triangleCount();
        }
        for (Id node = 0; node < n; ++node) {
            const auto& children = scene_->nodes[node].children;
            for (std::size_t i = 0; i < children.size(); ++i)
                rowInParent_[children[i]] = static_cast<int>(i);
        }
        // Subtree sums without recursion (TORCS-like flat or deep trees alike): walk nodes in
        // an order where children follow parents, then accumulate in reverse.
        // `seen` keeps a malformed hand-built hierarchy (a cycle) from looping forever.
        std::vector<Id> order{0};
        std::vector<char> seen(n, 0);
        seen[0] = 1;
        for (std::size_t i = 0; i < order.size(); ++i)
            for (Id child : scene_->nodes[order[i]].children)
                if (child < n && !seen[child]) {
                    seen[child] = 1;
                    order.push_back(child);
                }
        for (Id node : order) {
            counts_[node].meshes = counts_[node].ownMeshes;
            counts_[node].triangles = counts_[node].ownTriangles;
        }
        for (auto it = order.rbegin(); it != order.rend(); ++it) {
            const Id parent = scene_->nodes[*it].parent;
            if (parent != kNoId && parent < n) {
                counts_[parent].meshes += counts_[*it].meshes;
                counts_[parent].triangles += counts_[*it].triangles;
            }
        }
    }
    endResetModel();
}

void SceneTreeModel::setExcluded(std::vector<Id> instances) {
    std::vector<std::size_t> perNode;
    if (scene_ && !instances.empty()) {
        perNode.assign(scene_->nodes.size(), 0);
        for (Id i : instances)
            if (i < scene_->instances.size() && scene_->instances[i].node < perNode.size())
                ++perNode[scene_->instances[i].node];
    }
    if (perNode == excluded_) return;
    excluded_ = std::move(perNode);
    // Every row's name and tooltip may have changed: tell the views to repaint all of them.
    Q_EMIT layoutAboutToBeChanged();
    Q_EMIT layoutChanged();
}

std::size_t SceneTreeModel::excludedMeshes(Id node) const {
    return node < excluded_.size() ? excluded_[node] : 0;
}

Id SceneTreeModel::nodeOf(const QModelIndex& index) const {
    return index.isValid() ? static_cast<Id>(index.internalId()) : kNoId;
}

QModelIndex SceneTreeModel::indexOfNode(Id node) const {
    if (!scene_ || node >= scene_->nodes.size()) return {};
    return createIndex(node == 0 ? 0 : rowInParent_[node], 0, static_cast<quintptr>(node));
}

QModelIndex SceneTreeModel::index(int row, int column, const QModelIndex& parent) const {
    if (!scene_ || scene_->nodes.empty() || row < 0 || column < 0 || column >= ColumnCount)
        return {};
    if (!parent.isValid()) return row == 0 ? createIndex(0, column, quintptr{0}) : QModelIndex();
    const auto& children = scene_->nodes[nodeOf(parent)].children;
    if (row >= static_cast<int>(children.size())) return {};
    return createIndex(row, column, static_cast<quintptr>(children[row]));
}

QModelIndex SceneTreeModel::parent(const QModelIndex& child) const {
    if (!child.isValid() || !scene_) return {};
    const Id parentNode = scene_->nodes[nodeOf(child)].parent;
    if (parentNode == kNoId || parentNode >= scene_->nodes.size()) return {};
    return indexOfNode(parentNode);
}

int SceneTreeModel::rowCount(const QModelIndex& parent) const {
    if (!scene_ || scene_->nodes.empty()) return 0;
    if (!parent.isValid()) return 1;
    if (parent.column() != 0) return 0;
    return static_cast<int>(scene_->nodes[nodeOf(parent)].children.size());
}

int SceneTreeModel::columnCount(const QModelIndex&) const { return ColumnCount; }

QVariant SceneTreeModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || !scene_) return {};
    const Id node = nodeOf(index);
    const Counts& c = counts_[node];
    const QLocale locale;
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case NameColumn: {
            QString name = QString::fromStdString(scene_->nodes[node].name);
            if (name.isEmpty()) name = tr("(unnamed %1)").arg(node);
            const std::size_t out = excludedMeshes(node);
            return out > 0 && out == c.ownMeshes ? tr("%1 (excluded)").arg(name) : name;
        }
        case MeshesColumn:
            return locale.toString(static_cast<qulonglong>(c.meshes));
        case TrianglesColumn:
            return locale.toString(static_cast<qulonglong>(c.triangles));
        default:
            return {};
        }
    case Qt::TextAlignmentRole:
        return index.column() == NameColumn ? QVariant()
                                            : QVariant(Qt::AlignRight | Qt::AlignVCenter);
    case Qt::ToolTipRole:
        return tr("Node %1: %2 meshes, %3 triangles on this node; %4 meshes, %5 triangles "
                  "including children")
                   .arg(node)
                   .arg(locale.toString(static_cast<qulonglong>(c.ownMeshes)))
                   .arg(locale.toString(static_cast<qulonglong>(c.ownTriangles)))
                   .arg(locale.toString(static_cast<qulonglong>(c.meshes)))
                   .arg(locale.toString(static_cast<qulonglong>(c.triangles))) +
               (excludedMeshes(node) > 0
                    ? QLatin1Char('\n') +
                          tr("%1 of its meshes excluded from HLOD (drawn as themselves, never in "
                             "a proxy)")
                              .arg(excludedMeshes(node))
                    : QString());
    case NodeIdRole:
        return QVariant::fromValue(static_cast<uint>(node));
    default:
        return {};
    }
}

QVariant SceneTreeModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case NameColumn:
        return tr("Node");
    case MeshesColumn:
        return tr("Meshes");
    case TrianglesColumn:
        return tr("Triangles");
    default:
        return {};
    }
}

} // namespace hlod::widgets
