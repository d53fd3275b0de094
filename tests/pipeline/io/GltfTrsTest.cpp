// TRS decomposition of node transforms (GltfTrs.h): rotation, scale and mirror come back as
// they were composed, shear is refused.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/io/GltfTrs.h"

using namespace hlod;

TEST(GltfTrs, RotationScaleAndTranslationComeBack) {
    Trs t;
    t.translation = {10.0, -2.0, 3.5};
    t.rotation = glm::angleAxis(glm::radians(30.0), glm::normalize(glm::dvec3(1, 2, 3)));
    t.scale = {2.0, 0.5, 3.0};
    const auto back = decomposeTrs(composeTrs(t));
    ASSERT_TRUE(back);
    EXPECT_NEAR(glm::length(back->translation - t.translation), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(back->scale - t.scale), 0.0, 1e-12);
    EXPECT_NEAR(std::abs(glm::dot(back->rotation, t.rotation)), 1.0, 1e-12);
}

TEST(GltfTrs, AMirrorBecomesANegativeXScale) {
    // Mirroring z: the same as turning 180 degrees about y and mirroring x.
    const glm::dmat4 m = glm::scale(glm::dmat4(1.0), glm::dvec3(1.0, 1.0, -1.0));
    const auto t = decomposeTrs(m);
    ASSERT_TRUE(t);
    EXPECT_DOUBLE_EQ(t->scale.x, -1.0);
    const glm::dmat4 back = composeTrs(*t);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            EXPECT_NEAR(back[c][r], m[c][r], 1e-12);
}

TEST(GltfTrs, ShearAndProjectionAreRefused) {
    glm::dmat4 shear(1.0);
    shear[1][0] = 0.5; // y axis leans into x
    EXPECT_FALSE(decomposeTrs(shear));
    glm::dmat4 projective(1.0);
    projective[2][3] = 1.0;
    EXPECT_FALSE(decomposeTrs(projective));
    EXPECT_FALSE(decomposeTrs(glm::dmat4(0.0)));
}
