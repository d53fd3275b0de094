#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/proxy/Aggregate.h"
#include "pipeline/proxy/DecimateProxy.h"
#include "pipeline/proxy/ErrorBudget.h"
#include "pipeline/proxy/PartwiseSimplify.h"
#include "pipeline/proxy/ProxyTestUtil.h"
#include "pipeline/proxy/SloppyProxy.h"
#include "pipeline/proxy/SmallParts.h"
#include "pipeline/proxy/Weld.h"
#include "pipeline/scene/Primitives.h"

using namespace hlod;

namespace {

// A unit sphere finely tessellated (128 x 64): its own chord error is about 4e-4, small next
// to the budget of a 2 m node at 300 px (2 / 300 = 6.7e-3).
ProxyMesh unitSphereSoup(const glm::dvec3& at = glm::dvec3(0.0)) {
    Scene s;
    const Id mesh = s.addMesh(makeSphere(1.0f, 128, 64));
    const Id inst =
        s.addInstance(mesh, s.addNode("sphere", 0, glm::translate(glm::dmat4(1.0), at)));
    const AggregatePart part{inst, nullptr};
    return aggregateParts(s, std::span(&part, 1), at);
}

// Largest distance between proxy and the analytic sphere, both ways: proxy samples to the
// sphere (| |p| - 1 |), and sphere points (Fibonacci directions) to the proxy.
double hausdorffToUnitSphere(const ProxyMesh& proxy, const glm::dvec3& centre) {
    double worst = 0.0;
    for (const glm::dvec3& p : test::surfaceSamples(proxy)) {
        worst = std::max(worst, std::abs(glm::length(p - centre) - 1.0));
    }
    const int n = 600;
    for (int i = 0; i < n; ++i) {
        const double z = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - z * z);
        const double phi = i * 2.399963229728653;
        const glm::dvec3 u(r * std::cos(phi), r * std::sin(phi), z);
        worst = std::max(worst, test::distanceToMesh(proxy, centre + u));
    }
    return worst;
}

// Connected parts by shared position (finished proxies split vertices at creases).
std::size_t partsByPosition(ProxyMesh m) {
    m.colors.assign(m.positions.size(), glm::u8vec4(255));
    weldVertices(m, 0.0f);
    return countParts(m);
}

} // namespace

TEST(DecimateProxy, SphereStaysWithinErrorBudgetBothWays) {
    // Far from the origin on purpose: proxies live in their node's frame, precision must hold.
    const glm::dvec3 centre(5000.0, -300.0, 20.0);
    const double e = proxyErrorBudget(2.0, ScreenParams{}); // 2 m diameter at S=300, t=1
    ASSERT_NEAR(e, 2.0 / 300.0, 1e-12);
    const ProxyMesh proxy = decimateProxy(unitSphereSoup(centre), e);
    EXPECT_LE(hausdorffToUnitSphere(proxy, centre), e);
    // 16,128 input triangles; within 1/300 of the diameter the sphere keeps well under half.
    EXPECT_LT(proxy.triangleCount(), 16128u / 2);
    EXPECT_GT(proxy.triangleCount(), 500u);
    EXPECT_EQ(proxy.normals.size(), proxy.positions.size());
    EXPECT_EQ(test::openEdgeCount(proxy), 0u); // topology kept: still closed
}

TEST(DecimateProxy, LargerBudgetGivesFewerTriangles) {
    const ProxyMesh fine = decimateProxy(unitSphereSoup(), 0.005);
    const ProxyMesh coarse = decimateProxy(unitSphereSoup(), 0.05);
    EXPECT_LT(coarse.triangleCount(), fine.triangleCount());
    EXPECT_LE(hausdorffToUnitSphere(coarse, glm::dvec3(0.0)), 0.05);
}

TEST(DecimateProxy, DropsPartsSmallerThanTheBudget) {
    Scene s;
    const Id big = s.addMesh(makeBox({1, 1, 1}));
    const Id tiny = s.addMesh(makeBox({0.001f, 0.001f, 0.001f})); // diagonal 1.7 mm
    const Id a = s.addInstance(big, s.addNode("big", 0));
    const Id b =
        s.addInstance(tiny, s.addNode("tiny", 0, glm::translate(glm::dmat4(1.0), {2, 0, 0})));
    const AggregatePart parts[] = {{a, nullptr}, {b, nullptr}};
    // Budget 5 mm: the 1.7 mm box covers less than a pixel at the switch point.
    const ProxyMesh proxy = decimateProxy(aggregateParts(s, parts, glm::dvec3(0.0)), 0.005);
    EXPECT_EQ(partsByPosition(proxy), 1u);
    EXPECT_EQ(proxy.triangleCount(), 12u); // a box cannot lose a triangle within 5 mm
}

