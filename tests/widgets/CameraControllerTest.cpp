// Tests of widgets/CameraController: turntable orbit, pan, fit (camera maths only, no GL).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>
#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>

#include "widgets/CameraController.h"

namespace hlod::widgets {
namespace {

glm::dvec3 position(vtkCamera* c) {
    return {c->GetPosition()[0], c->GetPosition()[1], c->GetPosition()[2]};
}
glm::dvec3 focal(vtkCamera* c) {
    return {c->GetFocalPoint()[0], c->GetFocalPoint()[1], c->GetFocalPoint()[2]};
}

TEST(CameraController, OrbitTurnsAroundTheUpAxisKeepingDistance) {
    vtkNew<vtkCamera> camera;
    camera->SetFocalPoint(0, 0, 0);
    camera->SetPosition(0, 0, 10);
    CameraController controller(camera);
    controller.setUpAxis(1);
    controller.orbit(90.0, 0.0); // a quarter turn around +Y takes +Z to +X
    EXPECT_NEAR(position(camera).x, 10.0, 1e-9);
    EXPECT_NEAR(position(camera).z, 0.0, 1e-9);
    EXPECT_NEAR(glm::length(position(camera)), 10.0, 1e-9);
}

TEST(CameraController, ElevationStopsShortOfThePole) {
    vtkNew<vtkCamera> camera;
    camera->SetPosition(0, 0, 10);
    CameraController controller(camera);
    controller.setUpAxis(1);
    controller.orbit(0.0, 200.0); // asks for far past the pole
    // Clamped at 89 degrees: height 10 sin 89 = 9.99848, never over the top.
    EXPECT_NEAR(position(camera).y, 10.0 * std::sin(glm::radians(89.0)), 1e-6);
    EXPECT_GT(position(camera).z, 0.0);
    const double* up = camera->GetViewUp();
    EXPECT_GT(up[1], 0.0); // the horizon did not flip
}

TEST(CameraController, PanMovesFocalPointByPixelsAtFocalDistance) {
    // View angle 30, distance 10: the frame is 2*10*tan(15) = 5.359 units over 400 px high.
    vtkNew<vtkCamera> camera;
    camera->SetPosition(0, 0, 10);
    camera->SetViewAngle(30.0);
    CameraController controller(camera);
    controller.setUpAxis(1);
    controller.pan(100.0, 0.0, 400); // drag right: the scene follows, so the camera moves left
    EXPECT_NEAR(focal(camera).x, -100.0 * 2.0 * 10.0 * std::tan(glm::radians(15.0)) / 400.0, 1e-9);
    EXPECT_NEAR(position(camera).z, 10.0, 1e-9);
}

TEST(CameraController, FitCentresEveryCornerInsideTheFrustum) {
    vtkNew<vtkCamera> camera;
    camera->SetViewAngle(30.0);
    CameraController controller(camera);
    controller.setUpAxis(2);
    controller.setDefaultDirection();
    const std::array<double, 6> bounds{-5, 15, 0, 2, -1, 1}; // long and flat
    const double aspect = 1.5;
    controller.fit(bounds, aspect);
    // Project each corner to normalised device coordinates.
    double xMin = 1e9, xMax = -1e9, yMin = 1e9, yMax = -1e9;
    vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(aspect, -1, 1);
    for (int i = 0; i < 8; ++i) {
        const double p[4] = {bounds[(i & 1) ? 1 : 0], bounds[(i & 2) ? 3 : 2],
                             bounds[(i & 4) ? 5 : 4], 1.0};
        double q[4];
        m->MultiplyPoint(p, q);
        xMin = std::min(xMin, q[0] / q[3]), xMax = std::max(xMax, q[0] / q[3]);
        yMin = std::min(yMin, q[1] / q[3]), yMax = std::max(yMax, q[1] / q[3]);
    }
    // Inside the frame with the 6% margin: the limiting side sits at 0.94 ...
    const double worst = std::max({-xMin, xMax, -yMin, yMax});
    EXPECT_LE(worst, 0.9401);
    EXPECT_GE(worst, 0.93);
    // ... and the picture is centred: equal space left and right, above and below.
    EXPECT_NEAR(xMin + xMax, 0.0, 0.02);
    EXPECT_NEAR(yMin + yMax, 0.0, 0.02);
}

TEST(CameraController, FitOnPointsIgnoresEmptyCornersOfTheSceneBox) {
    // A 5 m post at the front of a flat 20 x 8 m slab, seen from the front and above: the scene
    // box has empty corners 5 m above the slab's back edge, which project highest on screen;
    // the points do not, so fitting the points gets closer than fitting the box.
    vtkNew<vtkCamera> boxCamera, pointCamera;
    for (vtkCamera* c : {boxCamera.Get(), pointCamera.Get()}) {
        c->SetPosition(0, -10, 10);
        c->SetViewAngle(30.0);
    }
    const std::vector<glm::dvec3> points{
        {-10, 0, 0}, {10, 0, 0}, {0, 0, 5}, {-10, 8, 0}, {10, 8, 0}};
    CameraController(boxCamera).fit(std::array<double, 6>{-10, 10, 0, 8, 0, 5}, 3.0);
    CameraController(pointCamera).fit(points, 3.0); // wide: the height limits
    EXPECT_LT(pointCamera->GetDistance(), 0.9 * boxCamera->GetDistance());
}

} // namespace
} // namespace hlod::widgets
