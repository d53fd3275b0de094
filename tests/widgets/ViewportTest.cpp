// Tests of widgets/Viewport: real rendering through Mesa under xvfb-run, compared with baseline
// images (tests/widgets/baselines, rewritten with HLOD_UPDATE_BASELINES=1).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include <QApplication>
#include <QMouseEvent>
#include <QTest>
#include <QWheelEvent>
#include <glm/glm.hpp>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include "TestScenes.h"
#include "pipeline/io/Import.h"
#include "pipeline/io/SampleScene.h"
#include "widgets/GlSupport.h"
#include "widgets/SceneActors.h"
#include "widgets/Viewport.h"

namespace hlod::widgets {
namespace {

// Mean absolute difference (0..255 per channel) tolerated against a baseline: llvmpipe is
// deterministic on one machine; this absorbs Mesa version drift in anti-aliased edges.
constexpr double kBaselineTolerance = 2.0;

class ViewportTest : public ::testing::Test {
protected:
    void SetUp() override {
        const GlProbeResult gl = probeOpenGl();
        ASSERT_TRUE(gl.ok) << gl.problem.toStdString();
        viewport = std::make_unique<Viewport>();
        viewport->setFixedSize(480, 360);
        viewport->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(viewport.get()));
        background = viewport->grabFrame(); // nothing loaded yet: gradient only
        ASSERT_EQ(background.size(), QSize(480, 360));
    }

    void show(const Scene& scene, const SceneActorsOptions& options = {}) {
        viewport->setSceneActors(SceneActors::build(scene, options), suggestedUpAxis(scene));
    }

