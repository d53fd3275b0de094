// Entry point of hlod_widgets_tests: GoogleTest inside a QApplication that requests the same
// OpenGL 3.2 core surface format as hlod-studio (it must be set before the QApplication exists,
// which is why gtest_main is not used). Run under xvfb-run: QOpenGLWidget needs a real X server.
#include <QApplication>
#include <QSurfaceFormat>
#include <gtest/gtest.h>

#include "widgets/GlSupport.h"

int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(hlod::widgets::viewportSurfaceFormat());
    QApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QApplication app(argc, argv);
    // Tests must not read or write the user's settings.
    QApplication::setOrganizationName(QStringLiteral("hlod-tests"));
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
