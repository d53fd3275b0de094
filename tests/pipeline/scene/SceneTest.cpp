#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/io/SampleScene.h"
#include "pipeline/scene/Primitives.h"
#include "pipeline/scene/Scene.h"

using namespace hlod;

TEST(Scene, InstancedMeshIsCountedOncePerInstanceForDrawingAndOnceAsUnique) {
    Scene s;
    const Id box = s.addMesh(makeBox({1, 1, 1}));
    const Id a = s.addNode("a", 0, glm::translate(glm::dmat4(1.0), {10, 0, 0}));
    const Id b = s.addNode("b", a, glm::translate(glm::dmat4(1.0), {0, 5, 0}));
    s.addInstance(box, a);
    s.addInstance(box, b);
    const SceneStats st = s.stats();
    // One box = 12 triangles and 24 vertices; two instances draw it twice.
    EXPECT_EQ(st.meshes, 1u);
    EXPECT_EQ(st.instances, 2u);
    EXPECT_EQ(st.drawCalls, 2u);
    EXPECT_EQ(st.triangles, 24u);
    EXPECT_EQ(st.uniqueTriangles, 12u);
    EXPECT_EQ(st.vertices, 48u);
    EXPECT_EQ(st.nodes, 3u);
    EXPECT_EQ(st.depth, 3u); // root -> a -> b
}

TEST(Scene, WorldTransformsComposeParentFirst) {
    Scene s;
    const Id box = s.addMesh(makeBox({2, 2, 2}));
    const Id a = s.addNode("a", 0, glm::translate(glm::dmat4(1.0), {10, 0, 0}));
    const Id b = s.addNode("b", a, glm::scale(glm::dmat4(1.0), {2, 2, 2}));
    s.addInstance(box, b);
    // Box [-1,1]^3 scaled by 2 then moved by +10 in x: [8,12] x [-2,2] x [-2,2].
    const Aabb bounds = s.worldBounds();
    EXPECT_DOUBLE_EQ(bounds.min.x, 8.0);
    EXPECT_DOUBLE_EQ(bounds.max.x, 12.0);
    EXPECT_DOUBLE_EQ(bounds.min.y, -2.0);
    EXPECT_DOUBLE_EQ(bounds.max.z, 2.0);
    s.nodes[a].local = glm::translate(glm::dmat4(1.0), {0, 0, 0});
    s.updateWorldTransforms();
    EXPECT_DOUBLE_EQ(s.worldBounds().max.x, 2.0);
}

TEST(Scene, AppendPutsEachPartUnderItsOwnNamedNode) {
    Scene a;
    a.addInstance(a.addMesh(makeBox({1, 1, 1})), a.addNode("part", 0));
    Scene b;
    const Id mat = b.addMaterial(Material{"red", {1, 0, 0, 1}, {}, false, glm::vec4(1.0f)});
    Mesh m = makeBox({1, 1, 1});
    m.material = mat;
    b.addInstance(b.addMesh(std::move(m)), b.addNode("part", 0));
    Scene s;
    s.append(std::move(a), "first");
    s.append(std::move(b), "second");
    ASSERT_EQ(s.nodes[0].children.size(), 2u);
    EXPECT_EQ(s.nodes[s.nodes[0].children[0]].name, "first");
    EXPECT_EQ(s.nodes[s.nodes[0].children[1]].name, "second");
    ASSERT_EQ(s.instances.size(), 2u);
    // Material ids are rebased: the second mesh must still be red.
    EXPECT_EQ(s.materials[s.meshes[s.instances[1].mesh].material].name, "red");
    EXPECT_EQ(s.nodes[s.instances[1].node].parent, s.nodes[0].children[1]);
}

TEST(Primitives, ClosedShapesHaveTheTextbookTriangleCounts) {
    EXPECT_EQ(makeBox({1, 2, 3}).triangleCount(), 12u);
    EXPECT_EQ(makeCylinder(1, 2, 16).triangleCount(), 64u); // 2*16 side + 2*16 caps
    EXPECT_EQ(makeSphere(1, 16, 8).triangleCount(), 2u * 16 * 7);
    const Aabb b = makeBox({1, 2, 3}).localBounds();
    EXPECT_FLOAT_EQ(static_cast<float>(b.extent().y), 2.0f);
}

TEST(Primitives, BoxNormalsPointOutward) {
    const Mesh m = makeBox({2, 2, 2});
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        // Every vertex of a centred box lies on the side its normal points to.
        EXPECT_GT(glm::dot(m.positions[i], m.normals[i]), 0.0f);
    }
    // Winding agrees with the normal: counter-clockwise seen from outside.
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                        c = m.positions[m.indices[t + 2]];
        EXPECT_GT(glm::dot(glm::cross(b - a, c - a), m.normals[m.indices[t]]), 0.0f);
    }
}

TEST(SampleScene, IsDeterministicAndShowsClumpsOfInstancedObjects) {
    const Scene a = makeSampleScene();
    const Scene b = makeSampleScene();
    const SceneStats st = a.stats();
    EXPECT_EQ(st.triangles, b.stats().triangles);
    // 1 yard + 9 tanks + 9 domes + 3 racks x (4 posts + 2 beams + 4 pipes) + 4 x 12 crates.
    EXPECT_EQ(st.instances, 1u + 9 + 9 + 30 + 48);
    EXPECT_EQ(st.meshes, 7u);
    EXPECT_EQ(st.materials, 6u); // default + 5
    const Aabb bounds = a.worldBounds();
    EXPECT_NEAR(bounds.extent().x, 120.0, 1e-6); // the yard plate spans the scene
}
