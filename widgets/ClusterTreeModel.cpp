// Item model over an HLOD cluster tree (see ClusterTreeModel.h).
#include "widgets/ClusterTreeModel.h"

#include <algorithm>
#include <numbers>

#include <QIcon>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLocale>
#include <QMimeData>
#include <QPainter>
#include <QPixmap>

#include "pipeline/view/TreeViews.h"
#include "widgets/NumberFormat.h"

namespace hlod::widgets {

namespace {

// A small padlock (shackle over a body), drawn once: the Clusters tab's mark of a locked
// cluster.
QIcon lockIcon() {
    static const QIcon icon = [] {
        QPixmap pixmap(32, 32);
        pixmap.fill(Qt::transparent);
        QPainter p(&pixmap);
        p.setRenderHint(QPainter::Antialiasing);
        p.setPen(QPen(QColor(90, 90, 100), 3.5));
        p.setBrush(Qt::NoBrush);
        p.drawArc(QRectF(9, 3, 14, 18), 0, 180 * 16);
        p.drawLine(QPointF(9, 12), QPointF(9, 15));
        p.drawLine(QPointF(23, 12), QPointF(23, 15));
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(200, 150, 40));
        p.drawRoundedRect(QRectF(5, 14, 22, 16), 3, 3);
        return QIcon(pixmap);
    }();
    return icon;
}

} // namespace

ClusterTreeModel::ClusterTreeModel(QObject* parent) : QAbstractItemModel(parent) {}

void ClusterTreeModel::setBuild(std::shared_ptr<const Scene> scene,
                                std::shared_ptr<const NodeOutput> build, std::vector<int> labels) {
    beginResetModel();
    scene_ = build ? std::move(scene) : nullptr;
    build_ = scene_ ? std::move(build) : nullptr;
    triangles_.clear();
    rowInParent_.clear();
    labels_.clear();
    keys_.clear();
    nodeOfKey_.clear();
    if (build_) {
        const ClusterTree& tree = *build_->tree;
        if (labels.size() == tree.nodes.size()) labels_ = std::move(labels);
        keys_ = clusterKeys(tree);
        nodeOfKey_.reserve(keys_.size());
        for (Id n = 0; n < keys_.size(); ++n)
            nodeOfKey_.emplace(keys_[n], n);
        triangles_ = subtreeTriangles(tree, *scene_);
        rowInParent_.assign(tree.nodes.size(), 0);
        for (const ClusterNode& node : tree.nodes)
            for (std::size_t i = 0; i < node.children.size(); ++i)
                rowInParent_[node.children[i]] = static_cast<int>(i);
    }
    endResetModel();
}

Id ClusterTreeModel::nodeOf(const QModelIndex& index) const {
    return index.isValid() ? static_cast<Id>(index.internalId()) : kNoId;
}

QModelIndex ClusterTreeModel::indexOfNode(Id node) const {
    if (!build_ || node >= build_->tree->nodes.size()) return {};
    const int row = node == build_->tree->root ? 0 : rowInParent_[node];
    return createIndex(row, 0, static_cast<quintptr>(node));
}

ClusterKey ClusterTreeModel::keyOf(const QModelIndex& index) const {
    const Id node = nodeOf(index);
    return node < keys_.size() ? keys_[node] : 0;
}

QModelIndex ClusterTreeModel::indexOfKey(ClusterKey key) const {
    const auto it = nodeOfKey_.find(key);
    return it == nodeOfKey_.end() ? QModelIndex() : indexOfNode(it->second);
}

InstanceSet ClusterTreeModel::leafSetOf(Id node) const {
    if (!build_ || node >= build_->tree->nodes.size()) return {};
    return leafSet(*build_->tree, node);
}

Qt::ItemFlags ClusterTreeModel::flags(const QModelIndex& index) const {
    Qt::ItemFlags f = QAbstractItemModel::flags(index);
    if (!index.isValid() || !build_) return f;
    const Id node = nodeOf(index);
    if (node == build_->tree->root) return f;
    f |= Qt::ItemIsDragEnabled;
    if (!build_->tree->nodes[node].isLeaf()) f |= Qt::ItemIsDropEnabled;
    return f;
}

QStringList ClusterTreeModel::mimeTypes() const { return {QString::fromLatin1(kMimeType)}; }

QMimeData* ClusterTreeModel::mimeData(const QModelIndexList& indexes) const {
    std::vector<Id> nodes;
    for (const QModelIndex& index : indexes)
        if (index.isValid() && index.column() == NameColumn) nodes.push_back(nodeOf(index));
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    QJsonArray sets;
    for (Id node : nodes) {
        QJsonArray set;
        for (Id instance : leafSetOf(node))
            set.append(static_cast<qint64>(instance));
        sets.append(set);
    }
    auto* data = new QMimeData;
    data->setData(QString::fromLatin1(kMimeType),
                  QJsonDocument(sets).toJson(QJsonDocument::Compact));
    return data;
}

