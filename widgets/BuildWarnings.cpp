// Warnings about a finished build (see BuildWarnings.h).
#include "widgets/BuildWarnings.h"

#include <QCoreApplication>
#include <QLocale>

#include "widgets/GraphRunner.h"

namespace hlod::widgets {

namespace {

QString tr(const char* text) { return QCoreApplication::translate("BuildWarnings", text); }

} // namespace

Id widestCluster(const BuiltHlod& built) {
    Id widest = kNoId;
    if (!built.build || !built.build->tree) return widest;
    const ClusterTree& tree = *built.build->tree;
    std::size_t most = 0;
    for (Id n = 0; n < tree.nodes.size(); ++n) {
        const ClusterNode& node = tree.nodes[n];
        if (node.isLeaf() || (node.parent == kNoId && n != tree.root)) continue;
        if (node.children.size() > most) {
            most = node.children.size();
            widest = n;
        }
    }
    return widest;
}

QString dissolveWarning(const BuiltHlod& built, const std::vector<int>& labels) {
    if (!built.build || !built.build->tree || !built.build->bake) return {};
    const ClusterTree& tree = *built.build->tree;
    const int maxChildren = built.build->cluster.maxChildren;
    const Id widest = widestCluster(built);
    if (widest == kNoId) return {};
    const std::size_t children = tree.nodes[widest].children.size();
    const int number = widest < labels.size() ? labels[widest] : static_cast<int>(widest);
    const QString widestName = widest == tree.root ? tr("the root (Cluster %1)").arg(number)
                                                   : tr("Cluster %1").arg(number);
    std::size_t leaves = 0;
    for (const ClusterNode& n : tree.nodes)
        if (n.isLeaf()) ++leaves;
    // A tree of one level over more meshes than one merge takes: every cluster dissolved.
    const bool collapsed = tree.height() <= 1 && leaves > static_cast<std::size_t>(maxChildren);
    const bool wide = children > static_cast<std::size_t>(maxChildren);
    if (!collapsed && !wide) return {};
    const QLocale locale;
    const std::size_t dissolved = built.build->bake->dissolved;
    QString text = dissolved == 1 ? tr("The proxy economy dissolved 1 cluster: ")
                                  : tr("The proxy economy dissolved %1 clusters: ")
                                        .arg(locale.toString(static_cast<qulonglong>(dissolved)));
    if (collapsed)
        text += tr("the tree collapsed to height %1, %2 has %3 children (max children %4). "
                   "The HLOD barely reduces draw calls: try the decimate proxy method, a larger "
                   "proxy ratio or a smaller level growth.")
                    .arg(tree.height())
                    .arg(widestName)
                    .arg(locale.toString(static_cast<qulonglong>(children)))
                    .arg(maxChildren);
    else
        text += tr("%1 has %2 children although max children is %3 (a dissolved cluster's "
                   "children hang from its parent).")
                    .arg(widestName)
                    .arg(locale.toString(static_cast<qulonglong>(children)))
                    .arg(maxChildren);
    return text;
}

} // namespace hlod::widgets
