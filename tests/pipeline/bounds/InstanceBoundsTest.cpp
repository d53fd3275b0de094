// Per-instance world bounds (pipeline/bounds/InstanceBounds.h).
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "pipeline/bounds/BoundingSphere.h"
#include "pipeline/bounds/InstanceBounds.h"
#include "pipeline/cluster/RandomScenes.h"

namespace hlod {
namespace {

TEST(InstanceBounds, TranslatedScaledCubeHasExactBoxAndSphere) {
    Scene s;
    s.addMesh(test::makeBoxMesh({-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}, "cube"));
    const glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(10, 0, -3)) *
                         glm::scale(glm::dmat4(1.0), glm::dvec3(2.0));
    s.addInstance(0, s.addNode("a", 0, m));
    const auto b = computeInstanceBounds(s);
    ASSERT_EQ(b.size(), 1u);
    // A 2 m cube centred at (10, 0, -3): box +-1, sphere radius sqrt 3 (half diagonal).
    EXPECT_EQ(b[0].box.min, glm::dvec3(9, -1, -4));
    EXPECT_EQ(b[0].box.max, glm::dvec3(11, 1, -2));
    EXPECT_NEAR(b[0].sphere.radius, std::sqrt(3.0), 1e-12);
    EXPECT_NEAR(glm::length(b[0].sphere.center - glm::dvec3(10, 0, -3)), 0.0, 1e-12);
}

TEST(InstanceBounds, NonUniformScaleRecomputesTheSphere) {
    // Scaled (4, 1, 1) the cube is a 4 x 1 x 1 box: minimum sphere radius sqrt(16+1+1)/2.
    Scene s;
    s.addMesh(test::makeBoxMesh({-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}, "cube"));
    s.addInstance(0, s.addNode("a", 0, glm::scale(glm::dmat4(1.0), glm::dvec3(4, 1, 1))));
    const auto b = computeInstanceBounds(s);
    EXPECT_NEAR(b[0].sphere.radius, std::sqrt(18.0) / 2.0, 1e-12);
}

TEST(InstanceBounds, SimilarityShortcutEqualsDirectWelzl) {
    // The reused local sphere must be the sphere of the transformed vertices.
    const Scene s = test::makeRandomScene({200, test::Layout::Uniform, 5, 0.0});
    const auto b = computeInstanceBounds(s);
    for (Id i = 0; i < s.instances.size(); ++i) {
        std::vector<glm::dvec3> world;
        for (const glm::vec3& p : s.meshes[s.instances[i].mesh].positions) {
            world.emplace_back(s.instanceTransform(i) * glm::dvec4(glm::dvec3(p), 1.0));
        }
        const Sphere direct = minimumBoundingSphere(world);
        EXPECT_NEAR(b[i].sphere.radius, direct.radius, 1e-9 * direct.radius) << i;
        EXPECT_NEAR(glm::length(b[i].sphere.center - direct.center), 0.0, 1e-9 * direct.radius);
        const Aabb exact = s.instanceBounds(i);
        EXPECT_EQ(b[i].box.min, exact.min);
        EXPECT_EQ(b[i].box.max, exact.max);
    }
}

TEST(InstanceBounds, EmptyMeshSitsAtItsOrigin) {
    Scene s;
    s.addMesh(Mesh{});
    s.addInstance(0, s.addNode("a", 0, glm::translate(glm::dmat4(1.0), glm::dvec3(1, 2, 3))));
    const auto b = computeInstanceBounds(s);
    EXPECT_EQ(b[0].box.min, glm::dvec3(1, 2, 3));
    EXPECT_EQ(b[0].sphere.radius, 0.0);
}

TEST(InstanceBounds, SimilarityDetection) {
    double scale = 0.0;
    EXPECT_TRUE(isSimilarity(glm::rotate(glm::dmat4(1.0), 0.7, glm::dvec3(1, 2, 3)) *
                                 glm::scale(glm::dmat4(1.0), glm::dvec3(3.0)),
                             scale));
    EXPECT_NEAR(scale, 3.0, 1e-12);
    EXPECT_FALSE(isSimilarity(glm::scale(glm::dmat4(1.0), glm::dvec3(1, 2, 1)), scale));
    glm::dmat4 shear(1.0);
    shear[1][0] = 0.5;
    EXPECT_FALSE(isSimilarity(shear, scale));
}

} // namespace
} // namespace hlod
