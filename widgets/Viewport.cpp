// The 3D viewport: VTK rendering inside a QOpenGLWidget (see Viewport.h for the design).
#include "widgets/Viewport.h"

#include <cmath>

#include <QKeyEvent>
#include <QLabel>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QResizeEvent>
#include <QTimer>
#include <QWheelEvent>
#include <vtkCamera.h>
#include <vtkCellPicker.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkLightKit.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>

#include "widgets/GlSupport.h"
#include "widgets/SceneActors.h"

namespace hlod::widgets {

namespace {

// Degrees of orbit per pixel of mouse drag: a drag across a 700 px view turns ~ 250 degrees.
constexpr double kOrbitPerPixel = 0.35;
// Zoom per wheel notch and per pixel of right-drag.
constexpr double kWheelZoom = 1.15;
constexpr double kDragZoomPerPixel = 1.01;
// Pointer travel (pixels) below which a press and release is a click, not a drag.
constexpr int kClickSlop = 4;

} // namespace

Viewport::Viewport(QWidget* parent)
    : QOpenGLWidget(parent), controller_(renderer_->GetActiveCamera()) {
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(160, 120);

    // Gradient from a light grey-blue floor to a darker slate sky: neutral for any material
    // colour and different enough from white and black parts to read silhouettes.
    renderer_->GradientBackgroundOn();
    renderer_->SetBackground(0.86, 0.88, 0.91);  // bottom
    renderer_->SetBackground2(0.36, 0.41, 0.50); // top
    renderer_->SetBackgroundAlpha(1.0);
    // Anti-aliasing without a multisampled context; switched off while the camera moves (it
    // costs about half of a frame on llvmpipe) and back on for the still frame.
    renderer_->UseFXAAOn();
    settleTimer_.setSingleShot(true);
    settleTimer_.setInterval(250);
    connect(&settleTimer_, &QTimer::timeout, this, [this] { setInteractive(false); });
    renderer_->SetTwoSidedLighting(true);
    renderer_->AutomaticLightCreationOff();
    // Key, fill and back lights that follow the camera: every side of an orbited model is lit.
    vtkNew<vtkLightKit> lights;
    lights->SetKeyLightIntensity(0.7);
    lights->AddLightsToRenderer(renderer_);
    renderer_->GetActiveCamera()->SetViewAngle(30.0);

    renderWindow_->AddRenderer(renderer_);
    renderWindow_->SetMultiSamples(0);
    renderWindow_->SetReadyForRendering(false); // until initializeGL has a context for it
    for (unsigned long event : {vtkCommand::WindowMakeCurrentEvent,
                                vtkCommand::WindowIsCurrentEvent, vtkCommand::WindowFrameEvent})
        observers_.push_back(
            renderWindow_->AddObserver(event, this, &Viewport::onRenderWindowEvent));
}

Viewport::~Viewport() {
    releaseGraphics();
    for (unsigned long id : observers_)
        renderWindow_->RemoveObserver(id);
}

vtkRenderer* Viewport::renderer() const { return renderer_; }
vtkCamera* Viewport::camera() const { return renderer_->GetActiveCamera(); }

void Viewport::onRenderWindowEvent(vtkObject*, unsigned long event, void* callData) {
    switch (event) {
    case vtkCommand::WindowMakeCurrentEvent:
        // VTK asks for its context often, also in the middle of a frame while one of its own
        // framebuffers is bound. QOpenGLWidget::makeCurrent() rebinds the widget's framebuffer
        // behind VTK's state cache (VTK would then attach its textures to Qt's framebuffer),
        // so only switch when another context is current (releasing resources outside paintGL).
        if (context() && QOpenGLContext::currentContext() != context()) makeCurrent();
        break;
    case vtkCommand::WindowIsCurrentEvent:
        *static_cast<bool*>(callData) = context() && QOpenGLContext::currentContext() == context();
        break;
    case vtkCommand::WindowFrameEvent:
        // A Render() started outside paintGL drew into VTK's buffer only: show it.
        if (!inPaint_) update();
        break;
    default:
        break;
    }
}

void Viewport::initializeGL() {
    if (!context() || !context()->isValid() || !formatIsSufficient(context()->format())) {
        const QSurfaceFormat got = context() ? context()->format() : QSurfaceFormat();
        showGlProblem(tr("This widget received an OpenGL %1.%2 context.")
                          .arg(got.majorVersion())
                          .arg(got.minorVersion()));
        return;
    }
    // The context is recreated when the widget moves to another top-level window: VTK's
    // resources belong to the old one and must be released before it goes.
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::releaseGraphics,
            Qt::UniqueConnection);
    renderWindow_->SetReadyForRendering(true);
    renderWindow_->SetOwnContext(false);
    renderWindow_->InitializeFromCurrentContext();
    renderWindow_->SetFrameBlitModeToBlitToCurrent();
    const qreal dpr = devicePixelRatioF();
    renderWindow_->SetSize(std::lround(width() * dpr), std::lround(height() * dpr));
    vtkReady_ = true;
}

