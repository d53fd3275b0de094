// LOD selection against a brute-force reference: the cut is, by definition, every node whose
// ancestors are all "open" (visible, inner, projecting larger than S) and which is not open
// itself; drawn nodes are the visible ones of the cut. Algorithm 5 and the front cache must
// both produce exactly that, on random trees and cameras, over camera paths with jumps.
#include <gtest/gtest.h>

#include <cmath>

#include "pipeline/select/LodSelection.h"
#include "select/RandomTree.h"

using namespace hlod;

namespace {

std::vector<Id> referenceDrawList(const SelectionTree& tree, const Camera& cam,
                                  const SelectionParams& p) {
    const NodeClassifier cls(tree, cam, p);
    std::vector<Id> out;
    for (Id n = 0; n < tree.size(); ++n) {
        bool ancestorsOpen = true;
        for (Id a = tree.parent(n); a != kNoId; a = tree.parent(a))
            ancestorsOpen &= cls.open(a);
        if (ancestorsOpen && !cls.open(n) && cls.visible(n)) out.push_back(n);
    }
    return out;
}

Camera randomCamera(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1500.0, 1500.0), h(1.0, 400.0);
    Camera c;
    c.eye = {u(rng), h(rng), u(rng)};
    c.target = {u(rng) * 0.3, 0.0, u(rng) * 0.3};
    c.viewportHeight = 720;
    c.aspect = 1280.0 / 720.0;
    c.farPlane = 1e5;
    return c;
}

std::vector<std::uint64_t> unitTriangles(const ClusterTree& t) {
    std::vector<std::uint64_t> tris(t.nodes.size());
    for (std::size_t i = 0; i < tris.size(); ++i)
        tris[i] = 10 + i % 7;
    return tris;
}

} // namespace

TEST(LodSelection, FullTraversalMatchesTheDefinitionOnRandomTrees) {
    for (unsigned seed = 1; seed <= 6; ++seed) {
        const ClusterTree t = hlod::test::randomTree(400, seed);
        const SelectionTree st(t, unitTriangles(t));
        std::mt19937_64 rng(seed * 77);
        for (int i = 0; i < 40; ++i) {
            const Camera cam = randomCamera(rng);
            for (double s : {30.0, 300.0, 2000.0}) {
                const SelectionParams p{s};
                const SelectionResult full = selectFull(st, cam, p);
                EXPECT_EQ(full.drawList, referenceDrawList(st, cam, p)) << seed << " " << i;
                EXPECT_EQ(full.drawCalls, full.drawList.size());
            }
        }
    }
}

TEST(LodSelection, FrontCacheGivesTheSameCutAlongPathsWithJumps) {
    for (unsigned seed = 11; seed <= 14; ++seed) {
        const ClusterTree t = hlod::test::randomTree(600, seed, 6);
        const SelectionTree st(t, unitTriangles(t));
        FrontCache cache(st);
        std::mt19937_64 rng(seed);
        Camera cam = randomCamera(rng);
        const SelectionParams p{300.0};
        for (int frame = 0; frame < 200; ++frame) {
            if (frame % 50 == 49) {
                cam = randomCamera(rng); // a teleport: the cache must cope with any change
            } else {                     // smooth fly-in towards the target
                cam.eye += (cam.target - cam.eye) * 0.03;
            }
            const SelectionResult a = cache.select(cam, p);
            const SelectionResult b = selectFull(st, cam, p);
            ASSERT_EQ(a.drawList, b.drawList) << "seed " << seed << " frame " << frame;
            EXPECT_EQ(a.triangles, b.triangles);
        }
    }
}

TEST(LodSelection, FarCameraDrawsOnlyTheRootAndBehindCameraDrawsNothing) {
    const ClusterTree t = hlod::test::randomTree(100, 3);
    const SelectionTree st(t, unitTriangles(t));
    Camera far;
    far.eye = {0, 0, 1e7}; // the whole scene (< 3 km) is a few pixels from 10,000 km
    far.target = {0, 0, 0};
    far.farPlane = 1e8;
    const SelectionResult r = selectFull(st, far, {300.0});
    ASSERT_EQ(r.drawList.size(), 1u);
    EXPECT_EQ(r.drawList[0], t.root);
    EXPECT_EQ(r.nodesVisited, 1u);
    Camera away = far;
    away.target = {0, 0, 2e7}; // looking away from the scene
    EXPECT_TRUE(selectFull(st, away, {300.0}).drawList.empty());
}

TEST(LodSelection, SwitchDistanceIsWhereTheProjectedDiameterEqualsS) {
    // A sphere of radius 10 at the switch distance projects to exactly S pixels:
    // diameter_px = 2r · H / (2 d tan(fov/2)).
    const double fov = 0.7853981633974483, S = 300.0;
    const int H = 1080;
    const double d = switchDistance(10.0, S, fov, H);
    EXPECT_NEAR(2.0 * 10.0 * H / (2.0 * d * std::tan(fov / 2)), S, 1e-9);
    EXPECT_NEAR(d, 10.0 * 1080 / (std::tan(fov / 2) * 300.0), 1e-9); // 86.9 m
}

TEST(LodSelection, TriangleCountsAddUpOverTheDrawList) {
    // Root with two leaves; close up both leaves are drawn, far away only the root.
    ClusterTree t;
    t.nodes.resize(3);
    t.nodes[0].sphere = {{-5, 0, 0}, 1};
    t.nodes[0].parent = 2;
    t.nodes[1].sphere = {{5, 0, 0}, 1};
    t.nodes[1].parent = 2;
    t.nodes[2].sphere = {{0, 0, 0}, 6};
    t.nodes[2].children = {0, 1};
    t.root = 2;
    const SelectionTree st(t, {100, 200, 50});
    Camera near;
    near.eye = {0, 0, 20};
    const SelectionResult a = selectFull(st, near, {300.0});
    EXPECT_EQ(a.drawList, (std::vector<Id>{0, 1}));
    EXPECT_EQ(a.triangles, 300u);
    Camera far = near;
    far.eye = {0, 0, 2000};
    const SelectionResult b = selectFull(st, far, {300.0});
    EXPECT_EQ(b.drawList, (std::vector<Id>{2}));
    EXPECT_EQ(b.triangles, 50u);
}
