// The 3D viewport: a QOpenGLWidget that hosts VTK rendering in its own GL context.
//
// Why not QVTKOpenGLNativeWidget: Debian's VTK 9.1 builds VTK::GUISupportQt against Qt 5, so
// this widget owns a vtkGenericOpenGLRenderWindow that borrows the widget's context
// (SetOwnContext(false), InitializeFromCurrentContext() in initializeGL) and, at the end of each
// Render() in paintGL, blits VTK's framebuffer into the widget's framebuffer (BlitToCurrent).
// Navigation drives the vtkCamera directly (CameraController): no vtkRenderWindowInteractor.
//
// Mouse: left drag orbits, middle drag or Shift+left pans, right drag or Ctrl+left zooms, the
// wheel zooms; clicks without a drag are reported (clicked, ctrlClicked, contextClicked).
// Keys: F fits the view, arrows orbit in 10 degree steps, +/- zoom.
//
// Without a usable OpenGL 3.2 context the widget shows a message instead of rendering and
// reports it through glFailed(); nothing in VTK is touched then.
// The viewport shows SceneActors it is given; it keeps no scene or pipeline state of its own.
// Other views add their own props to renderer() (cluster colours, the HLOD preview, overlays):
// clearScene() removes only the scene's actors. A left click without a drag reports clicked()
// and pick() finds the prop and cell under a point; aboutToRender() lets a view update what it
// shows for the exact camera of the coming frame (the HLOD preview's LOD selection).
#pragma once

#include <memory>

#include <QImage>
#include <QOpenGLWidget>
#include <QPoint>
#include <QTimer>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include "widgets/CameraController.h"

class QLabel;
class vtkCamera;
class vtkGenericOpenGLRenderWindow;
class vtkObject;
class vtkProp;
class vtkRenderer;

namespace hlod::widgets {

class SceneActors;

class Viewport : public QOpenGLWidget {
    Q_OBJECT
public:
    explicit Viewport(QWidget* parent = nullptr);
    ~Viewport() override;

    // Replaces what is shown. `upAxis` (0 X, 1 Y, 2 Z) orients navigation; when `resetView`
    // is true the camera goes to the default direction and fits the new scene.
    void setSceneActors(std::shared_ptr<SceneActors> actors, int upAxis = 1, bool resetView = true);
    void clearScene();
    const std::shared_ptr<SceneActors>& sceneActors() const { return actors_; }
    // Shows or hides the scene's own actors (other display modes draw something else).
    void setSceneActorsVisible(bool visible);
    bool sceneActorsVisible() const { return sceneVisible_; }

    struct PickResult {
        vtkProp* prop = nullptr; // null: nothing pickable under the point
        vtkIdType cell = -1;
    };
    // The pickable prop and cell under `pos` (widget coordinates, logical pixels).
    PickResult pick(const QPoint& pos);
    // Height of the rendered frame in device pixels (what a LOD selection projects onto).
    int frameHeight() const;

    // Navigation, also used by menus and tests. Each schedules a repaint.
    void fitView();
    void resetView(); // default direction, then fit
    void orbit(double azimuthDegrees, double elevationDegrees);
    void pan(double dxPixels, double dyPixels);
    void zoom(double factor); // > 1 zooms in

    // Renders (if needed) and returns the current frame, opaque RGB32, in device pixels.
    // Null image when OpenGL is unavailable.
    QImage grabFrame();

    bool glAvailable() const { return glProblem_.isEmpty(); }
    QString glProblem() const { return glProblem_; }
    int framesRendered() const { return frames_; }

    vtkRenderer* renderer() const;
    vtkCamera* camera() const;

Q_SIGNALS:
    void frameRendered();
    // Emitted in paintGL before VTK renders (the GL context is current).
    void aboutToRender();
    // A left button press and release without dragging, in widget coordinates.
    void clicked(const QPoint& pos);
    // The same with Ctrl held (add to / remove from a selection; a Ctrl drag still zooms).
    void ctrlClicked(const QPoint& pos);
    // A right button press and release without dragging (a context menu; a drag still zooms).
    void contextClicked(const QPoint& pos);
    void glFailed(const QString& message);

protected:
    void initializeGL() override;
    void resizeGL(int w, int h) override;
    void paintGL() override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    enum class Drag { None, Orbit, Pan, Zoom };

    void onRenderWindowEvent(vtkObject* caller, unsigned long event, void* callData);
    void releaseGraphics();
    void showGlProblem(const QString& detail);
    void clearAlpha();
    void cameraChanged();
    // Fast frames (no anti-aliasing) while the user moves the camera.
    void setInteractive(bool interactive);
    double aspect() const;

    vtkNew<vtkGenericOpenGLRenderWindow> renderWindow_;
    vtkNew<vtkRenderer> renderer_;
    CameraController controller_;
    std::shared_ptr<SceneActors> actors_;
    std::vector<unsigned long> observers_;
    QLabel* message_ = nullptr;
    QString glProblem_;
    bool vtkReady_ = false;
    bool inPaint_ = false;
    bool fitPending_ = false; // fit once the widget has its real size
    int frames_ = 0;
    Drag drag_ = Drag::None;
    QPoint lastPos_;
    QPoint pressPos_;
    bool dragged_ = false; // the left button moved far enough to be a drag, not a click
    bool sceneVisible_ = true;
    QTimer settleTimer_; // ends the fast frames after the last wheel event
};

} // namespace hlod::widgets
