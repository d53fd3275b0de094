// The editor's one owner of state: the open scene, the Bake node whose HLOD is shown and its
// build (cluster tree, proxies, statistics), the selection and the display options. Widgets
// (trees, viewport display, panels) show what it holds and change it through its functions; they
// keep no pipeline state of their own.
//
// Builds are runs of the pipeline graph (setGraph: the document's, or a comparison pane's own),
// in the background (GraphRunner): build() runs the shown Bake node, buildAll() every Bake node
// of the open scene, runExports() Export nodes (packages). Each run brings its statuses into the
// graph node by node (the Pipeline dock shows them), and every Bake node it built is kept with
// its statistics, so showing another branch (setShownBake) shows its last build at once. The
// model shows a build only when it was made from the scene that is still open. A new scene drops
// the builds and the selection. The runtime LOD selection of the HLOD preview (SelectionTree +
// FrontCache over the shown build) lives here too, so every view of it agrees.
// Selection: a set of scene instances, plus the scene node and cluster node it came from (or
// that correspond to it: picking an instance selects its scene node and its cluster leaf).
// Several cluster nodes can be selected at once (setSelection(nodes, current): the rows of a
// Ctrl/Shift-click multi-selection in the Clusters tree); the instances are then the union of
// their subtrees and clusterNode is the current one of them (the row clicked last).
// Signals are emitted only on real changes, so views can sync both ways without loops.
// Across rebuilds (an edit, its undo, a parameter change) clusters keep their identity
// (ClusterIdentity.h): clusterLabels() gives a cluster the label it had while its meshes are the
// same, and the selection keeps the clusters that still exist; when one is gone (split, moved
// into), the largest clusters holding only the selected meshes are selected instead. The
// selection is settled before buildFinished, so every view shows the new tree with it.
#pragma once

#include <memory>
#include <vector>

#include <QObject>
#include <QString>

#include <map>

#include "pipeline/select/LodSelection.h"
#include "widgets/ClusterIdentity.h"
#include "widgets/GraphRunner.h"

namespace hlod::widgets {

enum class DisplayMode { Original, Clusters, Hlod };
enum class BoundsShape { None, Spheres, Boxes };

// Parses "original", "clusters", "hlod"; false when `text` is none of them.
bool displayModeFromString(const QString& text, DisplayMode& mode);

struct ViewOptions {
    DisplayMode mode = DisplayMode::Original;
    int level = 1; // cluster level shown in Clusters mode (0 = leaves)
    BoundsShape bounds = BoundsShape::Spheres;
    bool boundsOfSelectionOnly = false; // bounds of the selected cluster's subtree, not the level
    bool tintByDepth = false;           // HLOD preview: colour drawn nodes by their tree depth
};

struct StudioSelection {
    std::vector<Id> instances; // sorted scene instance ids
    Id sceneNode = kNoId;
    Id clusterNode = kNoId;       // the current cluster node (one of clusterNodes)
    std::vector<Id> clusterNodes; // every selected cluster node, sorted
    bool empty() const { return instances.empty() && clusterNode == kNoId; }
    bool operator==(const StudioSelection&) const = default;
};

class StudioModel : public QObject {
    Q_OBJECT
public:
    explicit StudioModel(QObject* parent = nullptr);
    ~StudioModel() override;

    void setScene(std::shared_ptr<const Scene> scene);
    const std::shared_ptr<const Scene>& scene() const { return scene_; }

    // The graph the model runs and shows Bake nodes of (not owned: it must outlive the model
    // or be unset first). Setting another one drops the kept builds.
    void setGraph(PipelineGraph* graph);
    PipelineGraph* graph() const { return graph_; }

    // The Bake node whose HLOD is shown (kNoNode: none). Its last build is shown at once when
    // there is one (kept from a run of this session, or the graph's up-to-date output); else
    // nothing is (hasBuild() false) until it is built. Emits shownBakeChanged.
    void setShownBake(NodeId bake);
    NodeId shownBake() const { return shown_; }
    // The Cluster node upstream of the shown Bake node (kNoNode when none): the one hand edits
    // act on.
    NodeId shownCluster() const;
    // The Bake nodes the editor can show: those of the graph fed by its first Import node (the
    // open scene), ascending.
    std::vector<NodeId> bakeNodes() const;
    // "Cluster #5 → Bake #6" (names included): the branch of a Bake node, as views name it.
    QString branchLabel(NodeId bake) const;

    // Runs the shown Bake node / every node of bakeNodes() / the Export nodes `exports` (no-op
    // without a scene or a graph, or with nothing to run).
    void build();
    void buildAll();
    void runExports(const std::vector<NodeId>& exports);
    void cancelBuild();
    bool building() const { return runner_->busy(); }
    // The nodes the running run was asked for (empty when idle).
    const std::vector<NodeId>& runTargets() const { return runner_->targets(); }
    // Whether the running run brings `node` up to date as the graph defines it now.
    bool runCovers(NodeId node) const { return runner_->covers(node); }
    // Whether the running run writes packages (one of its targets is an Export node).
    bool exporting() const;
    // Whether a run of this session built something for the open scene (AutoRebuild starts only
    // after that).
    bool everBuilt() const { return everBuilt_; }

