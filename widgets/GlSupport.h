// OpenGL requirements of the VTK viewport: the surface format to request and a probe that tells,
// before any window opens, whether this machine can give us that context.
//
// VTK 9.1's OpenGL2 backend needs an OpenGL 3.2 core context. Where none exists (remote X without
// GLX, a very old driver), the app must say so instead of crashing inside VTK, so main() probes
// with an offscreen surface first and the viewport checks its own context again.
#pragma once

#include <QString>
#include <QSurfaceFormat>

namespace hlod::widgets {

// The format every QOpenGLWidget of the app uses. Set it with QSurfaceFormat::setDefaultFormat()
// before the QApplication exists (Qt shares it with all contexts created later).
QSurfaceFormat viewportSurfaceFormat();

struct GlProbeResult {
    bool ok = false;
    QString version;  // "4.5 (Core Profile) Mesa 22.3.6", empty when no context
    QString renderer; // "llvmpipe (LLVM 15.0.6, 256 bits)"
    QString problem;  // why it failed, empty when ok; translated, ready for the user
};

// Creates a context with the default surface format on an offscreen surface and checks it is
// at least OpenGL 3.2 core. Needs a QGuiApplication. Cheap (a few ms); result not cached.
GlProbeResult probeOpenGl();

// True when `format` (the format a context actually got) satisfies the viewport.
bool formatIsSufficient(const QSurfaceFormat& format);

// The sentence shown in place of the viewport when OpenGL is missing; `detail` is appended.
QString glUnavailableMessage(const QString& detail);

} // namespace hlod::widgets
