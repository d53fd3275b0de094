// A proxy's sidedness and emission from the originals it stands for (ProxyLook.h): two-sided
// when any original is; emission as an area-weighted mean, relative to the atlas when there is
// one, absolute otherwise.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/proxy/ProxyLook.h"

using namespace hlod;

namespace {

// A unit square in the XY plane, two triangles (area 1 before scaling).
Mesh square(Id material) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    m.indices = {0, 1, 2, 0, 2, 3};
    m.material = material;
    return m;
}

// Root 0 over leaves 1 (instance 0) and 2 (instance 1).
ClusterTree twoLeaves() {
    ClusterTree t;
    t.nodes.resize(3);
    t.root = 0;
    t.nodes[0].children = {1, 2};
    t.nodes[0].level = 1;
    for (Id i = 1; i <= 2; ++i) {
        t.nodes[i].parent = 0;
        t.nodes[i].instance = i - 1;
    }
    return t;
}

// Original 0: a 1 m² square, base 0.4, emitting 0.4 (TORCS' rgb / emis), one-sided.
// Original 1: the square scaled by 3 in X (3 m²), base 0.5, not emitting, two-sided.
Scene emitterAndCard() {
    Scene s;
    Material lit;
    lit.baseColor = {0.4f, 0.4f, 0.4f, 1.0f};
    lit.emissive = glm::vec3(0.4f);
    const Id a = s.addMaterial(lit);
    Material card;
    card.baseColor = {0.5f, 0.5f, 0.5f, 1.0f};
    card.doubleSided = true;
    const Id b = s.addMaterial(card);
    s.addInstance(s.addMesh(square(a)), s.addNode("lit", 0));
    s.addInstance(s.addMesh(square(b)),
                  s.addNode("card", 0, glm::scale(glm::dmat4(1.0), glm::dvec3(3, 1, 1))));
    s.updateWorldTransforms();
    return s;
}

ProxyMesh proxyWithAtlas(bool atlas) {
    ProxyMesh p;
    p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    p.indices = {0, 1, 2};
    if (atlas) {
        auto a = std::make_shared<ProxyAtlas>();
        a->image = std::make_shared<RgbaImage>(1, 1, glm::u8vec4(255));
        p.atlas = a;
        p.uvs.assign(3, glm::vec2(0.0f));
    }
    return p;
}

} // namespace

TEST(ProxyLook, SubtreeSumsWeighOriginalsByTheirWorldArea) {
    const Scene s = emitterAndCard();
    const std::vector<ProxyLookSums> sums = subtreeLookSums(s, twoLeaves(), {1, 2, 0});
    EXPECT_DOUBLE_EQ(sums[1].area, 1.0);
    EXPECT_DOUBLE_EQ(sums[2].area, 3.0); // scaled by 3 in X
    EXPECT_DOUBLE_EQ(sums[0].area, 4.0);
    EXPECT_TRUE(sums[0].doubleSided); // the card is
    EXPECT_FALSE(sums[1].doubleSided);
}

TEST(ProxyLook, AtlasProxyEmitsTheMeanRatioOfEmissionToBaseColour) {
    const Scene s = emitterAndCard();
    const std::vector<ProxyLookSums> sums = subtreeLookSums(s, twoLeaves(), {1, 2, 0});
    ProxyMesh p = proxyWithAtlas(true);
    applyProxyLook(p, sums[0]);
    // Ratio 0.4 / 0.4 = 1 over 1 m², 0 over 3 m²: factor 0.25 on the atlas.
    EXPECT_FLOAT_EQ(p.emissive.r, 0.25f);
    EXPECT_TRUE(p.doubleSided);
    // Over the emitter alone the atlas emits exactly what the original does (factor 1).
    ProxyMesh alone = proxyWithAtlas(true);
    applyProxyLook(alone, sums[1]);
    EXPECT_EQ(alone.emissive, glm::vec3(1.0f));
    EXPECT_FALSE(alone.doubleSided);
}

TEST(ProxyLook, VertexColourProxyEmitsTheMeanEmittedColour) {
    const Scene s = emitterAndCard();
    const std::vector<ProxyLookSums> sums = subtreeLookSums(s, twoLeaves(), {1, 2, 0});
    ProxyMesh p = proxyWithAtlas(false);
    applyProxyLook(p, sums[0]);
    EXPECT_FLOAT_EQ(p.emissive.g, 0.1f); // 0.4 over 1 m² of 4
}

TEST(ProxyLook, NothingEmittingSkipsTheAreasAndEmitsNothing) {
    Scene s = emitterAndCard();
    s.materials[1].emissive = glm::vec3(0.0f);
    const std::vector<ProxyLookSums> sums = subtreeLookSums(s, twoLeaves(), {1, 2, 0});
    EXPECT_EQ(sums[0].area, 0.0);
    ProxyMesh p = proxyWithAtlas(true);
    applyProxyLook(p, sums[0]);
    EXPECT_EQ(p.emissive, glm::vec3(0.0f));
    EXPECT_TRUE(p.doubleSided);
}
