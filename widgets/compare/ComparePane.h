// One side of the comparison view: what it shows (a Bake node of the document, or "Custom": a
// quick configuration laid over a base branch, CompareConfig.h), a configuration selector
// (volume, k, screen size), the build status with progress and Cancel, and a Viewport showing
// that side's HLOD preview with its own frame counters (draw calls, triangles, nodes visited).
//
// The pane reuses the editor's pieces instead of copying them: a StudioModel of its own holds
// the pane's scene and build (its GraphRunner runs the graph in the background, its front cache
// runs the per-frame LOD selection) and a DisplayController in HLOD preview mode draws it into
// the Viewport. A Bake-node side runs the document's own graph (its statuses show in the
// Pipeline dock, and the editor finds the node built); a Custom side runs a copy of the
// document's graph with a temporary branch: copies of the base branch's Cluster and Bake nodes
// with the configuration applied, fed by the same Import (whose scene the copy already holds).
// Editing the selector of a Bake-node side turns it into a Custom side over that node.
// Builds: rebuild() drops the shown result first, so a cancelled or failed build leaves the
// pane empty rather than showing a result of another configuration. documentChanged() rebuilds
// only when what the side builds changed (its node's definition, PipelineGraph.h). Without a
// scene nothing builds.
// Lifetime: destroying the pane cancels and joins its build (StudioModel's GraphRunner).
#pragma once

#include <memory>

#include <QWidget>

#include "widgets/compare/CompareConfig.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace hlod::widgets {

struct BuiltHlod;
struct FrameStats;
class DisplayController;
class StudioModel;
class Viewport;

class ComparePane : public QWidget {
    Q_OBJECT
public:
    enum class State { Empty, Building, Built, Cancelled, Failed };

    explicit ComparePane(const QString& title, QWidget* parent = nullptr);
    ~ComparePane() override;

    // The scene to build (the pane shows nothing until a build finishes); does not build.
    // `upAxis` (0 X, 1 Y, 2 Z) orients navigation.
    void setScene(std::shared_ptr<const Scene> scene, int upAxis);
    const std::shared_ptr<const Scene>& scene() const;
    // The document's graph (not owned: it must outlive the pane or be unset) and the Bake node a
    // Custom side is laid over; does not build.
    void setDocument(PipelineGraph* document, NodeId baseBake);
    NodeId baseBake() const { return base_; }
    // Shows `side` in the selector; rebuilds when it differs from the current one and
    // `rebuildIfChanged`.
    void setSide(const CompareSide& side, bool rebuildIfChanged = true);
    const CompareSide& side() const { return side_; }
    // The configuration of the side: the Custom one, or that of its Bake node's branch.
    CompareConfig config() const;
    // "Bake #6: AABB k=2" or "AABB k=2 (over Bake #3)".
    QString label(bool withScreenSize = false) const;
    // The document changed: refreshes the list of Bake nodes and rebuilds when what the side
    // builds changed.
    void documentChanged();

    void rebuild();
    // Stops the build: the pane is Cancelled (and not building) at once, with no result; the
    // worker winds down in the background (model()->building() until it has).
    void cancel();
    State state() const { return state_; }
    bool building() const { return state_ == State::Building; }
    // The build shown (null before one finished, after a cancel or a failure).
    const BuiltHlod* built() const;
    // Offer "Use These Settings" (a Custom side, with a document to apply them to).
    void setUseVisible(bool visible);

    StudioModel* model() const { return model_.get(); }
    Viewport* viewport() const { return viewport_; }
    DisplayController* display() const { return display_.get(); }
    QComboBox* sourceBox() const { return source_; }
    QComboBox* volumeBox() const { return volume_; }
    QDoubleSpinBox* kBox() const { return k_; }
    QDoubleSpinBox* screenSizeBox() const { return screen_; }
    QPushButton* cancelButton() const { return cancel_; }
    QPushButton* useButton() const { return use_; }
    QLabel* statusLabel() const { return status_; }
    // The same for both sides whatever their texts, so a splitter gives them equal widths (and
    // both previews select for the same frustum).
    QSize sizeHint() const override { return {640, 480}; }

Q_SIGNALS:
    // The selector changed the configuration (a rebuild has started).
    void configChanged();
    // Building started, finished, failed or was cancelled.
    void stateChanged();
    void frameStats(const hlod::widgets::FrameStats& stats);
    void useRequested();

private:
    void readSource();
    void readSelector();
    void writeSelector();
    void fillSources();
    // The graph and node this side builds (the document's, or the copy with the temporary
    // branch, remade from the document); kNoNode when it cannot build.
    std::pair<PipelineGraph*, NodeId> target();
    void updateUse();
    void setState(State state, const QString& text);
    void onProgress(const QString& stage, qint64 done, qint64 total);
    void onFinished();

    PipelineGraph* document_ = nullptr;
    NodeId base_ = kNoNode;
    CompareSide side_;
    PipelineGraph temp_;          // a Custom side's copy of the document with its branch
    std::string builtDefinition_; // of what the last rebuild() ran
    bool useWanted_ = false;
    State state_ = State::Empty;
    std::unique_ptr<StudioModel> model_;
    Viewport* viewport_ = nullptr;
    std::unique_ptr<DisplayController> display_;
    QLabel* title_ = nullptr;
    QComboBox* source_ = nullptr;
    QComboBox* volume_ = nullptr;
    QDoubleSpinBox* k_ = nullptr;
    QDoubleSpinBox* screen_ = nullptr;
    QLabel* status_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QPushButton* cancel_ = nullptr;
    QPushButton* use_ = nullptr;
    // The pane itself is setting the selector or restarting its model: the signals that causes
    // are not the user's edits or cancels.
    bool writing_ = false;
};

} // namespace hlod::widgets
