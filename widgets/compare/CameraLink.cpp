// Two-way camera link between two viewports (see CameraLink.h).
#include "widgets/compare/CameraLink.h"

#include <cmath>

#include <vtkCommand.h>

#include "widgets/Viewport.h"

namespace hlod::widgets {

namespace {

// Equal within `tolerance` per component. Exact equality is too strict: vtkCamera::SetViewUp
// normalizes what it is given, so a copied view up may differ from its source in the last bit.
bool sameVector(const double* a, const double* b, double tolerance) {
    return std::abs(a[0] - b[0]) <= tolerance && std::abs(a[1] - b[1]) <= tolerance &&
           std::abs(a[2] - b[2]) <= tolerance;
}

double magnitude(const double* v) { return std::abs(v[0]) + std::abs(v[1]) + std::abs(v[2]); }

} // namespace

CameraLink::CameraLink(Viewport* a, Viewport* b, QObject* parent)
    : QObject(parent), a_(a), b_(b), cameraA_(a->camera()), cameraB_(b->camera()) {
    observerA_ = cameraA_->AddObserver(vtkCommand::ModifiedEvent, this, &CameraLink::onModified);
    observerB_ = cameraB_->AddObserver(vtkCommand::ModifiedEvent, this, &CameraLink::onModified);
}

CameraLink::~CameraLink() {
    cameraA_->RemoveObserver(observerA_);
    cameraB_->RemoveObserver(observerB_);
}

void CameraLink::setEnabled(bool enabled) {
    enabled_ = enabled;
    if (enabled_) follow(cameraA_, cameraB_, b_); // the second view catches up with the first
}

bool CameraLink::samePose(const vtkCamera* a, const vtkCamera* b) {
    // vtkCamera's getters are not const in VTK 9.1.
    auto* x = const_cast<vtkCamera*>(a);
    auto* y = const_cast<vtkCamera*>(b);
    // Relative to the scene's coordinates (kilometres for a track, millimetres for a part).
    const double scale = 1.0 + magnitude(x->GetPosition()) + magnitude(x->GetFocalPoint());
    constexpr double kRelative = 1e-12;
    return sameVector(x->GetPosition(), y->GetPosition(), kRelative * scale) &&
           sameVector(x->GetFocalPoint(), y->GetFocalPoint(), kRelative * scale) &&
           sameVector(x->GetViewUp(), y->GetViewUp(), 1e-12) &&
           std::abs(x->GetViewAngle() - y->GetViewAngle()) <= 1e-12;
}

void CameraLink::copyFrom(const vtkCamera* from) {
    auto* source = const_cast<vtkCamera*>(from);
    if (!source || source == cameraA_.Get()) return;
    cameraA_->SetPosition(source->GetPosition());
    cameraA_->SetFocalPoint(source->GetFocalPoint());
    cameraA_->SetViewUp(source->GetViewUp());
    cameraA_->SetViewAngle(source->GetViewAngle());
    if (a_) a_->update();
}

void CameraLink::onModified(vtkObject* caller, unsigned long, void*) {
    if (copying_ || !enabled_) return;
    if (caller == cameraA_.Get())
        follow(cameraA_, cameraB_, b_);
    else if (caller == cameraB_.Get())
        follow(cameraB_, cameraA_, a_);
}

void CameraLink::follow(vtkCamera* source, vtkCamera* target, Viewport* targetView) {
    if (samePose(source, target)) return;
    copying_ = true;
    target->SetPosition(source->GetPosition());
    target->SetFocalPoint(source->GetFocalPoint());
    target->SetViewUp(source->GetViewUp());
    target->SetViewAngle(source->GetViewAngle());
    copying_ = false;
    ++copies_;
    if (targetView) targetView->update();
}

} // namespace hlod::widgets