    std::unique_ptr<Viewport> viewport;
    QImage background;
};

TEST_F(ViewportTest, EmptyViewportShowsTheGradientBackground) {
    ASSERT_TRUE(viewport->glAvailable());
    // Top row: Background2 (0.36, 0.41, 0.50) -> (92, 105, 128); bottom row: Background
    // (0.86, 0.88, 0.91) -> (219, 224, 232), give or take interpolation at the very edge.
    const QRgb top = background.pixel(240, 0);
    const QRgb bottom = background.pixel(240, 359);
    EXPECT_NEAR(qRed(top), 92, 3);
    EXPECT_NEAR(qBlue(top), 128, 3);
    EXPECT_NEAR(qRed(bottom), 219, 3);
    EXPECT_NEAR(qBlue(bottom), 232, 3);
    EXPECT_EQ(test::foregroundShare(background, background), 0.0);
}

TEST_F(ViewportTest, SampleSceneFillsTheFrameAndMatchesBaseline) {
    show(makeSampleScene());
    const QImage frame = viewport->grabFrame();
    // Fitted to the frame, the yard covers a good part of it (measured 0.22: the grey plate is
    // close to the light end of the background gradient, so parts of it do not count).
    EXPECT_GT(test::foregroundShare(frame, background), 0.15);
    const double diff = test::compareWithBaseline(frame, QStringLiteral("sample"));
    EXPECT_GE(diff, 0.0) << "missing baseline: run with HLOD_UPDATE_BASELINES=1";
    EXPECT_LT(diff, kBaselineTolerance);
}

TEST_F(ViewportTest, SharedRoomSceneMatchesBaseline) {
    const Scene scene = importScene({HLOD_TEST_DATA_DIR "/scenes/godot-room/room.glb"});
    show(scene);
    const QImage frame = viewport->grabFrame();
    EXPECT_GT(test::foregroundShare(frame, background), 0.25);
    const double diff = test::compareWithBaseline(frame, QStringLiteral("godot-room"));
    EXPECT_GE(diff, 0.0) << "missing baseline: run with HLOD_UPDATE_BASELINES=1";
    EXPECT_LT(diff, kBaselineTolerance);
}

TEST_F(ViewportTest, OrbitChangesTheImageAndOrbitingBackRestoresIt) {
    show(test::makeCubeGrid(30));
    const QImage before = viewport->grabFrame();
    viewport->orbit(60.0, 0.0);
    const QImage turned = viewport->grabFrame();
    EXPECT_GT(test::meanAbsDifference(before, turned), 4.0);
    viewport->orbit(-60.0, 0.0);
    EXPECT_LT(test::meanAbsDifference(before, viewport->grabFrame()), 0.05);
}

TEST_F(ViewportTest, FitViewBringsAZoomedAndPannedSceneBackIntoFrame) {
    show(test::makeCubeGrid(30));
    viewport->zoom(6.0);
    viewport->pan(300.0, 120.0);
    const QRect lost = test::foregroundBox(viewport->grabFrame(), background);
    // Zoomed in and pushed aside, the scene is cut by the frame edge.
    EXPECT_TRUE(lost.isNull() || lost.left() == 0 || lost.top() == 0 || lost.right() == 479 ||
                lost.bottom() == 359);

    viewport->fitView();
    const QImage fitted = viewport->grabFrame();
    const QRect box = test::foregroundBox(fitted, background);
    ASSERT_FALSE(box.isNull());
    // Whole scene inside, with the margin free on every side ...
    EXPECT_GT(box.left(), 2);
    EXPECT_GT(box.top(), 2);
    EXPECT_LT(box.right(), 477);
    EXPECT_LT(box.bottom(), 357);
    // ... and not lost in the middle: it spans most of the frame in at least one direction.
    EXPECT_GT(std::max(box.width() / 480.0, box.height() / 360.0), 0.75);
}

TEST_F(ViewportTest, ZoomInEnlargesTheScene) {
    show(test::makeCubeGrid(30));
    const double fitted = test::foregroundShare(viewport->grabFrame(), background);
    viewport->zoom(1.5);
    EXPECT_GT(test::foregroundShare(viewport->grabFrame(), background), fitted * 1.3);
}

TEST_F(ViewportTest, MergedLayoutRendersLikeOneActorPerInstance) {
    // Same scene, both layouts: merging moves vertices to world space on the CPU, so any
    // transform or normal mistake shows up as a different image.
    const Scene scene = test::makeCubeGrid(60);
    show(scene, {.mergeAbove = 1000});
    ASSERT_FALSE(viewport->sceneActors()->merged());
    const QImage perInstance = viewport->grabFrame();
    show(scene, {.mergeAbove = 0});
    ASSERT_TRUE(viewport->sceneActors()->merged());
    EXPECT_LT(test::meanAbsDifference(perInstance, viewport->grabFrame()), 0.5);
}

TEST_F(ViewportTest, ClearingTheSceneLeavesOnlyBackground) {
    show(test::makeCubeGrid(10));
    EXPECT_GT(test::foregroundShare(viewport->grabFrame(), background), 0.05);
    viewport->clearScene();
    EXPECT_EQ(test::foregroundShare(viewport->grabFrame(), background), 0.0);
}

// One unit quad in z = 0 whose front faces +Z, seen from -Z (its back): a one-sided material
// is culled as engines cull it, a double-sided one is drawn. And a black quad facing the
// camera that emits red shows red (emission added after lighting). Both layouts.
Scene quadScene(bool doubleSided, bool facingCamera, glm::vec3 emissive) {
    Scene s;
    Material m;
    m.baseColor = emissive == glm::vec3(0.0f) ? glm::vec4(0.5f, 0.5f, 0.5f, 1.0f)
                                              : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    m.doubleSided = doubleSided;
    m.emissive = emissive;
    Mesh quad;
    quad.positions = {{-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}, {-0.5f, 0.5f, 0}};
    quad.indices = facingCamera ? std::vector<std::uint32_t>{0, 2, 1, 0, 3, 2}
                                : std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3};
    quad.material = s.addMaterial(m);
    s.addInstance(s.addMesh(std::move(quad)), s.addNode("quad", 0));
    return s;
}

TEST_F(ViewportTest, BackFacesAreCulledUnlessDoubleSidedAndEmissionIsAdded) {
    for (std::size_t mergeAbove : {std::size_t(1000), std::size_t(0)}) {
        auto look = [&](const Scene& scene) {
            show(scene, {.mergeAbove = mergeAbove, .maxMergedParts = 0}); // 0: by opacity
            vtkCamera* camera = viewport->camera();
            camera->SetPosition(0, 0, -3);
            camera->SetFocalPoint(0, 0, 0);
            camera->SetViewUp(0, 1, 0);
            viewport->renderer()->ResetCameraClippingRange();
            return viewport->grabFrame();
        };
        EXPECT_EQ(test::foregroundShare(look(quadScene(false, false, {})), background), 0.0)
            << "a back face was drawn, mergeAbove " << mergeAbove;
        EXPECT_GT(test::foregroundShare(look(quadScene(true, false, {})), background), 0.05)
            << "a double-sided back face was culled, mergeAbove " << mergeAbove;
        const QColor centre = look(quadScene(false, true, {1.0f, 0.0f, 0.0f})).pixelColor(240, 180);
        // Black lit is the viewport's white specular highlight at most (0.12 of white); the
        // emission makes it red.
        EXPECT_GE(centre.red(), 250) << "mergeAbove " << mergeAbove;
        EXPECT_LE(centre.green(), 60);
        EXPECT_LE(centre.blue(), 60);
    }
}