void Viewport::releaseGraphics() {
    if (!vtkReady_) return;
    makeCurrent();
    renderWindow_->Finalize();
    renderWindow_->SetReadyForRendering(false);
    doneCurrent();
    vtkReady_ = false;
}

void Viewport::resizeGL(int w, int h) {
    const qreal dpr = devicePixelRatioF();
    renderWindow_->SetSize(std::lround(w * dpr), std::lround(h * dpr));
}

void Viewport::resizeEvent(QResizeEvent* event) {
    QOpenGLWidget::resizeEvent(event);
    if (message_) message_->setGeometry(rect());
    if (fitPending_ && width() > 0 && height() > 0) fitView();
}

void Viewport::paintGL() {
    if (!vtkReady_) {
        // No VTK (no context, or one too old): a flat grey behind the message label.
        if (QOpenGLContext::currentContext()) {
            QOpenGLFunctions* f = context()->functions();
            f->glClearColor(0.5f, 0.5f, 0.5f, 1.0f);
            f->glClear(GL_COLOR_BUFFER_BIT);
        }
        return;
    }
    inPaint_ = true;
    // Qt may have changed GL state (and the bound framebuffer) since VTK's last frame, while
    // VTK caches state: re-read it so VTK blits into the widget's framebuffer.
    vtkOpenGLState* state = renderWindow_->GetState();
    state->Reset();
    state->ResetFramebufferBindings();
    state->Push();
    Q_EMIT aboutToRender();
    renderer_->ResetCameraClippingRange();
    renderWindow_->Render();
    state->Pop();
    clearAlpha();
    inPaint_ = false;
    ++frames_;
    Q_EMIT frameRendered();
}

