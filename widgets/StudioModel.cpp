// The editor's state owner (see StudioModel.h).
#include "widgets/StudioModel.h"

#include <algorithm>
#include <unordered_map>

#include "pipeline/proxy/ProxyEconomy.h"
#include "pipeline/view/TreeViews.h"

namespace hlod::widgets {

namespace {

// The clusters of `tree` whose meshes are all `chosen` and whose parent's are not.
std::vector<Id> largestClustersWithin(const ClusterTree& tree, const std::vector<char>& chosen) {
    std::vector<char> full(tree.nodes.size(), 0);
    if (tree.root == kNoId) return {};
    std::vector<std::pair<Id, bool>> stack{{tree.root, false}};
    while (!stack.empty()) { // post-order
        const auto [id, expanded] = stack.back();
        stack.pop_back();
        const ClusterNode& n = tree.nodes[id];
        if (n.isLeaf()) {
            full[id] = n.instance < chosen.size() && chosen[n.instance];
        } else if (!expanded) {
            stack.push_back({id, true});
            for (Id c : n.children)
                stack.push_back({c, false});
        } else {
            full[id] = std::all_of(n.children.begin(), n.children.end(),
                                   [&](Id c) { return full[c] != 0; });
        }
    }
    std::vector<Id> out;
    for (Id n = 0; n < tree.nodes.size(); ++n)
        if (full[n] && (tree.nodes[n].parent == kNoId || !full[tree.nodes[n].parent]))
            out.push_back(n);
    return out;
}

} // namespace

bool displayModeFromString(const QString& text, DisplayMode& mode) {
    const QString t = text.trimmed().toLower();
    if (t == QLatin1String("original"))
        mode = DisplayMode::Original;
    else if (t == QLatin1String("clusters"))
        mode = DisplayMode::Clusters;
    else if (t == QLatin1String("hlod"))
        mode = DisplayMode::Hlod;
    else
        return false;
    return true;
}

StudioModel::StudioModel(QObject* parent) : QObject(parent), runner_(new GraphRunner(this)) {
    connect(runner_, &GraphRunner::started, this, &StudioModel::buildStarted);
    connect(runner_, &GraphRunner::progressed, this,
            [this](quint32 node, const QString& stage, qint64 done, qint64 total,
                   const QString& detail) {
                Q_EMIT nodeProgress(node, stage, done, total);
                Q_EMIT buildProgress(stage, done, total, detail);
            });
    connect(runner_, &GraphRunner::nodeStatus, this,
            [this](quint32 node, int) { Q_EMIT nodeStatusChanged(node); });
    connect(runner_, &GraphRunner::finished, this, &StudioModel::onRunFinished);
    connect(runner_, &GraphRunner::failed, this, &StudioModel::buildFailed);
    connect(runner_, &GraphRunner::cancelled, this, &StudioModel::buildCancelled);
}

StudioModel::~StudioModel() = default;

void StudioModel::setScene(std::shared_ptr<const Scene> scene) {
    const bool wasBuilding = runner_->busy();
    runner_->abandon();
    scene_ = std::move(scene);
    nodeInstances_.clear();
    if (scene_) {
        nodeInstances_.resize(scene_->nodes.size());
        for (Id i = 0; i < scene_->instances.size(); ++i)
            if (scene_->instances[i].node < nodeInstances_.size())
                nodeInstances_[scene_->instances[i].node].push_back(i);
    }
    kept_.clear();
    everBuilt_ = false;
    clearShown();
    labeller_.reset();
    selection_ = {};
    if (wasBuilding) Q_EMIT buildCancelled();
    Q_EMIT sceneChanged();
    Q_EMIT selectionChanged();
    ViewOptions view = view_;
    view.mode = DisplayMode::Original; // nothing else to show until a build exists
    setView(view);
}

void StudioModel::clearShown() {
    frontCache_.reset();
    selectionTree_.reset();
    built_ = {};
    subtreeTriangles_.clear();
    depths_.clear();
    leafOfInstance_.clear();
    labels_.clear();
    keys_.clear();
}

void StudioModel::setGraph(PipelineGraph* graph) {
    if (graph == graph_) return;
    runner_->abandon();
    graph_ = graph;
    kept_.clear();
}

NodeId StudioModel::shownCluster() const {
    if (!graph_ || shown_ == kNoNode || !graph_->hasNode(shown_)) return kNoNode;
    return graph_->upstreamOfKind(shown_, NodeKind::Cluster);
}

std::vector<NodeId> StudioModel::bakeNodes() const {
    std::vector<NodeId> out;
    if (!graph_) return out;
    const std::vector<NodeId> imports = graph_->nodesOf(NodeKind::Import);
    if (imports.empty()) return out;
    for (NodeId bake : graph_->nodesOf(NodeKind::Bake)) {
        const NodeId import = graph_->upstreamOfKind(bake, NodeKind::Import);
        if (import != kNoNode && import == imports.front()) out.push_back(bake);
    }
    return out;
}

QString StudioModel::branchLabel(NodeId bake) const {
    if (!graph_ || !graph_->hasNode(bake)) return {};
    QString text;
    for (NodeId id : graph_->branchOf(bake)) {
        const GraphNode& n = graph_->node(id);
        if (n.kind == NodeKind::Import) continue;
        if (!text.isEmpty()) text += QStringLiteral(" → ");
        text += QString::fromStdString(describeNode(n));
    }
    return text;
}

const BuiltHlod* StudioModel::builtOf(NodeId bake) const {
    const auto it = kept_.find(bake);
    return it == kept_.end() ? nullptr : &it->second;
}

void StudioModel::setShownBake(NodeId bake) {
    if (graph_ && bake != kNoNode && !graph_->hasNode(bake)) bake = kNoNode;
    if (bake == shown_) return;
    shown_ = bake;
    const BuiltHlod* kept = builtOf(bake);
    const std::shared_ptr<const NodeOutput> current =
        graph_ && bake != kNoNode ? graph_->sharedOutput(bake) : nullptr;
    if (kept && (!current || kept->build == current)) {
        show(*kept);
    } else if (current && current->scene == scene_ && current->bake) {
        // Built before this session kept it (a run of another view of the same graph).
        show(withStatistics(bake, current));
    } else {
        const bool had = hasBuild();
        clearShown();
        if (had) {
            Q_EMIT buildFinished();
            if (view_.mode != DisplayMode::Original) setMode(DisplayMode::Original);
        }
    }
    Q_EMIT shownBakeChanged();
}

void StudioModel::startRun(std::vector<NodeId> targets) {
    if (!scene_ || !graph_ || targets.empty()) return;
    runner_->start(graph_, std::move(targets));
}

void StudioModel::build() {
    if (shown_ == kNoNode || !graph_ || !graph_->hasNode(shown_)) return;
    startRun({shown_});
}

void StudioModel::buildAll() { startRun(bakeNodes()); }

void StudioModel::runExports(const std::vector<NodeId>& exports) { startRun(exports); }

void StudioModel::cancelBuild() { runner_->cancel(); }

bool StudioModel::exporting() const {
    if (!graph_) return false;
    for (NodeId id : runner_->targets())
        if (graph_->hasNode(id) && graph_->node(id).kind == NodeKind::Export) return true;
    return false;
}

void StudioModel::onRunFinished(const std::vector<BuiltHlod>& bakes) {
    for (const BuiltHlod& b : bakes)
        setBuilt(b);
    Q_EMIT runFinished();
}

void StudioModel::setBuilt(const BuiltHlod& result) {
    if (result.scene != scene_ || !result.build) return; // built for a scene no longer open
    everBuilt_ = true;
    kept_[result.bakeNode] = result;
    if (shown_ == kNoNode) {
        shown_ = result.bakeNode;
        Q_EMIT shownBakeChanged();
    }
    if (result.bakeNode == shown_) show(result);
}

void StudioModel::show(const BuiltHlod& result) {
    frontCache_.reset();
    selectionTree_.reset();
    const std::shared_ptr<const NodeOutput> previous = built_.build;
    const std::vector<ClusterKey> previousKeys = std::move(keys_);
    built_ = result;
    const ClusterTree& tree = *built_.build->tree;
    subtreeTriangles_ = hlod::subtreeTriangles(tree, *scene_);
    depths_ = nodeDepths(tree);
    keys_ = hlod::widgets::clusterKeys(tree);
    labels_ = labeller_.assign(tree, keys_);
    leafOfInstance_.assign(scene_->instances.size(), kNoId);
    std::vector<std::uint64_t> drawCost(tree.nodes.size(), 0);
    for (Id n = 0; n < tree.nodes.size(); ++n) {
        const ClusterNode& node = tree.nodes[n];
        if (node.isLeaf()) {
            drawCost[n] = subtreeTriangles_[n];
            if (node.instance < leafOfInstance_.size()) leafOfInstance_[node.instance] = n;
        } else if (n < built_.build->bake->nodes.size()) {
            drawCost[n] = built_.build->bake->nodes[n].proxy.triangleCount();
        }
    }
    selectionTree_ = std::make_unique<SelectionTree>(tree, std::move(drawCost),
                                                     rootHasNoProxy(tree, *built_.build->bake));
    frontCache_ = std::make_unique<FrontCache>(*selectionTree_);
    // The selection follows its clusters into the new tree before any view shows it.
    StudioSelection selection =
        carrySelection(previous ? previous->tree.get() : nullptr, previousKeys);
    if (selection.clusterNodes.empty() && selection.clusterNode != kNoId)
        selection.clusterNodes = {selection.clusterNode};
    const bool selectionMoved = !(selection == selection_);
    selection_ = std::move(selection);
    const int level = std::clamp(view_.level, 0, maxLevel());
    const bool levelClamped = level != view_.level;
    view_.level = level;
    Q_EMIT buildFinished();
    if (selectionMoved) Q_EMIT selectionChanged();
    if (levelClamped) Q_EMIT viewChanged();
}

StudioSelection StudioModel::carrySelection(const ClusterTree* old,
                                            const std::vector<ClusterKey>& oldKeys) {
    const ClusterTree& tree = *built_.build->tree;
    StudioSelection out;
    std::vector<Id> oldNodes = selection_.clusterNodes;
    if (oldNodes.empty() && selection_.clusterNode != kNoId) oldNodes = {selection_.clusterNode};
    const bool comparable = old && oldKeys.size() == old->nodes.size();
    if (oldNodes.empty() || !comparable) {
        // Meshes chosen in the scene tree or the viewport: the same meshes, their leaf if one.
        out.instances = selection_.instances;
        out.sceneNode = selection_.sceneNode;
        if (out.instances.size() == 1 && out.instances[0] < leafOfInstance_.size())
            out.clusterNode = leafOfInstance_[out.instances[0]];
        return out;
    }
    std::unordered_map<ClusterKey, Id> nodeOfKey;
    nodeOfKey.reserve(keys_.size());
    for (Id n = 0; n < keys_.size(); ++n)
        nodeOfKey.emplace(keys_[n], n);
    std::vector<Id> kept;
    bool lost = false;
    Id current = kNoId;
    for (Id node : oldNodes) {
        const auto it = node < oldKeys.size() ? nodeOfKey.find(oldKeys[node]) : nodeOfKey.end();
        if (it == nodeOfKey.end()) {
            lost = true;
            continue;
        }
        kept.push_back(it->second);
        if (node == selection_.clusterNode) current = it->second;
    }
    if (lost) {
        // The largest clusters of the new tree holding only meshes that were selected.
        std::vector<char> chosen(scene_->instances.size(), 0);
        for (Id i : selection_.instances)
            if (i < chosen.size()) chosen[i] = 1;
        kept = largestClustersWithin(tree, chosen);
        current = kNoId;
    }
    std::sort(kept.begin(), kept.end());
    kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
    if (kept.empty()) return out;
    out.clusterNodes = kept;
    out.clusterNode = current != kNoId ? current : kept.front();
    for (Id node : kept) {
        const std::vector<Id> below = instancesBelow(tree, node);
        out.instances.insert(out.instances.end(), below.begin(), below.end());
    }
    std::sort(out.instances.begin(), out.instances.end());
    out.instances.erase(std::unique(out.instances.begin(), out.instances.end()),
                        out.instances.end());
    if (out.instances.size() == 1) out.sceneNode = scene_->instances[out.instances[0]].node;
    return out;
}

int StudioModel::maxLevel() const { return hasBuild() ? built_.build->tree->height() : 0; }

int StudioModel::suggestedLevel() const {
    if (!hasBuild()) return 0;
    const ClusterTree& tree = *built_.build->tree;
    for (int level = 1; level < tree.height(); ++level)
        if (nodesAtLevel(tree, level).size() <= 12) return level;
    return tree.height();
}

std::vector<Id> StudioModel::instancesBelowSceneNode(Id node) const {
    std::vector<Id> out;
    if (!scene_ || node >= scene_->nodes.size()) return out;
    std::vector<Id> stack{node};
    std::vector<char> seen(scene_->nodes.size(), 0); // a malformed hierarchy must not loop
    while (!stack.empty()) {
        const Id n = stack.back();
        stack.pop_back();
        if (seen[n]) continue;
        seen[n] = 1;
        out.insert(out.end(), nodeInstances_[n].begin(), nodeInstances_[n].end());
        for (Id child : scene_->nodes[n].children)
            if (child < scene_->nodes.size()) stack.push_back(child);
    }
    std::sort(out.begin(), out.end());
    return out;
}

void StudioModel::selectInstance(Id instance) {
    if (!scene_ || instance >= scene_->instances.size()) {
        clearSelection();
        return;
    }
    StudioSelection s;
    s.instances = {instance};
    s.sceneNode = scene_->instances[instance].node;
    s.clusterNode = instance < leafOfInstance_.size() ? leafOfInstance_[instance] : kNoId;
    applySelection(std::move(s));
}

void StudioModel::selectSceneNode(Id node) {
    if (!scene_ || node >= scene_->nodes.size()) {
        clearSelection();
        return;
    }
    StudioSelection s;
    s.sceneNode = node;
    s.instances = instancesBelowSceneNode(node);
    if (s.instances.size() == 1 && s.instances[0] < leafOfInstance_.size())
        s.clusterNode = leafOfInstance_[s.instances[0]];
    applySelection(std::move(s));
}

void StudioModel::selectClusterNode(Id node) {
    if (!hasBuild() || node >= built_.build->tree->nodes.size()) {
        clearSelection();
        return;
    }
    StudioSelection s;
    s.clusterNode = node;
    s.instances = instancesBelow(*built_.build->tree, node);
    std::sort(s.instances.begin(), s.instances.end());
    if (s.instances.size() == 1) s.sceneNode = scene_->instances[s.instances[0]].node;
    applySelection(std::move(s));
}

void StudioModel::setSelection(const std::vector<Id>& nodes, Id current) {
    StudioSelection s;
    if (hasBuild()) {
        const ClusterTree& tree = *built_.build->tree;
        for (Id node : nodes)
            if (node < tree.nodes.size()) s.clusterNodes.push_back(node);
    }
    std::sort(s.clusterNodes.begin(), s.clusterNodes.end());
    s.clusterNodes.erase(std::unique(s.clusterNodes.begin(), s.clusterNodes.end()),
                         s.clusterNodes.end());
    if (s.clusterNodes.empty()) {
        clearSelection();
        return;
    }
    const bool known = std::binary_search(s.clusterNodes.begin(), s.clusterNodes.end(), current);
    s.clusterNode = known ? current : s.clusterNodes.front();
    for (Id node : s.clusterNodes) {
        const std::vector<Id> below = instancesBelow(*built_.build->tree, node);
        s.instances.insert(s.instances.end(), below.begin(), below.end());
    }
    std::sort(s.instances.begin(), s.instances.end());
    s.instances.erase(std::unique(s.instances.begin(), s.instances.end()), s.instances.end());
    if (s.instances.size() == 1) s.sceneNode = scene_->instances[s.instances[0]].node;
    applySelection(std::move(s));
}

void StudioModel::clearSelection() { applySelection({}); }

void StudioModel::applySelection(StudioSelection selection) {
    // A single cluster node (from an instance, a scene node or a cluster) is the whole set.
    if (selection.clusterNodes.empty() && selection.clusterNode != kNoId)
        selection.clusterNodes = {selection.clusterNode};
    if (selection == selection_) return;
    selection_ = std::move(selection);
    Q_EMIT selectionChanged();
}

void StudioModel::setView(const ViewOptions& view) {
    const bool same = view.mode == view_.mode && view.level == view_.level &&
                      view.bounds == view_.bounds &&
                      view.boundsOfSelectionOnly == view_.boundsOfSelectionOnly &&
                      view.tintByDepth == view_.tintByDepth;
    if (same) return;
    view_ = view;
    Q_EMIT viewChanged();
}

void StudioModel::setMode(DisplayMode mode) {
    ViewOptions v = view_;
    v.mode = mode;
    setView(v);
}

void StudioModel::setLevel(int level) {
    ViewOptions v = view_;
    v.level = std::clamp(level, 0, maxLevel());
    setView(v);
}

void StudioModel::setBounds(BoundsShape bounds) {
    ViewOptions v = view_;
    v.bounds = bounds;
    setView(v);
}

void StudioModel::setBoundsOfSelectionOnly(bool on) {
    ViewOptions v = view_;
    v.boundsOfSelectionOnly = on;
    setView(v);
}

void StudioModel::setTintByDepth(bool on) {
    ViewOptions v = view_;
    v.tintByDepth = on;
    setView(v);
}

SelectionResult StudioModel::selectLod(const Camera& camera) {
    if (!frontCache_) return {};
    SelectionParams params;
    params.screenSizePx = built_.build->bakeParams.screen.screenSize;
    return frontCache_->select(camera, params);
}

} // namespace hlod::widgets
