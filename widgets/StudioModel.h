// The editor's one owner of state: the open scene, the HLOD settings, the current HLOD build
// (cluster tree, proxies, statistics), the selection and the display options. Widgets (trees,
// viewport display, panels) show what it holds and change it through its functions; they keep
// no pipeline state of their own.
//
// Builds run in the background (HlodBuilder); the model forwards their progress and keeps the
// result only when a build finishes for the scene that is still open. A new scene drops the
// build and the selection. The runtime LOD selection of the HLOD preview (SelectionTree +
// FrontCache over the current build) lives here too, so every view of it agrees.
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
// Export: the last package written from a build (exportState()), so the Pipeline dock can tell
// whether the package is up to date with the shown build.
#pragma once

#include <memory>
#include <vector>

#include <QObject>
#include <QString>

#include "pipeline/doc/HlodBuild.h"
#include "pipeline/select/LodSelection.h"
#include "widgets/ClusterIdentity.h"
#include "widgets/HlodBuilder.h"

namespace hlod {
class Document;
}

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

// The last package export of this session (File ▸ Export Package).
struct ExportState {
    enum class Status { None, Running, Done, Failed };
    Status status = Status::None;
    std::shared_ptr<const HlodBuild> build; // what was (is being) exported
    QString folder;
    QString message; // the error of a failed export
};

class StudioModel : public QObject {
    Q_OBJECT
public:
    explicit StudioModel(QObject* parent = nullptr);
    ~StudioModel() override;

    void setScene(std::shared_ptr<const Scene> scene);
    const std::shared_ptr<const Scene>& scene() const { return scene_; }

    const HlodSettings& settings() const { return settings_; }
    void setSettings(const HlodSettings& settings);
    // The document whose parameters and hand edits the builds use (DESIGN.md: the document is
    // the one source of truth); null (the default) builds with setSettings()' values. The
    // document must outlive the model or be unset first.
    void setDocument(const Document* doc);
    // Copies the document's settings (settingsOf, ProjectSession.h) into settings().
    void syncSettings();

    // Starts a build of the open scene with the current settings, taken from the document when
    // one is set (no-op without a scene).
    void build();
    void cancelBuild();
    bool building() const { return builder_->busy(); }

    // Adopts a finished build (what a background build delivers; also a build made elsewhere,
    // e.g. read back or made by a test). Ignored unless it was made from the open scene.
    void setBuilt(const BuiltHlod& result);
    bool hasBuild() const { return built_.build != nullptr; }
    // The current build; its pointers are null before the first finished build.
    const BuiltHlod& built() const { return built_; }
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

    // Export of the current build: started (Running), finished to `folder` (Done), failed.
    void exportStarted(const QString& folder);
    void exportFinished(const QString& folder);
    void exportFailed(const QString& message);
    void exportCancelled(); // back to no export
    const ExportState& exportState() const { return export_; }
    // A package of exactly the shown build has been written.
    bool exportUpToDate() const;

Q_SIGNALS:
    void sceneChanged();
    void settingsChanged();
    void buildStarted();
    void buildProgress(const QString& stage, qint64 done, qint64 total, const QString& detail);
    void buildFinished();
    void buildFailed(const QString& message);
    void buildCancelled();
    void selectionChanged();
    void viewChanged();
    void exportChanged();

private:
    void applySelection(StudioSelection selection);
    void setView(const ViewOptions& view);
    std::vector<Id> instancesBelowSceneNode(Id node) const;
    // The selection carried over from `old` (the previous tree and its keys) to the new build.
    StudioSelection carrySelection(const ClusterTree* old, const std::vector<ClusterKey>& oldKeys);

    std::shared_ptr<const Scene> scene_;
    std::vector<std::vector<Id>> nodeInstances_; // per scene node: instances placed on it
    HlodSettings settings_;
    const Document* document_ = nullptr;
    HlodBuilder* builder_ = nullptr;
    BuiltHlod built_;
    std::vector<std::uint64_t> subtreeTriangles_;
    std::vector<int> depths_;
    std::vector<Id> leafOfInstance_;
    ClusterLabels labeller_;
    std::vector<int> labels_;
    std::vector<ClusterKey> keys_;
    ExportState export_;
    std::unique_ptr<SelectionTree> selectionTree_;
    std::unique_ptr<FrontCache> frontCache_; // refers to *selectionTree_
    StudioSelection selection_;
    ViewOptions view_;
};

} // namespace hlod::widgets
