// Cluster hand edits from the Clusters tab and the viewport (see ClusterEditActions.h).
#include "widgets/ClusterEditActions.h"

#include <algorithm>

#include <QAction>
#include <QItemSelectionModel>
#include <QMenu>
#include <QTreeView>

#include "pipeline/doc/Commands.h"
#include "pipeline/view/TreeViews.h"
#include "widgets/ClusterTreeModel.h"
#include "widgets/DisplayController.h"
#include "widgets/StudioModel.h"
#include "widgets/Viewport.h"
#include "widgets/doc/ProjectSession.h"
#include "widgets/doc/SplitClusterOfTree.h"

namespace hlod::widgets {

namespace {

QAction* makeAction(const QString& text, const QString& tip, const QKeySequence& keys,
                    QObject* parent) {
    auto* action = new QAction(text, parent);
    action->setStatusTip(tip);
    action->setToolTip(tip);
    action->setShortcut(keys);
    // Window-wide (the Clusters tab, the viewport, any dock) and shown in context menus too.
    action->setShortcutContext(Qt::WindowShortcut);
    action->setShortcutVisibleInContextMenu(true);
    return action;
}

} // namespace

ClusterEditActions::ClusterEditActions(ProjectSession* session, StudioModel* model, QTreeView* tree,
                                       ClusterTreeModel* treeModel, QObject* parent)
    : QObject(parent), session_(session), model_(model), tree_(tree), treeModel_(treeModel) {
    using K = QKeySequence;
    merge_ = makeAction(tr("&Merge Clusters"),
                        tr("Make the selected clusters one locked cluster, then rebuild"),
                        K(Qt::CTRL | Qt::Key_G), this);
    split_ = makeAction(tr("&Split Cluster"),
                        tr("Remove the selected cluster: its children hang from its parent"),
                        K(Qt::CTRL | Qt::SHIFT | Qt::Key_G), this);
    lock_ = makeAction(tr("&Lock Cluster"),
                       tr("Keep the selected clusters whole when clustering reruns"),
                       K(Qt::CTRL | Qt::Key_L), this);
    unlock_ =
        makeAction(tr("&Unlock Cluster"), tr("Let clustering regroup the selected locked clusters"),
                   K(Qt::CTRL | Qt::SHIFT | Qt::Key_L), this);
    exclude_ = makeAction(tr("&Exclude from HLOD"),
                          tr("Hang the selected meshes directly from the root, never merged"),
                          K(Qt::CTRL | Qt::SHIFT | Qt::Key_X), this);
    include_ = makeAction(tr("&Include in HLOD"), tr("Cluster the selected excluded meshes again"),
                          K(Qt::CTRL | Qt::SHIFT | Qt::Key_I), this);
    move_ = makeAction(tr("Mo&ve to Cluster"),
                       tr("Move the other selected meshes and clusters into the current cluster "
                          "(the row clicked last)"),
                       K(Qt::CTRL | Qt::Key_M), this);
    connect(move_, &QAction::triggered, this, &ClusterEditActions::moveToCurrent);
    connect(merge_, &QAction::triggered, this, &ClusterEditActions::merge);
    connect(split_, &QAction::triggered, this, &ClusterEditActions::split);
    connect(lock_, &QAction::triggered, this, &ClusterEditActions::lock);
    connect(unlock_, &QAction::triggered, this, &ClusterEditActions::unlock);
    connect(exclude_, &QAction::triggered, this, &ClusterEditActions::exclude);
    connect(include_, &QAction::triggered, this, &ClusterEditActions::include);

    tree_->setSelectionMode(QAbstractItemView::ExtendedSelection);
    tree_->setContextMenuPolicy(Qt::CustomContextMenu);
    tree_->setDragEnabled(true);
    tree_->setAcceptDrops(true);
    tree_->setDropIndicatorShown(true);
    tree_->setDragDropMode(QAbstractItemView::InternalMove);
    tree_->setDefaultDropAction(Qt::MoveAction);
    connect(tree_, &QWidget::customContextMenuRequested, this, &ClusterEditActions::showTreeMenu);
    connect(treeModel_, &ClusterTreeModel::moveRequested, this, &ClusterEditActions::moveTo);
    // The actions are enabled exactly when they apply, at every moment (their shortcuts too).
    for (auto signal :
         {&StudioModel::selectionChanged, &StudioModel::buildStarted, &StudioModel::buildFinished,
          &StudioModel::buildCancelled, &StudioModel::sceneChanged})
        connect(model_, signal, this, &ClusterEditActions::updateActions);
    connect(model_, &StudioModel::buildFailed, this, &ClusterEditActions::updateActions);
    connect(session_, &ProjectSession::documentChanged, this, &ClusterEditActions::updateActions);
    connect(tree_->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &ClusterEditActions::updateActions);
    connect(tree_->selectionModel(), &QItemSelectionModel::currentChanged, this,
            &ClusterEditActions::updateActions);
    connect(treeModel_, &QAbstractItemModel::modelReset, this, &ClusterEditActions::updateActions);
    updateActions();
}

void ClusterEditActions::attachViewport(Viewport* viewport, DisplayController* display) {
    viewport_ = viewport;
    display_ = display;
    if (!viewport_ || !display_) return;
    connect(viewport_, &Viewport::ctrlClicked, this, [this](const QPoint& pos) { toggleAt(pos); });
    connect(viewport_, &Viewport::contextClicked, this, &ClusterEditActions::showViewportMenu);
}

QList<QAction*> ClusterEditActions::actions() const {
    return {merge_, split_, move_, lock_, unlock_, exclude_, include_};
}

std::vector<Id> ClusterEditActions::selectedNodes() const {
    std::vector<Id> nodes;
    const BuiltHlod& built = model_->built();
    if (!built.build || !tree_->selectionModel()) return nodes;
    for (const QModelIndex& row : tree_->selectionModel()->selectedRows()) {
        const Id node = treeModel_->nodeOf(row);
        if (node < built.build->tree->nodes.size()) nodes.push_back(node);
    }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    return nodes;
}

std::vector<InstanceSet> ClusterEditActions::selectedClusters() const {
    std::vector<InstanceSet> sets;
    for (Id node : selectedNodes())
        sets.push_back(leafSet(*model_->built().build->tree, node));
    std::sort(sets.begin(), sets.end());
    return sets;
}

InstanceSet ClusterEditActions::excludedInSelection() const {
    const Document& doc = session_->document();
    if (model_->shownCluster() == kNoNode) return {};
    const InstanceSet& excluded = doc.graph().node(model_->shownCluster()).edits.excluded;
    InstanceSet out;
    for (const InstanceSet& set : selectedClusters())
        for (Id instance : set)
            if (std::binary_search(excluded.begin(), excluded.end(), instance))
                out.push_back(instance);
    return normalizedSet(std::move(out));
}

void ClusterEditActions::updateActions() {
    const std::vector<Id> nodes = selectedNodes();
    const bool idle =
        model_->hasBuild() && !model_->building() && model_->shownCluster() != kNoNode;
    bool clusters = false;    // an inner node other than the root (split, lock)
    bool unlocked = false;    // one of those not locked yet
    bool lockedGroup = false; // a selected cluster that is a locked group of the hand edits
    bool root = false;
    bool nested = false; // one selected row inside another
    if (idle) {
        const ClusterTree& tree = *model_->built().build->tree;
        const Document& doc = session_->document();
        const std::vector<InstanceSet>& locked =
            doc.graph().node(model_->shownCluster()).edits.locked;
        for (Id node : nodes) {
            const ClusterNode& n = tree.nodes[node];
            root = root || node == tree.root;
            const bool inner = !n.isLeaf() && node != tree.root;
            clusters = clusters || inner;
            unlocked = unlocked || (inner && !n.locked);
            lockedGroup =
                lockedGroup ||
                (n.locked && std::binary_search(locked.begin(), locked.end(), leafSet(tree, node)));
            for (Id other : nodes)
                nested = nested || (other != node && isInSubtree(tree, node, other));
        }
    }
    const InstanceSet excluded = idle ? excludedInSelection() : InstanceSet{};
    std::size_t instances = 0;
    for (const InstanceSet& set : idle ? selectedClusters() : std::vector<InstanceSet>{})
        instances += set.size();
    merge_->setEnabled(idle && nodes.size() >= 2 && !root && !nested);
    split_->setEnabled(idle && clusters);
    lock_->setEnabled(idle && unlocked);
    unlock_->setEnabled(idle && lockedGroup);
    exclude_->setEnabled(idle && !root && instances > excluded.size());
    // Exclude on a cluster excludes its meshes (issue 31 #10: a cluster has no geometry of its
    // own to leave out); the action says how many, and both trees then mark them "(excluded)".
    const std::size_t toExclude = instances - std::min(instances, excluded.size());
    if (clusters && toExclude > 0) {
        exclude_->setText(toExclude == 1 ? tr("&Exclude 1 Mesh from HLOD")
                                         : tr("&Exclude %1 Meshes from HLOD").arg(toExclude));
        exclude_->setStatusTip(tr("Exclude every mesh of the selected clusters: each hangs from "
                                  "the root, drawn as itself and never merged into a proxy; the "
                                  "Clusters and Scene tabs mark them (excluded)"));
    } else {
        exclude_->setText(tr("&Exclude from HLOD"));
        exclude_->setStatusTip(tr("Hang the selected meshes directly from the root, never "
                                  "merged; the Clusters and Scene tabs mark them (excluded)"));
    }
    exclude_->setToolTip(exclude_->statusTip());
    include_->setEnabled(idle && !excluded.empty());
    std::vector<InstanceSet> items;
    InstanceSet target;
    move_->setEnabled(idle && moveToCurrentSets(items, target));
}

void ClusterEditActions::fillMenu(QMenu* menu) {
    updateActions();
    menu->addActions({merge_, split_, move_});
    menu->addSeparator();
    menu->addActions({lock_, unlock_});
    menu->addSeparator();
    menu->addActions({exclude_, include_});
}

void ClusterEditActions::showTreeMenu(const QPoint& pos) {
    QMenu menu(tree_);
    fillMenu(&menu);
    menu.exec(tree_->viewport()->mapToGlobal(pos));
}

void ClusterEditActions::showViewportMenu(const QPoint& pos) {
    if (!model_->hasBuild()) return;
    selectForMenuAt(pos);
    QMenu menu(viewport_);
    fillMenu(&menu);
    menu.exec(viewport_->mapToGlobal(pos));
}

Id ClusterEditActions::pickCluster(const QPoint& pos) {
    if (!display_ || !model_->hasBuild()) return kNoId;
    display_->pickAt(pos); // selects what a plain click selects
    Id node = model_->selection().clusterNode;
    if (node == kNoId || model_->view().mode != DisplayMode::Clusters) return node;
    // Clusters mode colours the clusters of the shown level: the click means the one holding it.
    const ClusterTree& tree = *model_->built().build->tree;
    const std::vector<Id>& cut = display_->shownClusters();
    for (Id n = node; n != kNoId; n = tree.nodes[n].parent) {
        if (std::find(cut.begin(), cut.end(), n) != cut.end()) {
            model_->selectClusterNode(n);
            return n;
        }
    }
    return node;
}

void ClusterEditActions::selectRows(const std::vector<Id>& nodes, Id current) {
    QItemSelectionModel* selection = tree_->selectionModel();
    QItemSelection rows;
    for (Id node : nodes) {
        const QModelIndex index = treeModel_->indexOfNode(node);
        if (index.isValid()) rows.select(index, index);
    }
    selection->select(rows, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    const QModelIndex index = treeModel_->indexOfNode(current);
    if (index.isValid()) {
        selection->setCurrentIndex(index, QItemSelectionModel::NoUpdate);
        tree_->scrollTo(index);
    }
    updateActions();
}

Id ClusterEditActions::toggleAt(const QPoint& pos) {
    std::vector<Id> nodes = selectedNodes();
    const Id node = pickCluster(pos);
    if (node == kNoId) {
        selectRows(nodes, nodes.empty() ? kNoId : nodes.back());
        return kNoId;
    }
    const auto it = std::find(nodes.begin(), nodes.end(), node);
    if (it != nodes.end()) {
        nodes.erase(it);
        selectRows(nodes, nodes.empty() ? kNoId : nodes.back());
    } else {
        nodes.push_back(node);
        selectRows(nodes, node);
    }
    return node;
}

Id ClusterEditActions::selectForMenuAt(const QPoint& pos) {
    const std::vector<Id> nodes = selectedNodes();
    const Id node = pickCluster(pos);
    if (node != kNoId && std::find(nodes.begin(), nodes.end(), node) != nodes.end())
        selectRows(nodes, node); // a right click on a selected cluster keeps the selection
    return node;
}

bool ClusterEditActions::merge() {
    std::vector<InstanceSet> sets = selectedClusters();
    const NodeId node = model_->shownCluster();
    if (sets.size() < 2 || node == kNoNode) return false;
    return session_->undo()->execute(std::make_unique<MergeClusters>(node, std::move(sets)));
}

bool ClusterEditActions::split() {
    const NodeId node = model_->shownCluster();
    if (!model_->hasBuild() || node == kNoNode) return false;
    const ClusterTree& tree = *model_->built().build->tree;
    bool any = false;
    for (Id cluster : selectedNodes()) {
        if (cluster == tree.root || tree.nodes[cluster].isLeaf()) continue;
        any = session_->undo()->execute(
                  std::make_unique<SplitClusterOfTree>(node, leafSet(tree, cluster), tree)) ||
              any;
    }
    return any;
}

bool ClusterEditActions::lock() {
    const NodeId node = model_->shownCluster();
    if (node == kNoNode || !model_->hasBuild()) return false;
    const ClusterTree& tree = *model_->built().build->tree;
    bool any = false;
    for (Id cluster : selectedNodes()) {
        const ClusterNode& n = tree.nodes[cluster];
        if (n.isLeaf() || cluster == tree.root || n.locked) continue; // nothing to lock there
        any = session_->undo()->execute(
                  std::make_unique<LockCluster>(node, leafSet(tree, cluster))) ||
              any;
    }
    return any;
}

bool ClusterEditActions::unlock() {
    const NodeId node = model_->shownCluster();
    if (node == kNoNode) return false;
    const std::vector<InstanceSet>& locked = session_->document().graph().node(node).edits.locked;
    std::vector<InstanceSet> toUnlock;
    for (const InstanceSet& set : selectedClusters())
        if (std::binary_search(locked.begin(), locked.end(), set)) toUnlock.push_back(set);
    bool any = false;
    for (const InstanceSet& set : toUnlock)
        any = session_->undo()->execute(std::make_unique<UnlockCluster>(node, set)) || any;
    return any;
}

bool ClusterEditActions::exclude() {
    InstanceSet all;
    for (const InstanceSet& set : selectedClusters())
        all.insert(all.end(), set.begin(), set.end());
    const NodeId node = model_->shownCluster();
    if (all.empty() || node == kNoNode) return false;
    return session_->undo()->execute(
        std::make_unique<ExcludeInstance>(node, normalizedSet(std::move(all))));
}

bool ClusterEditActions::include() {
    InstanceSet excluded = excludedInSelection();
    const NodeId node = model_->shownCluster();
    if (excluded.empty() || node == kNoNode) return false;
    return session_->undo()->execute(std::make_unique<IncludeInstance>(node, std::move(excluded)));
}

bool ClusterEditActions::moveToCurrentSets(std::vector<InstanceSet>& items,
                                           InstanceSet& target) const {
    items.clear();
    target.clear();
    if (!model_->hasBuild() || !tree_->selectionModel()) return false;
    const QModelIndex current = tree_->selectionModel()->currentIndex();
    if (!current.isValid() || !tree_->selectionModel()->isSelected(current)) return false;
    const Id targetNode = treeModel_->nodeOf(current);
    for (Id node : selectedNodes())
        if (node != targetNode) items.push_back(treeModel_->leafSetOf(node));
    target = treeModel_->leafSetOf(targetNode);
    return !items.empty() && treeModel_->acceptsMove(items, target);
}

bool ClusterEditActions::moveToCurrent() {
    std::vector<InstanceSet> items;
    InstanceSet target;
    if (!moveToCurrentSets(items, target)) return false;
    return moveTo(items, target);
}

bool ClusterEditActions::moveTo(const std::vector<InstanceSet>& items, const InstanceSet& target) {
    const NodeId node = model_->shownCluster();
    if (items.empty() || target.empty() || node == kNoNode || model_->building()) return false;
    return session_->undo()->execute(std::make_unique<MoveToCluster>(node, items, target));
}

} // namespace hlod::widgets