bool ClusterTreeModel::decodeDrop(const QMimeData* data, const QModelIndex& parent,
                                  std::vector<InstanceSet>& items, InstanceSet& target) const {
    if (!build_ || !data || !parent.isValid()) return false;
    const QJsonDocument json = QJsonDocument::fromJson(data->data(QString::fromLatin1(kMimeType)));
    if (!json.isArray()) return false;
    items.clear();
    for (const QJsonValue& set : json.array()) {
        InstanceSet ids;
        for (const QJsonValue& id : set.toArray()) {
            const qint64 v = id.toInteger(-1);
            if (v < 0) return false;
            ids.push_back(static_cast<Id>(v));
        }
        if (ids.empty()) return false;
        items.push_back(normalizedSet(std::move(ids)));
    }
    // A drop between two rows lands on the cluster that holds them.
    target = leafSetOf(nodeOf(parent));
    return !items.empty();
}

bool ClusterTreeModel::acceptsMove(const std::vector<InstanceSet>& items,
                                   const InstanceSet& target) const {
    if (!build_ || items.empty()) return false;
    const ClusterTree& tree = *build_->tree;
    const Id t = findCluster(tree, target);
    if (t == kNoId || t == tree.root || tree.nodes[t].isLeaf()) return false;
    bool anyMoves = false;
    for (const InstanceSet& item : items) {
        const Id i = findCluster(tree, item);
        if (i == kNoId || i == tree.root) return false;
        // The target may not be a dragged row or lie inside one.
        if (std::includes(item.begin(), item.end(), target.begin(), target.end())) return false;
        anyMoves = anyMoves || tree.nodes[i].parent != t;
    }
    return anyMoves;
}

bool ClusterTreeModel::canDropMimeData(const QMimeData* data, Qt::DropAction action, int, int,
                                       const QModelIndex& parent) const {
    if (action != Qt::MoveAction) return false;
    std::vector<InstanceSet> items;
    InstanceSet target;
    return decodeDrop(data, parent, items, target) && acceptsMove(items, target);
}

bool ClusterTreeModel::dropMimeData(const QMimeData* data, Qt::DropAction action, int row,
                                    int column, const QModelIndex& parent) {
    if (!canDropMimeData(data, action, row, column, parent)) return false;
    std::vector<InstanceSet> items;
    InstanceSet target;
    decodeDrop(data, parent, items, target);
    Q_EMIT moveRequested(items, target);
    return true;
}

QModelIndex ClusterTreeModel::index(int row, int column, const QModelIndex& parent) const {
    if (!build_ || build_->tree->root == kNoId || row < 0 || column < 0 || column >= ColumnCount)
        return {};
    if (!parent.isValid())
        return row == 0 ? createIndex(0, column, static_cast<quintptr>(build_->tree->root))
                        : QModelIndex();
    const auto& children = build_->tree->nodes[nodeOf(parent)].children;
    if (row >= static_cast<int>(children.size())) return {};
    return createIndex(row, column, static_cast<quintptr>(children[row]));
}

QModelIndex ClusterTreeModel::parent(const QModelIndex& child) const {
    if (!child.isValid() || !build_) return {};
    const Id parentNode = build_->tree->nodes[nodeOf(child)].parent;
    return parentNode == kNoId ? QModelIndex() : indexOfNode(parentNode);
}

int ClusterTreeModel::rowCount(const QModelIndex& parent) const {
    if (!build_ || build_->tree->root == kNoId) return 0;
    if (!parent.isValid()) return 1;
    if (parent.column() != 0) return 0;
    return static_cast<int>(build_->tree->nodes[nodeOf(parent)].children.size());
}

int ClusterTreeModel::columnCount(const QModelIndex&) const { return ColumnCount; }

QString ClusterTreeModel::name(Id node) const {
    if (!build_ || node >= build_->tree->nodes.size()) return {};
    const ClusterNode& n = build_->tree->nodes[node];
    const int number = node < labels_.size() ? labels_[node] : static_cast<int>(node);
    if (!n.isLeaf() || n.instance >= scene_->instances.size())
        return n.locked ? tr("Cluster %1 (locked)").arg(number) : tr("Cluster %1").arg(number);
    const MeshInstance& instance = scene_->instances[n.instance];
    QString label = QString::fromStdString(scene_->nodes[instance.node].name);
    if (label.isEmpty()) label = QString::fromStdString(scene_->meshes[instance.mesh].name);
    if (label.isEmpty()) label = tr("Instance %1").arg(n.instance);
    return excluded(n.instance) ? tr("%1 (excluded)").arg(label) : label;
}

bool ClusterTreeModel::excluded(Id instance) const {
    if (!build_) return false;
    const InstanceSet& set = build_->cluster.excluded;
    return std::binary_search(set.begin(), set.end(), instance);
}

