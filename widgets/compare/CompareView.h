// The comparison view of the editor (issue #7, issue 29): two branches of the same scene side
// by side (for example sphere against AABB k=2, the thesis' comparison of chapter 6), each in
// its own pane with its HLOD preview and frame counters, the two cameras linked both ways, and a
// statistics table below (draw calls and triangles of the current frame, tree nodes, proxy
// triangles, package size) with the better value of each row highlighted.
//
// A side is any Bake node of the document, or a quick configuration over a branch that the view
// builds as a temporary branch (CompareConfig.h, ComparePane.h). Both sides build in the
// background at once (one GraphRunner each, inside each pane's StudioModel) through the
// document's graph, so they reuse the document's proxy cache and outputs like the editor's own
// runs. Changing one side's selector rebuilds that side only; documentChanged() rebuilds only
// the sides whose node changed. With an UndoAdapter set, a quick-configuration pane offers "Use
// These Settings", which applies its configuration to the branch it is laid over as one
// undoable command (SetParameters).
// The view shows BuiltHlods and holds no pipeline state of its own; closing it cancels the
// builds, destroying it also joins them.
// Keys: F fits both views to the scene (the panes' viewports show no SceneActors of their
// own, so the view fits to the scene's instance boxes itself); Esc or the Close button closes
// the window (issue 20 #8).
#pragma once

#include <memory>
#include <utility>

#include <QWidget>

#include "widgets/compare/CompareConfig.h"

class QCheckBox;
class QLabel;
class QPushButton;
class vtkCamera;

namespace hlod::widgets {

class CameraLink;
class ComparePane;
class CompareTable;
class UndoAdapter;

class CompareView : public QWidget {
    Q_OBJECT
public:
    explicit CompareView(QWidget* parent = nullptr);
    ~CompareView() override;

    // Shows `scene` (what `document`'s first Import gives) with `sides` (left, right), quick
    // configurations laid over the branch of `baseBake`, and builds both sides. `document` is
    // not owned: it must outlive the view or be replaced by another open().
    void open(std::shared_ptr<const Scene> scene, PipelineGraph* document, NodeId baseBake,
              const std::pair<CompareSide, CompareSide>& sides);
    const std::shared_ptr<const Scene>& scene() const;
    // The document changed; rebuilds each side whose node changed.
    void documentChanged();
    // Lets go of the document and the scene at once (runs dropped, nothing shown): its content
    // is about to be replaced. open() takes them again.
    void detach();
    // The document "Use These Settings" applies to; null hides the buttons.
    void setUndo(UndoAdapter* undo);

    void rebuildAll();
    void cancelAll();
    bool building() const;
    // Both sides have a finished build and neither is building.
    bool allBuilt() const;

    // Both cameras to the pose of `camera` (the editor's view).
    void copyCamera(const vtkCamera* camera);
    // Looks at the whole scene from the current direction, in both panes.
    void fitView();

    ComparePane* left() const { return left_; }
    ComparePane* right() const { return right_; }
    CompareTable* table() const { return table_; }
    CameraLink* cameraLink() const { return link_; }
    QCheckBox* linkBox() const { return linkBox_; }
    QLabel* messageLabel() const { return message_; }
    QPushButton* closeButton() const { return close_; }

Q_SIGNALS:
    // Both sides finished building (after any build of either side).
    void buildsFinished();
    // "Use These Settings" changed the document; `label` names the configuration.
    void settingsUsed(const QString& label);

protected:
    void closeEvent(QCloseEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void onStateChanged(ComparePane* pane);
    void useSettings(ComparePane* pane);
    void updateTitles();

    ComparePane* left_ = nullptr;
    ComparePane* right_ = nullptr;
    CompareTable* table_ = nullptr;
    CameraLink* link_ = nullptr;
    QCheckBox* linkBox_ = nullptr;
    QPushButton* fit_ = nullptr;
    QPushButton* rebuild_ = nullptr;
    QPushButton* close_ = nullptr;
    QLabel* message_ = nullptr;
    UndoAdapter* undo_ = nullptr;
    int upAxis_ = 1;
};

} // namespace hlod::widgets