TEST(DecimateProxy, MaterialColourSurvivesAsVertexColour) {
    Scene s;
    Material red;
    red.name = "red";
    red.baseColor = {1.0f, 0.0f, 0.0f, 1.0f};
    red.hasTexture = true;
    red.textureMean = {0.5f, 0.5f, 0.5f, 1.0f}; // a mid-grey texture halves the factor
    Mesh box = makeBox({1, 1, 1});
    box.material = s.addMaterial(red);
    const Id inst = s.addInstance(s.addMesh(std::move(box)), s.addNode("b", 0));
    const AggregatePart part{inst, nullptr};
    const ProxyMesh proxy = decimateProxy(aggregateParts(s, std::span(&part, 1), {}), 0.01);
    ASSERT_FALSE(proxy.colors.empty());
    for (const glm::u8vec4& c : proxy.colors) {
        EXPECT_EQ(c, glm::u8vec4(128, 0, 0, 255)); // 0.5 * 255 rounds to 128
    }
}

TEST(SloppyProxy, SphereStaysWithinErrorBudgetBothWays) {
    const double e = 2.0 / 300.0;
    const ProxyMesh proxy = sloppyProxy(unitSphereSoup(), e);
    EXPECT_LE(hausdorffToUnitSphere(proxy, glm::dvec3(0.0)), e);
    EXPECT_LT(proxy.triangleCount(), 16128u);
}

TEST(SloppyProxy, ClustersDenseMeshesHardAndLeavesCoarseOnesAlone) {
    // Vertex clustering only removes triangles whose corners share a grid cell: a 128 x 64
    // sphere (vertex spacing up to 4.9 cm) loses about half of them at a 10 cm budget (cells
    // of 5.8 cm; measured 8,256 of 16,128 kept, the dense polar rows collapse first)...
    const ProxyMesh dense = sloppyProxy(unitSphereSoup(), 0.1);
    EXPECT_LT(dense.triangleCount(), 16128u * 55 / 100);
    EXPECT_LE(hausdorffToUnitSphere(dense, glm::dvec3(0.0)), 0.1);
    // ...while 1 cm cubes at a 5 mm budget keep all 12 triangles (no two corners in a cell),
    // where decimation could merge nothing either.
    Scene s;
    const Id inst = s.addInstance(s.addMesh(makeBox({0.01f, 0.01f, 0.01f})), s.addNode("c", 0));
    const AggregatePart part{inst, nullptr};
    EXPECT_EQ(sloppyProxy(aggregateParts(s, std::span(&part, 1), {}), 0.005).triangleCount(), 12u);
}

TEST(PartwiseSimplify, EachPartStaysWithinTheBudgetOfItsOwnInput) {
    // Two unit spheres 4 m apart in one mesh: two parts, simplified and checked one by one.
    ProxyMesh both = unitSphereSoup();
    const ProxyMesh second = unitSphereSoup(glm::dvec3(4.0, 0.0, 0.0));
    const auto offset = static_cast<std::uint32_t>(both.positions.size());
    for (const glm::vec3& p : second.positions)
        both.positions.push_back(p + glm::vec3(4.0f, 0.0f, 0.0f));
    for (std::uint32_t v : second.indices)
        both.indices.push_back(v + offset);
    both.colors.assign(both.positions.size(), glm::u8vec4(255));
    const double e = 2.0 / 300.0;
    // The sphere's seam and pole vertices become one, as decimateProxy welds (Weld.h).
    weldVertices(both, static_cast<float>(e) / 64.0f);
    // The check bounds the distance to the input mesh; against the analytic sphere the input's
    // own chord error (4e-4) and the weld shift (1.8e-4) add, so leave 10% of e for them.
    const std::vector<std::uint32_t> out = simplifyPartsWithinError(both, 0.9 * e);
    ProxyMesh parts[2];
    for (std::size_t t = 0; t < out.size(); t += 3) {
        // Parts come out in the order of their first input triangle: sphere 0 first.
        const int which = both.positions[out[t]].x > 2.0f ? 1 : 0;
        if (which == 0) {
            EXPECT_TRUE(parts[1].indices.empty()) << "sphere 0 after sphere 1";
        }
        for (int k = 0; k < 3; ++k) {
            parts[which].indices.push_back(
                static_cast<std::uint32_t>(parts[which].positions.size()));
            parts[which].positions.push_back(both.positions[out[t + k]]);
        }
    }
    for (int which = 0; which < 2; ++which) {
        // Each sphere on its own keeps well under half of its 16,128 triangles (as the whole-
        // mesh test above) and stays within e of the analytic sphere, measured independently.
        EXPECT_LT(parts[which].triangleCount(), 16128u / 2) << which;
        EXPECT_GT(parts[which].triangleCount(), 500u) << which;
        EXPECT_LE(hausdorffToUnitSphere(parts[which], glm::dvec3(4.0 * which, 0.0, 0.0)), e);
    }
}