// Sends a drag from `from` to `to` with `button` held (QTest::mouseMove carries no buttons).
void drag(QWidget* w, Qt::MouseButton button, QPoint from, QPoint to,
          Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    QMouseEvent press(QEvent::MouseButtonPress, from, w->mapToGlobal(from), button, button,
                      modifiers);
    QApplication::sendEvent(w, &press);
    for (int step = 1; step <= 4; ++step) {
        const QPoint at = from + (to - from) * step / 4;
        QMouseEvent move(QEvent::MouseMove, at, w->mapToGlobal(at), Qt::NoButton, button,
                         modifiers);
        QApplication::sendEvent(w, &move);
    }
    QMouseEvent release(QEvent::MouseButtonRelease, to, w->mapToGlobal(to), button, Qt::NoButton,
                        modifiers);
    QApplication::sendEvent(w, &release);
}

TEST_F(ViewportTest, MouseAndKeysDriveTheCamera) {
    show(test::makeCubeGrid(30));
    vtkCamera* camera = viewport->camera();
    const double fitted = camera->GetDistance();
    const glm::dvec3 eye0(camera->GetPosition()[0], camera->GetPosition()[1],
                          camera->GetPosition()[2]);

    // Left drag orbits: the eye moves, the distance to the focal point does not.
    drag(viewport.get(), Qt::LeftButton, {100, 100}, {200, 100});
    const glm::dvec3 eye1(camera->GetPosition()[0], camera->GetPosition()[1],
                          camera->GetPosition()[2]);
    EXPECT_GT(glm::length(eye1 - eye0), 0.1 * fitted);
    EXPECT_NEAR(camera->GetDistance(), fitted, 1e-6 * fitted);

    // Wheel forward zooms in by 1.15 per notch.
    QWheelEvent wheel(QPointF(240, 180), viewport->mapToGlobal(QPointF(240, 180)), QPoint(),
                      QPoint(0, 120), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(viewport.get(), &wheel);
    EXPECT_NEAR(camera->GetDistance(), fitted / 1.15, 1e-6 * fitted);

    // Shift + left drag pans: the focal point moves sideways, the distance stays.
    const double fx = camera->GetFocalPoint()[0], fz = camera->GetFocalPoint()[2];
    drag(viewport.get(), Qt::LeftButton, {200, 200}, {260, 200}, Qt::ShiftModifier);
    EXPECT_GT(std::hypot(camera->GetFocalPoint()[0] - fx, camera->GetFocalPoint()[2] - fz), 0.01);
    EXPECT_NEAR(camera->GetDistance(), fitted / 1.15, 1e-6 * fitted);

    // Right drag upwards zooms in.
    const double before = camera->GetDistance();
    drag(viewport.get(), Qt::RightButton, {200, 250}, {200, 150});
    EXPECT_LT(camera->GetDistance(), before * 0.5);

    // F fits again: back to a framed view (from the new direction, so about the same distance).
    QTest::keyClick(viewport.get(), Qt::Key_F);
    EXPECT_NEAR(camera->GetDistance(), fitted, 0.25 * fitted);
    const QRect box = test::foregroundBox(viewport->grabFrame(), background);
    EXPECT_GT(box.left(), 2);
    EXPECT_LT(box.right(), 477);
}

TEST(GlSupport, ProbeFindsAnOpenGl32CoreContext) {
    const GlProbeResult gl = probeOpenGl();
    EXPECT_TRUE(gl.ok) << gl.problem.toStdString();
    EXPECT_FALSE(gl.version.isEmpty());
    EXPECT_TRUE(gl.problem.isEmpty());
    QSurfaceFormat old;
    old.setVersion(3, 1);
    EXPECT_FALSE(formatIsSufficient(old));
    QSurfaceFormat newer;
    newer.setVersion(4, 5);
    EXPECT_TRUE(formatIsSufficient(newer));
}

} // namespace
} // namespace hlod::widgets