void Viewport::clearAlpha() {
    // VTK's framebuffer may leave alpha below 1 (translucent parts, FXAA); Qt composites the
    // widget with blending and a grabbed frame would come out premultiplied dark.
    QOpenGLFunctions* f = context()->functions();
    f->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    f->glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    f->glClear(GL_COLOR_BUFFER_BIT);
    f->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void Viewport::showGlProblem(const QString& detail) {
    glProblem_ = glUnavailableMessage(detail);
    if (!message_) {
        message_ = new QLabel(this);
        message_->setWordWrap(true);
        message_->setAlignment(Qt::AlignCenter);
        message_->setMargin(24);
        message_->setAutoFillBackground(true);
    }
    message_->setText(glProblem_);
    message_->setGeometry(rect());
    message_->show();
    Q_EMIT glFailed(glProblem_);
}

void Viewport::setSceneActors(std::shared_ptr<SceneActors> actors, int upAxis, bool resetView) {
    clearScene();
    actors_ = std::move(actors);
    if (actors_) {
        for (const auto& actor : actors_->actors()) {
            actor->SetVisibility(sceneVisible_);
            renderer_->AddActor(actor);
        }
    }
    controller_.setUpAxis(upAxis);
    if (resetView) this->resetView();
    update();
}

void Viewport::clearScene() {
    if (!actors_) return;
    // Removing actors may release their GL buffers: VTK then asks for the context itself.
    for (const auto& actor : actors_->actors())
        renderer_->RemoveActor(actor);
    actors_.reset();
    update();
}

void Viewport::setSceneActorsVisible(bool visible) {
    sceneVisible_ = visible;
    if (actors_)
        for (const auto& actor : actors_->actors())
            actor->SetVisibility(visible);
    update();
}

int Viewport::frameHeight() const {
    return static_cast<int>(std::lround(height() * devicePixelRatioF()));
}

Viewport::PickResult Viewport::pick(const QPoint& pos) {
    PickResult result;
    if (!vtkReady_) return result;
    const qreal dpr = devicePixelRatioF();
    // VTK's display coordinates start at the bottom left, in device pixels.
    const double x = (pos.x() + 0.5) * dpr;
    const double y = (height() - pos.y() - 0.5) * dpr;
    renderer_->ResetCameraClippingRange();
    vtkNew<vtkCellPicker> picker;
    picker->SetTolerance(0.0005);
    if (picker->Pick(x, y, 0.0, renderer_) == 0) return result;
    result.prop = picker->GetViewProp();
    result.cell = picker->GetCellId();
    return result;
}

double Viewport::aspect() const {
    return height() > 0 ? static_cast<double>(width()) / height() : 1.0;
}

void Viewport::fitView() {
    if (!actors_ || actors_->parts().empty()) return;
    // Before the first resize the widget has a provisional size: fit again once it is real.
    fitPending_ = !isVisible();
    controller_.fit(actors_->fitPoints(), aspect());
    cameraChanged();
}

void Viewport::resetView() {
    controller_.setDefaultDirection();
    fitView();
}

void Viewport::orbit(double azimuthDegrees, double elevationDegrees) {
    controller_.orbit(azimuthDegrees, elevationDegrees);
    cameraChanged();
}

void Viewport::pan(double dxPixels, double dyPixels) {
    controller_.pan(dxPixels, dyPixels, height());
    cameraChanged();
}

void Viewport::zoom(double factor) {
    controller_.dolly(factor);
    cameraChanged();
}

void Viewport::cameraChanged() {
    renderer_->ResetCameraClippingRange();
    update();
}

QImage Viewport::grabFrame() {
    if (!glAvailable()) return {};
    return grabFramebuffer().convertToFormat(QImage::Format_RGB32);
}

void Viewport::mousePressEvent(QMouseEvent* event) {
    const bool shift = event->modifiers() & Qt::ShiftModifier;
    const bool ctrl = event->modifiers() & Qt::ControlModifier;
    switch (event->button()) {
    case Qt::LeftButton:
        drag_ = shift ? Drag::Pan : ctrl ? Drag::Zoom : Drag::Orbit;
        break;
    case Qt::MiddleButton:
        drag_ = Drag::Pan;
        break;
    case Qt::RightButton:
        drag_ = Drag::Zoom;
        break;
    default:
        QOpenGLWidget::mousePressEvent(event);
        return;
    }
    lastPos_ = event->position().toPoint();
    pressPos_ = lastPos_;
    dragged_ = false;
    setInteractive(true);
    event->accept();
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
    if (drag_ == Drag::None) {
        QOpenGLWidget::mouseMoveEvent(event);
        return;
    }
    const QPoint pos = event->position().toPoint();
    // A few pixels of hand jitter still count as a click, and do not turn the view.
    if (!dragged_ && (pos - pressPos_).manhattanLength() < kClickSlop) return;
    dragged_ = true;
    const QPoint delta = pos - lastPos_;
    lastPos_ = pos;
    switch (drag_) {
    case Drag::Orbit:
        // The scene follows the cursor: dragging right turns its front to the right, dragging
        // down shows more of its top.
        orbit(-delta.x() * kOrbitPerPixel, delta.y() * kOrbitPerPixel);
        break;
    case Drag::Pan:
        pan(delta.x(), delta.y());
        break;
    case Drag::Zoom:
        zoom(std::pow(kDragZoomPerPixel, -delta.y())); // drag up zooms in
        break;
    case Drag::None:
        break;
    }
    event->accept();
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
    const bool still = drag_ != Drag::None && !dragged_;
    const Qt::KeyboardModifiers mods = event->modifiers();
    const bool left = still && event->button() == Qt::LeftButton && !(mods & Qt::ShiftModifier);
    const bool click = left && !(mods & Qt::ControlModifier);
    const bool ctrlClick = left && (mods & Qt::ControlModifier);
    const bool context = still && event->button() == Qt::RightButton;
    drag_ = Drag::None;
    setInteractive(false);
    event->accept();
    if (click) Q_EMIT clicked(pressPos_);
    if (ctrlClick) Q_EMIT ctrlClicked(pressPos_);
    if (context) Q_EMIT contextClicked(pressPos_);
}

void Viewport::setInteractive(bool interactive) {
    if (interactive) {
        settleTimer_.stop();
        renderer_->UseFXAAOff();
        return;
    }
    if (drag_ != Drag::None) return; // still dragging: the release restores quality
    renderer_->UseFXAAOn();
    update();
}

void Viewport::wheelEvent(QWheelEvent* event) {
    const double notches = event->angleDelta().y() / 120.0;
    if (notches != 0.0) zoom(std::pow(kWheelZoom, notches));
    event->accept();
}

void Viewport::keyPressEvent(QKeyEvent* event) {
    switch (event->key()) {
    case Qt::Key_F:
        fitView();
        break;
    case Qt::Key_Left:
        orbit(10.0, 0.0);
        break;
    case Qt::Key_Right:
        orbit(-10.0, 0.0);
        break;
    case Qt::Key_Up:
        orbit(0.0, -10.0);
        break;
    case Qt::Key_Down:
        orbit(0.0, 10.0);
        break;
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        zoom(kWheelZoom);
        break;
    case Qt::Key_Minus:
        zoom(1.0 / kWheelZoom);
        break;
    default:
        QOpenGLWidget::keyPressEvent(event);
        return;
    }
    event->accept();
}

} // namespace hlod::widgets
