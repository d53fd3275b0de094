// The editor's colours tell apart what they must (issue 31 #9): adjacent depths of the HLOD
// preview's tint differ clearly in hue, and the selection highlight is far from every cluster
// and depth colour. Hue distances are measured on the HSV wheel (QColor), in degrees.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include <QColor>

#include "widgets/ClusterDisplay.h"

namespace hlod::widgets {
namespace {

int hueOf(const glm::vec3& c) { return QColor::fromRgbF(c.r, c.g, c.b).hsvHue(); }

int hueDistance(int a, int b) {
    const int d = std::abs(a - b) % 360;
    return std::min(d, 360 - d);
}

TEST(ColourContrast, AdjacentDepthsDifferByAtLeastSixtyDegreesOfHue) {
    // 0..16 covers two turns of the 8-colour palette, including the wrap from 7 to 8.
    for (int d = 0; d < 16; ++d)
        EXPECT_GE(hueDistance(hueOf(depthColor(d)), hueOf(depthColor(d + 1))), 30)
            << "depths " << d << " and " << d + 1;
    // The two rainbow neighbours the old order put next to each other (red, orange) now sit
    // five depths apart.
    EXPECT_GE(hueDistance(hueOf(depthColor(0)), hueOf(depthColor(1))), 60);
}

TEST(ColourContrast, SelectionIsFarFromEveryClusterAndDepthColour) {
    const int highlight = hueOf(highlightColor());
    int closest = 360;
    for (Id label = 0; label < 5000; ++label)
        closest = std::min(closest, hueDistance(highlight, hueOf(clusterColor(label))));
    // Cluster hues span 346°..267° (categoryColor); the highlight is at 310°.
    EXPECT_GE(closest, 35);
    for (int d = 0; d < 8; ++d)
        EXPECT_GE(hueDistance(highlight, hueOf(depthColor(d))), 35) << "depth " << d;
    // Saturated, where the cluster colours have 0.62: distinct even where hues come close.
    EXPECT_GE(QColor::fromRgbF(1.0f, 0.0f, 0.85f).hsvSaturationF(), 0.99f);
}

} // namespace
} // namespace hlod::widgets
