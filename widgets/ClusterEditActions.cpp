// Cluster hand edits from the Clusters tab (see ClusterEditActions.h).
#include "widgets/ClusterEditActions.h"

#include <algorithm>

#include <QAction>
#include <QItemSelectionModel>
#include <QMenu>
#include <QTreeView>

#include "pipeline/doc/Commands.h"
#include "widgets/ClusterTreeModel.h"
#include "widgets/StudioModel.h"
#include "widgets/doc/ProjectSession.h"

namespace hlod::widgets {

ClusterEditActions::ClusterEditActions(ProjectSession* session, StudioModel* model, QTreeView* tree,
                                       ClusterTreeModel* treeModel, QObject* parent)
    : QObject(parent), session_(session), model_(model), tree_(tree), treeModel_(treeModel) {
    merge_ = new QAction(tr("&Merge Clusters"), this);
    merge_->setStatusTip(tr("Make the selected clusters one locked cluster, then rebuild"));
    lock_ = new QAction(tr("&Lock Cluster"), this);
    lock_->setStatusTip(tr("Keep the selected clusters whole when clustering reruns"));
    unlock_ = new QAction(tr("&Unlock Cluster"), this);
    exclude_ = new QAction(tr("&Exclude from HLOD"), this);
    exclude_->setStatusTip(tr("Hang the selected meshes directly from the root, never merged"));
    connect(merge_, &QAction::triggered, this, &ClusterEditActions::merge);
    connect(lock_, &QAction::triggered, this, &ClusterEditActions::lock);
    connect(unlock_, &QAction::triggered, this, &ClusterEditActions::unlock);
    connect(exclude_, &QAction::triggered, this, &ClusterEditActions::exclude);

    tree_->setSelectionMode(QAbstractItemView::ExtendedSelection);
    tree_->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(tree_, &QWidget::customContextMenuRequested, this, &ClusterEditActions::showMenu);
    connect(session_, &ProjectSession::documentChanged, this,
            &ClusterEditActions::rebuildWhenEditsChanged);
    updateActions();
}

std::vector<InstanceSet> ClusterEditActions::selectedClusters() const {
    std::vector<InstanceSet> sets;
    const BuiltHlod& built = model_->built();
    if (!built.build || !tree_->selectionModel()) return sets;
    for (const QModelIndex& row : tree_->selectionModel()->selectedRows()) {
        const Id node = treeModel_->nodeOf(row);
        if (node < built.build->tree.nodes.size()) sets.push_back(leafSet(built.build->tree, node));
    }
    std::sort(sets.begin(), sets.end());
    sets.erase(std::unique(sets.begin(), sets.end()), sets.end());
    return sets;
}

void ClusterEditActions::updateActions() {
    const std::size_t n = selectedClusters().size();
    const bool idle = !model_->building();
    merge_->setEnabled(idle && n >= 2);
    lock_->setEnabled(idle && n >= 1);
    unlock_->setEnabled(idle && n >= 1);
    exclude_->setEnabled(idle && n >= 1);
}

void ClusterEditActions::showMenu(const QPoint& pos) {
    updateActions();
    QMenu menu(tree_);
    menu.addActions({merge_, lock_, unlock_});
    menu.addSeparator();
    menu.addAction(exclude_);
    menu.exec(tree_->viewport()->mapToGlobal(pos));
}

namespace {

// Runs `command` through the session's undo adapter; false (and `failed`) when it does not
// apply.
bool run(ProjectSession* session, std::unique_ptr<Command> command) {
    return session->undo()->execute(std::move(command));
}

} // namespace

bool ClusterEditActions::merge() {
    std::vector<InstanceSet> sets = selectedClusters();
    if (sets.size() < 2) return false;
    const NodeId node = session_->document().clusterNode();
    return run(session_, std::make_unique<MergeClusters>(node, std::move(sets)));
}

bool ClusterEditActions::lock() {
    const NodeId node = session_->document().clusterNode();
    bool any = false;
    for (const InstanceSet& set : selectedClusters())
        any = run(session_, std::make_unique<LockCluster>(node, set)) || any;
    return any;
}

bool ClusterEditActions::unlock() {
    const NodeId node = session_->document().clusterNode();
    bool any = false;
    for (const InstanceSet& set : selectedClusters())
        any = run(session_, std::make_unique<UnlockCluster>(node, set)) || any;
    return any;
}

bool ClusterEditActions::exclude() {
    InstanceSet all;
    for (const InstanceSet& set : selectedClusters())
        all.insert(all.end(), set.begin(), set.end());
    if (all.empty()) return false;
    const NodeId node = session_->document().clusterNode();
    return run(session_, std::make_unique<ExcludeInstance>(node, normalizedSet(std::move(all))));
}

void ClusterEditActions::rebuildWhenEditsChanged() {
    const BuiltHlod& built = model_->built();
    if (session_->replacing() || !built.build || !model_->scene()) return;
    const HlodSettings wanted = session_->settings();
    const ClusterParams& have = built.build->settings.cluster;
    if (wanted.cluster.lockedGroups == have.lockedGroups &&
        wanted.cluster.excluded == have.excluded)
        return;
    model_->build();
}

} // namespace hlod::widgets
