// Entry point of hlod_studio_tests: GoogleTest inside a QApplication set up as hlod-studio's
// main() does (OpenGL 3.2 core surface format before the QApplication, shared contexts, the
// resources with the icons and the translation). Run under xvfb-run.
#include <QApplication>
#include <QSurfaceFormat>
#include <gtest/gtest.h>

#include "widgets/GlSupport.h"

int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(hlod::widgets::viewportSurfaceFormat());
    QApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QApplication app(argc, argv);
    Q_INIT_RESOURCE(resources);
    // Tests must not read or write the user's settings (recent files, window layout).
    QApplication::setOrganizationName(QStringLiteral("hlod-tests"));
    QApplication::setApplicationName(QStringLiteral("hlod-studio-tests"));
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