    // Adopts a finished build of a Bake node (what a run delivers; also a build made elsewhere,
    // e.g. by a test), keeps it for its node and shows it when it is of the shown node (or no
    // node is shown: it becomes the shown one). Ignored unless it was made from the open scene.
    void setBuilt(const BuiltHlod& result);
    bool hasBuild() const { return built_.build != nullptr; }
    // The shown build; its pointers are null before one exists.
    const BuiltHlod& built() const { return built_; }
    // The kept build of `bake` (nullptr when none).
    const BuiltHlod* builtOf(NodeId bake) const;
    // Per cluster node: original triangles of its subtree; its depth from the root.
    const std::vector<std::uint64_t>& subtreeTriangles() const { return subtreeTriangles_; }
    const std::vector<int>& depths() const { return depths_; }
    // Per node of the current build: the cluster's label (stable across rebuilds, see above) and
    // the key of its leaf set (ClusterIdentity.h). Empty without a build.
    const std::vector<int>& clusterLabels() const { return labels_; }
    const std::vector<ClusterKey>& clusterKeys() const { return keys_; }
    // Levels that can be shown: 0 .. height of the tree (0 without a build).
    int maxLevel() const;
    // A level with a handful of clusters (at most 12), what Clusters mode starts with.
    int suggestedLevel() const;

    void selectInstance(Id instance);
    void selectSceneNode(Id node);
    void selectClusterNode(Id node);
    // Selects the cluster nodes `nodes` together (ids outside the build are dropped); `current`
    // becomes clusterNode when it is one of them, else the first of them.
    void setSelection(const std::vector<Id>& nodes, Id current = kNoId);
    void clearSelection();
    const StudioSelection& selection() const { return selection_; }
    // The selected cluster nodes (sorted; one for a single selection, none without a cluster).
    const std::vector<Id>& selectedNodes() const { return selection_.clusterNodes; }

    const ViewOptions& view() const { return view_; }
    void setMode(DisplayMode mode);
    void setLevel(int level); // clamped to 0 .. maxLevel()
    void setBounds(BoundsShape bounds);
    void setBoundsOfSelectionOnly(bool on);
    void setTintByDepth(bool on);

    // The HLOD preview's draw list for a camera (frame-coherent; same cut as Algorithm 5).
    // Empty without a build.
    SelectionResult selectLod(const Camera& camera);

Q_SIGNALS:
    void sceneChanged();
    void shownBakeChanged();
    // A run started (any run: a build, all branches, exports).
    void buildStarted();
    void buildProgress(const QString& stage, qint64 done, qint64 total, const QString& detail);
    // Progress of one node's step during a run.
    void nodeProgress(quint32 node, const QString& stage, qint64 done, qint64 total);
    // A status of a run was taken into the graph.
    void nodeStatusChanged(quint32 node);
    // The shown build was replaced (a run, setBuilt, another Bake node shown).
    void buildFinished();
    // A run ended well (after buildFinished when it built the shown node), failed, or was
    // cancelled.
    void runFinished();
    void buildFailed(const QString& message);
    void buildCancelled();
    void selectionChanged();
    void viewChanged();

private:
    void startRun(std::vector<NodeId> targets);
    void onRunFinished(const std::vector<BuiltHlod>& bakes);
    void show(const BuiltHlod& result);
    void clearShown();
    void applySelection(StudioSelection selection);
    void setView(const ViewOptions& view);
    std::vector<Id> instancesBelowSceneNode(Id node) const;
    // The selection carried over from `old` (the previous tree and its keys) to the new build.
    StudioSelection carrySelection(const ClusterTree* old, const std::vector<ClusterKey>& oldKeys);

    std::shared_ptr<const Scene> scene_;
    std::vector<std::vector<Id>> nodeInstances_; // per scene node: instances placed on it
    PipelineGraph* graph_ = nullptr;
    NodeId shown_ = kNoNode;
    GraphRunner* runner_ = nullptr;
    bool everBuilt_ = false;
    std::map<NodeId, BuiltHlod> kept_; // the last build of each Bake node, this scene
    BuiltHlod built_;
    std::vector<std::uint64_t> subtreeTriangles_;
    std::vector<int> depths_;
    std::vector<Id> leafOfInstance_;
    ClusterLabels labeller_;
    std::vector<int> labels_;
    std::vector<ClusterKey> keys_;
    std::unique_ptr<SelectionTree> selectionTree_;
    std::unique_ptr<FrontCache> frontCache_; // refers to *selectionTree_
    StudioSelection selection_;
    ViewOptions view_;
};

} // namespace hlod::widgets
