// One side of the comparison view: a configuration selector (volume, k, screen size), the
// build status with progress and Cancel, and a Viewport showing that configuration's HLOD
// preview with its own frame counters (draw calls, triangles, nodes visited).
//
// The pane reuses the editor's pieces instead of copying them: a StudioModel of its own holds
// the pane's scene and build (its HlodBuilder builds in the background, its front cache runs
// the per-frame LOD selection) and a DisplayController in HLOD preview mode draws it into the
// Viewport. The pane itself keeps only the base settings and its CompareConfig.
// Builds: rebuild() drops the shown result first, so a cancelled or failed build leaves the
// pane empty rather than showing a result of another configuration. Changing the selector
// rebuilds this pane only. Without a scene nothing builds.
// Lifetime: destroying the pane cancels and joins its build (StudioModel's HlodBuilder).
#pragma once

#include <memory>

#include <QWidget>

#include "pipeline/doc/HlodBuild.h"
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
    // The settings the configuration is laid over (the document's); does not build.
    void setBaseSettings(const HlodSettings& base) { base_ = base; }
    const HlodSettings& baseSettings() const { return base_; }
    // Shows `config` in the selector; rebuilds when it differs from the current one and
    // `rebuildIfChanged`.
    void setConfig(const CompareConfig& config, bool rebuildIfChanged = true);
    const CompareConfig& config() const { return config_; }
    // What this pane builds with: the base settings with its configuration.
    HlodSettings settings() const { return applyConfig(base_, config_); }

    void rebuild();
    // Stops the build: the pane is Cancelled (and not building) at once, with no result; the
    // worker winds down in the background (model()->building() until it has).
    void cancel();
    State state() const { return state_; }
    bool building() const { return state_ == State::Building; }
    // The build shown (null before one finished, after a cancel or a failure).
    const BuiltHlod* built() const;
    // Show "Use these settings" (only when there is a document to apply them to).
    void setUseVisible(bool visible);

    StudioModel* model() const { return model_.get(); }
    Viewport* viewport() const { return viewport_; }
    DisplayController* display() const { return display_.get(); }
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
    void readSelector();
    void writeSelector();
    void setState(State state, const QString& text);
    void onProgress(const QString& stage, qint64 done, qint64 total);
    void onFinished();

    HlodSettings base_;
    CompareConfig config_;
    State state_ = State::Empty;
    std::unique_ptr<StudioModel> model_;
    Viewport* viewport_ = nullptr;
    std::unique_ptr<DisplayController> display_;
    QLabel* title_ = nullptr;
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
