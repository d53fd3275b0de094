// OpenGL requirements of the VTK viewport: surface format and an up-front probe.
#include "widgets/GlSupport.h"

#include <QCoreApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>

namespace hlod::widgets {

namespace {

// Gives the free functions below a translation context ("GlSupport") that lupdate sees.
struct GlText {
    Q_DECLARE_TR_FUNCTIONS(GlSupport)
};

QString glString(QOpenGLContext& context, GLenum name) {
    const auto* text = reinterpret_cast<const char*>(context.functions()->glGetString(name));
    return text ? QString::fromLatin1(text) : QString();
}

} // namespace

QSurfaceFormat viewportSurfaceFormat() {
    // What VTK's own Qt adapter asks for: 3.2 core, RGBA8, no multisampling in the context
    // (VTK renders into its own framebuffer and resolves there). Depth 24 rather than VTK's
    // nominal 8 because the Qt widget's framebuffer is only a blit target, but some drivers
    // refuse odd depth sizes. Alpha 8 so grabbed frames keep an opaque alpha channel.
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 2);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setSwapBehavior(QSurfaceFormat::DoubleBuffer);
    format.setRedBufferSize(8);
    format.setGreenBufferSize(8);
    format.setBlueBufferSize(8);
    format.setAlphaBufferSize(8);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(0);
    format.setSamples(0);
    return format;
}

bool formatIsSufficient(const QSurfaceFormat& format) {
    if (format.renderableType() == QSurfaceFormat::OpenGLES) return false;
    return format.majorVersion() > 3 || (format.majorVersion() == 3 && format.minorVersion() >= 2);
}

QString glUnavailableMessage(const QString& detail) {
    QString message =
        GlText::tr("OpenGL 3.2 is not available, so the 3D view cannot be shown. "
                   "Use the hlod command-line tool for headless work, or run the editor "
                   "on a machine with an OpenGL 3.2 driver (Mesa's llvmpipe is enough).");
    if (!detail.isEmpty()) message += QStringLiteral("\n\n") + detail;
    return message;
}

GlProbeResult probeOpenGl() {
    GlProbeResult result;
    QOffscreenSurface surface;
    surface.setFormat(QSurfaceFormat::defaultFormat());
    surface.create();
    QOpenGLContext context;
    context.setFormat(QSurfaceFormat::defaultFormat());
    if (!surface.isValid() || !context.create()) {
        result.problem = GlText::tr("No OpenGL context could be created on this display.");
        return result;
    }
    const QSurfaceFormat got = context.format();
    if (!context.makeCurrent(&surface)) {
        result.problem = GlText::tr("An OpenGL context was created but could not be made current.");
        return result;
    }
    result.version = glString(context, GL_VERSION);
    result.renderer = glString(context, GL_RENDERER);
    context.doneCurrent();
    if (!formatIsSufficient(got)) {
        result.problem = GlText::tr("The driver offers OpenGL %1.%2 (%3), VTK needs 3.2 or newer.")
                             .arg(got.majorVersion())
                             .arg(got.minorVersion())
                             .arg(result.renderer);
        return result;
    }
    result.ok = true;
    return result;
}

} // namespace hlod::widgets