QString ClusterTreeModel::shownName(Id node) const {
    // The lock is the row's icon: "Cluster 117 (locked)" was cut off in the dock's default
    // width (issue 31 #10). An excluded mesh keeps its mark in the text, which the view elides
    // in the middle so the mark stays.
    if (!build_ || node >= build_->tree->nodes.size()) return {};
    const ClusterNode& n = build_->tree->nodes[node];
    if (n.isLeaf()) return name(node);
    const int number = node < labels_.size() ? labels_[node] : static_cast<int>(node);
    return tr("Cluster %1").arg(number);
}

double ClusterTreeModel::volume(Id node) const {
    if (!build_ || node >= build_->tree->nodes.size()) return 0.0;
    const ClusterNode& n = build_->tree->nodes[node];
    if (build_->tree->volume == VolumeType::Sphere)
        return 4.0 / 3.0 * std::numbers::pi * n.sphere.radius * n.sphere.radius * n.sphere.radius;
    if (n.box.empty()) return 0.0;
    const glm::dvec3 e = n.box.max - n.box.min;
    return e.x * e.y * e.z;
}

double ClusterTreeModel::size(Id node) const {
    if (!build_ || node >= build_->tree->nodes.size()) return 0.0;
    const ClusterNode& n = build_->tree->nodes[node];
    if (build_->tree->volume == VolumeType::Sphere) return 2.0 * n.sphere.radius;
    return n.box.empty() ? 0.0 : n.box.diagonal();
}

QVariant ClusterTreeModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || !build_) return {};
    const Id node = nodeOf(index);
    const ClusterNode& n = build_->tree->nodes[node];
    const std::size_t proxy =
        node < build_->bake->nodes.size() ? build_->bake->nodes[node].proxy.triangleCount() : 0;
    const QLocale locale;
    if (role == NodeIdRole) return QVariant::fromValue(static_cast<uint>(node));
    if (role == Qt::DecorationRole)
        return index.column() == NameColumn && n.locked ? QVariant(lockIcon()) : QVariant();
    if (role == Qt::TextAlignmentRole)
        return index.column() == NameColumn ? QVariant()
                                            : QVariant(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::ToolTipRole) {
        const QString counts =
            tr("%1 triangles below, %2 %4 across, volume %3 cubic %4")
                .arg(locale.toString(static_cast<qulonglong>(triangles_[node])),
                     formatLength(size(node)), formatVolume(volume(node)), lengthUnit());
        if (n.isLeaf())
            return tr("%1: mesh instance %2, %3").arg(name(node)).arg(n.instance).arg(counts);
        return tr("%1: %2 children, %3, proxy %4 triangles, fill %5%6")
            .arg(name(node))
            .arg(n.children.size())
            .arg(counts)
            .arg(locale.toString(static_cast<qulonglong>(proxy)))
            .arg(locale.toString(n.fill, 'f', 3))
            .arg(n.locked ? tr("; locked by a hand edit: kept whole when clustering reruns")
                          : QString());
    }
    if (role != Qt::DisplayRole && role != ValueRole) return {};
    const bool raw = role == ValueRole;
    switch (index.column()) {
    case NameColumn:
        return raw ? QVariant(name(node)) : QVariant(shownName(node));
    case TrianglesColumn:
        return raw ? QVariant::fromValue(static_cast<qulonglong>(triangles_[node]))
                   : QVariant(formatCount(triangles_[node]));
    case LevelColumn:
        return n.level;
    case SizeColumn:
        return raw ? QVariant(size(node)) : QVariant(formatLength(size(node)));
    case ProxyTrianglesColumn:
        if (n.isLeaf()) return raw ? QVariant(qulonglong{0}) : QVariant(QStringLiteral("–"));
        return raw ? QVariant::fromValue(static_cast<qulonglong>(proxy))
                   : QVariant(formatCount(proxy));
    default:
        return {};
    }
}

QVariant ClusterTreeModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal) return {};
    if (role == Qt::ToolTipRole) {
        switch (section) {
        case TrianglesColumn:
            return tr("Triangles of the original meshes below the cluster");
        case ProxyTrianglesColumn:
            return tr("Triangles of the cluster's proxy, drawn in place of everything below it");
        case LevelColumn:
            return tr("Level in the tree: 0 for single meshes, the root highest");
        case SizeColumn:
            return tr("Diameter of the cluster's bounding sphere (sphere trees) or diagonal of "
                      "its box, in %1 (the unit of the scene's coordinates)")
                .arg(lengthUnit());
        default:
            return {};
        }
    }
    if (role != Qt::DisplayRole) return {};
    switch (section) {
    case NameColumn:
        return tr("Cluster");
    case TrianglesColumn:
        return tr("Triangles");
    case LevelColumn:
        return tr("Level");
    case SizeColumn:
        return tr("Size");
    case ProxyTrianglesColumn:
        return tr("Proxy");
    default:
        return {};
    }
}

} // namespace hlod::widgets
