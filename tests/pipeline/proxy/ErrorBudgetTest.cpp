#include <gtest/gtest.h>

#include "pipeline/core/Error.h"
#include "pipeline/proxy/ErrorBudget.h"

using namespace hlod;

TEST(ErrorBudget, OnePixelAtThreeHundredPixelsIsADiameterOverThreeHundred) {
    // The thesis' Simplygon setting: screen size 300 px; a 3 m node may deviate 1 cm.
    EXPECT_DOUBLE_EQ(proxyErrorBudget(3.0, ScreenParams{}), 0.01);
    ScreenParams loose;
    loose.pixelError = 2.0;
    loose.screenSize = 600.0;
    EXPECT_DOUBLE_EQ(proxyErrorBudget(3.0, loose), 0.01); // 2 px of 600 is 1 px of 300
}

TEST(ErrorBudget, SwitchDistanceMakesTheNodeCoverScreenSizePixels) {
    ScreenParams p;
    p.fovYDegrees = 90.0;      // tan(45 deg) = 1
    p.viewportHeight = 1200.0; // 1200 px cover 2 d at distance d
    // A 2 m node covers 300 px where 2 m is 1/4 of the view height 2 d: d = 4 m.
    EXPECT_NEAR(switchDistance(2.0, p), 4.0, 1e-12);
    // Twice the diameter switches twice as far away.
    EXPECT_NEAR(switchDistance(4.0, p), 8.0, 1e-12);
}

TEST(ErrorBudget, NodeDiameterIsTheSphereOrElseTheBoxDiagonal) {
    ClusterNode n;
    n.box.expand(glm::dvec3(0.0));
    n.box.expand(glm::dvec3(3.0, 4.0, 0.0));
    EXPECT_DOUBLE_EQ(nodeDiameter(n), 5.0); // no sphere: the 3-4-5 diagonal
    n.sphere.radius = 2.25;
    EXPECT_DOUBLE_EQ(nodeDiameter(n), 4.5);
}

TEST(ErrorBudget, RejectsParametersOutOfRange) {
    ScreenParams p;
    EXPECT_NO_THROW(validate(p));
    p.screenSize = 0.0;
    EXPECT_THROW(validate(p), Error);
    p = ScreenParams{};
    p.pixelError = -1.0;
    EXPECT_THROW(validate(p), Error);
    p = ScreenParams{};
    p.fovYDegrees = 180.0;
    EXPECT_THROW(validate(p), Error);
}
