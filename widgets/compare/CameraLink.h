// Links the cameras of two viewports both ways: whatever moves one camera (orbit, pan, zoom,
// fit, a key) moves the other to the same pose, and the other viewport repaints.
//
// How: an observer on each vtkCamera's ModifiedEvent copies position, focal point, view up and
// view angle to the other camera when they differ. The copy itself modifies the other camera;
// a guard drops that echo, and the "when they differ" test makes the clipping-range updates
// every frame does (Viewport::paintGL) cost nothing, so there is no feedback loop.
// The link holds a reference to both cameras and removes its observers when destroyed, so it
// may outlive the viewports (they are then no longer repainted).
#pragma once

#include <QObject>
#include <QPointer>
#include <vtkCamera.h>
#include <vtkSmartPointer.h>

class vtkObject;

namespace hlod::widgets {

class Viewport;

class CameraLink : public QObject {
    Q_OBJECT
public:
    CameraLink(Viewport* a, Viewport* b, QObject* parent = nullptr);
    ~CameraLink() override;

    void setEnabled(bool enabled);
    bool enabled() const { return enabled_; }
    // Copies the pose of `from` to the first viewport's camera (and so to the second).
    void copyFrom(const vtkCamera* from);
    // Times a camera was moved to follow the other one (tests check the link does not echo).
    int copies() const { return copies_; }

    static bool samePose(const vtkCamera* a, const vtkCamera* b);

private:
    void onModified(vtkObject* caller, unsigned long event, void* data);
    void follow(vtkCamera* source, vtkCamera* target, Viewport* targetView);

    QPointer<Viewport> a_, b_;
    vtkSmartPointer<vtkCamera> cameraA_, cameraB_;
    unsigned long observerA_ = 0, observerB_ = 0;
    bool enabled_ = true;
    bool copying_ = false;
    int copies_ = 0;
};

} // namespace hlod::widgets
