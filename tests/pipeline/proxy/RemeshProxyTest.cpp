#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/core/Error.h"
#include "pipeline/proxy/Aggregate.h"
#include "pipeline/proxy/ErrorBudget.h"
#include "pipeline/proxy/ProxyTestUtil.h"
#include "pipeline/proxy/RemeshProxy.h"
#include "pipeline/scene/Primitives.h"

using namespace hlod;

namespace {

double maxNorm(const glm::dvec3& p) {
    return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
}

// A closed 2 m box around a closed 0.8 m box, both centred at the origin; with `openTop` the
// outer box misses its +Y face (2 triangles), so the inner box can be seen from above.
ProxyMesh boxInBox(bool openTop) {
    Scene s;
    Mesh outer = makeBox({2, 2, 2});
    if (openTop) outer.indices.erase(outer.indices.begin() + 24, outer.indices.begin() + 30);
    const Id a = s.addInstance(s.addMesh(std::move(outer)), s.addNode("outer", 0));
    const Id b = s.addInstance(s.addMesh(makeBox({0.8f, 0.8f, 0.8f})), s.addNode("inner", 0));
    const AggregatePart parts[] = {{a, nullptr}, {b, nullptr}};
    return aggregateParts(s, parts, glm::dvec3(0.0));
}

// Budget of a node bounding the 2 m box: diameter 2 sqrt(3) m at 300 px -> 11.5 mm.
const double kBoxBudget = proxyErrorBudget(2.0 * std::sqrt(3.0), ScreenParams{});

} // namespace

TEST(RemeshProxy, BoxInsideClosedBoxDisappears) {
    const ProxyMesh proxy = remeshProxy(boxInBox(false), kBoxBudget);
    ASSERT_FALSE(proxy.empty());
    // Every vertex lies on the outer box's surface within the budget; nothing is left near
    // the inner box (max-norm 0.4) nor on the inside of the outer walls.
    for (const glm::vec3& p : proxy.positions) {
        EXPECT_NEAR(maxNorm(glm::dvec3(p)), 1.0, kBoxBudget);
    }
    EXPECT_EQ(test::openEdgeCount(proxy), 0u); // watertight
    // Outward facing and enclosing the 8 m^3 box, inflated by at most the budget.
    const double volume = test::signedVolume(proxy);
    EXPECT_GT(volume, 8.0);
    EXPECT_LT(volume, std::pow(2.0 + 2.0 * kBoxBudget, 3.0));
    // 24 input triangles (12 of them hidden) -> a box with slightly rounded edges.
    EXPECT_LT(proxy.triangleCount(), 400u);
}

TEST(RemeshProxy, BoxSeenThroughAnOpeningStays) {
    // A 2 m hole is far wider than the shell (2 d = 7 mm): the fill enters, the inner box is
    // visible, so it must survive.
    const ProxyMesh proxy = remeshProxy(boxInBox(true), kBoxBudget);
    std::size_t nearInner = 0;
    for (const glm::vec3& p : proxy.positions) {
        if (std::abs(maxNorm(glm::dvec3(p)) - 0.4) <= kBoxBudget) ++nearInner;
    }
    EXPECT_GE(nearInner, 8u); // at least the inner box's corners
    EXPECT_EQ(test::openEdgeCount(proxy), 0u);
}

TEST(RemeshProxy, OpenSheetBecomesClosedThinSlab) {
    // A single 1 m quad (open, one-sided, like a game wall) cannot enclose anything: the shell
    // around it is a closed slab 2 d thick, within the budget of the quad everywhere.
    Scene s;
    Mesh quad;
    quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    quad.indices = {0, 1, 2, 0, 2, 3};
    const Id inst = s.addInstance(s.addMesh(std::move(quad)), s.addNode("wall", 0));
    const AggregatePart part{inst, nullptr};
    const double e = proxyErrorBudget(std::sqrt(2.0), ScreenParams{});
    const ProxyMesh proxy = remeshProxy(aggregateParts(s, std::span(&part, 1), {}), e);
    ASSERT_FALSE(proxy.empty());
    EXPECT_EQ(test::openEdgeCount(proxy), 0u);
    for (const glm::vec3& p : proxy.positions) {
        EXPECT_LE(std::abs(p.z), e);
        EXPECT_GE(p.x, -e);
        EXPECT_LE(p.x, 1.0 + e);
    }
    EXPECT_GT(test::signedVolume(proxy), 0.0);
}

TEST(RemeshProxy, SphereStaysWithinErrorBudgetBothWays) {
    Scene s;
    const Id inst = s.addInstance(s.addMesh(makeSphere(1.0f, 128, 64)), s.addNode("s", 0));
    const AggregatePart part{inst, nullptr};
    const double e = 2.0 / 300.0;
    const ProxyMesh proxy = remeshProxy(aggregateParts(s, std::span(&part, 1), {}), e);
    double worst = 0.0;
    for (const glm::dvec3& p : test::surfaceSamples(proxy)) {
        worst = std::max(worst, std::abs(glm::length(p) - 1.0));
    }
    for (int i = 0; i < 300; ++i) {
        const double z = 1.0 - 2.0 * (i + 0.5) / 300, r = std::sqrt(1.0 - z * z);
        const glm::dvec3 u(r * std::cos(i * 2.399963), r * std::sin(i * 2.399963), z);
        worst = std::max(worst, test::distanceToMesh(proxy, u));
    }
    EXPECT_LE(worst, e);
    EXPECT_EQ(test::openEdgeCount(proxy), 0u);
}

TEST(RemeshProxy, CancelFlagStopsWithCancelledError) {
    std::atomic<bool> cancel{true};
    Progress progress;
    progress.cancel = &cancel;
    try {
        remeshProxy(boxInBox(false), kBoxBudget, progress);
        FAIL() << "expected Error(Cancelled)";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ErrorCode::Cancelled);
    }
}
