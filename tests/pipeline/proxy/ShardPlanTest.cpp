// The distributed bake's cut (ShardPlan.h) and the subtree bake (bakeSubtrees): the cut
// balances estimated cost, keeps copies together and covers every inner node once; shards
// baked from their slices plus a bake of the whole tree over the same cache give exactly the
// single machine's proxies.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "TestUtil.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/io/SampleScene.h"
#include "pipeline/proxy/ProxyBaker.h"
#include "pipeline/proxy/ProxyTestUtil.h"
#include "pipeline/proxy/ShardPlan.h"
#include "pipeline/scene/Primitives.h"

using namespace hlod;

namespace {

// `triangles` separate triangles in a row (each its own three vertices): a mesh whose cost
// estimate is exactly its triangle count.
Mesh triangles(int count) {
    Mesh m;
    for (int i = 0; i < count; ++i) {
        const auto base = static_cast<std::uint32_t>(m.positions.size());
        const float x = static_cast<float>(i) * 0.01f;
        m.positions.insert(m.positions.end(), {{x, 0, 0}, {x + 0.01f, 0, 0}, {x, 0.01f, 0}});
        m.normals.insert(m.normals.end(), 3, {0, 0, 1});
        m.indices.insert(m.indices.end(), {base, base + 1, base + 2});
    }
    return m;
}

Id place(Scene& scene, Id mesh, const glm::dvec3& at) {
    return scene.addInstance(mesh, scene.addNode("n", 0, glm::translate(glm::dmat4(1.0), at)));
}

BakeParams fastParams() {
    BakeParams p;
    p.method = ProxyMethod::Sloppy;
    p.atlas.enabled = false;
    p.threads = 2;
    return p;
}

// Every inner node under the root is in exactly one shard's subtree or above the cut, and the
// nodes above the cut are closed upwards (their parents are above it too).
void expectCover(const ClusterTree& tree, const ShardPlan& plan) {
    std::vector<int> owner(tree.nodes.size(), -1);
    for (int s = 0; s < plan.shards; ++s) {
        for (Id r : plan.roots[static_cast<std::size_t>(s)]) {
            std::vector<Id> stack{r};
            while (!stack.empty()) {
                const Id id = stack.back();
                stack.pop_back();
                if (tree.nodes[id].isLeaf()) continue;
                EXPECT_EQ(owner[id], -1) << "node " << id << " in two shards";
                owner[id] = s;
                for (Id c : tree.nodes[id].children)
                    stack.push_back(c);
            }
        }
    }
    const std::set<Id> top(plan.top.begin(), plan.top.end());
    for (Id id = 0; id < tree.nodes.size(); ++id) {
        if (tree.nodes[id].isLeaf()) continue;
        EXPECT_NE(owner[id] >= 0, top.count(id) == 1) << "node " << id;
        if (top.count(id) && tree.nodes[id].parent != kNoId) {
            EXPECT_EQ(top.count(tree.nodes[id].parent), 1u) << "node " << id;
        }
    }
}

// Root R over four groups A, B, C, D 10 m apart; each holds two leaves of 200, 150, 100 and 50
// triangles (one mesh placed twice). `groups` gets A..D.
ClusterTree fourGroups(Scene& scene, std::vector<Id>& groups) {
    test::TreeBuilder b(scene);
    double x = 0.0;
    for (int tris : {200, 150, 100, 50}) {
        const Id mesh = scene.addMesh(triangles(tris));
        groups.push_back(b.inner(
            {b.leaf(place(scene, mesh, {x, 0, 0})), b.leaf(place(scene, mesh, {x, 1, 0}))}));
        x += 10.0;
    }
    return b.finish(b.inner(groups));
}

} // namespace

TEST(ShardPlan, BalancesEstimatedCostNotTheNumberOfSubtrees) {
    // Root R over A, B, C, D; each holds two leaves of 200, 150, 100, 50 triangles, so their
    // estimated inputs are 400, 300, 200, 100 and R's is rho x 1000 = 350 (rho 0.35). Cutting
    // below R and filling 2 shards largest first: A -> 0, B -> 1, C -> 1 (300 < 400),
    // D -> 0: 500 each. Cutting deeper would move 100..400 more above the cut: not done.
    Scene scene;
    std::vector<Id> groups;
    const ClusterTree tree = fourGroups(scene, groups);
    const ShardPlan plan = planShards(scene, tree, fastParams(), 2);
    EXPECT_EQ(plan.roots[0], (std::vector<Id>{groups[0], groups[3]}));
    EXPECT_EQ(plan.roots[1], (std::vector<Id>{groups[1], groups[2]}));
    EXPECT_DOUBLE_EQ(plan.cost[0], 500.0);
    EXPECT_DOUBLE_EQ(plan.cost[1], 500.0);
    EXPECT_EQ(plan.top, std::vector<Id>{tree.root});
    EXPECT_DOUBLE_EQ(plan.topCost, 350.0);
    EXPECT_DOUBLE_EQ(plan.totalCost, 1350.0);
    expectCover(tree, plan);
}

TEST(ShardPlan, SplitsOnPastACutThatIsNoBetterToBalanceTwoHeavySubtrees) {
    // Root R over X and Y, each over four groups of two 100-triangle leaves (input 200 each),
    // rho 0.1: X and Y are estimated 0.1 x 800 = 80 each, R 0.1 x 160 = 16. On 3 shards:
    // cutting below R gives units X and Y of 880: makespan 16 + 880 = 896. Splitting X alone
    // is worse (top 96, Y still 880: 976), so a search that stops there keeps 896; splitting
    // Y too gives eight units of 200 on 3 shards (600, 600, 400) under a top of 176: 776.
    Scene scene;
    test::TreeBuilder b(scene);
    const Id mesh = scene.addMesh(triangles(100));
    std::vector<Id> halves;
    for (int h = 0; h < 2; ++h) {
        std::vector<Id> groups;
        for (int g = 0; g < 4; ++g) {
            // The second leaf's offset differs per group: no two groups are copies.
            const glm::dvec3 at(20.0 * g, 20.0 * h, 0);
            groups.push_back(b.inner(
                {b.leaf(place(scene, mesh, at)),
                 b.leaf(place(scene, mesh, at + glm::dvec3(0, 1.0 + 0.5 * (4 * h + g), 0)))}));
        }
        halves.push_back(b.inner(groups));
    }
    const ClusterTree tree = b.finish(b.inner(halves));
    BakeParams params = fastParams();
    params.proxyRatio = 0.1;
    const ShardPlan plan = planShards(scene, tree, params, 3);
    std::vector<double> cost = plan.cost;
    std::sort(cost.begin(), cost.end());
    EXPECT_EQ(cost, (std::vector<double>{400.0, 600.0, 600.0}));
    EXPECT_EQ(plan.top, (std::vector<Id>{halves[0], halves[1], tree.root}));
    EXPECT_DOUBLE_EQ(plan.topCost, 176.0);
    EXPECT_DOUBLE_EQ(plan.largestOverMean(), 600.0 / (1600.0 / 3.0));
    EXPECT_DOUBLE_EQ(plan.predictedSpeedup(), 1776.0 / 776.0);
    expectCover(tree, plan);
}

TEST(ShardPlan, MeasuredCostsReplaceTheEstimates) {
    // The four groups of BalancesEstimatedCostNotTheNumberOfSubtrees (estimated 400, 300,
    // 200, 100), measured at 1, 1, 1 and 3 CPU seconds: 6 s for 1000 estimated triangles, so
    // the unmeasured root costs 350 x 0.006 = 2.1 s. Balanced by seconds, the smallest group
    // by triangles is a shard alone: {D} 3 s, {A, B, C} 3 s.
    Scene scene;
    std::vector<Id> groups;
    const ClusterTree tree = fourGroups(scene, groups);
    const std::vector<std::uint64_t> keys = structuralKeys(scene, tree, fastParams());
    const MeasuredCosts measured{{keys[groups[0]], 1.0},
                                 {keys[groups[1]], 1.0},
                                 {keys[groups[2]], 1.0},
                                 {keys[groups[3]], 3.0}};
    const ShardPlan plan = planShards(scene, tree, fastParams(), 2, measured);
    EXPECT_EQ(plan.measuredNodes, 4u);
    EXPECT_DOUBLE_EQ(plan.secondsPerTriangle, 0.006);
    EXPECT_EQ(plan.roots[0], (std::vector<Id>{groups[3]}));
    EXPECT_EQ(plan.roots[1], (std::vector<Id>{groups[0], groups[1], groups[2]}));
    EXPECT_DOUBLE_EQ(plan.cost[0], 3.0);
    EXPECT_DOUBLE_EQ(plan.cost[1], 3.0);
    EXPECT_DOUBLE_EQ(plan.topCost, 2.1);
    expectCover(tree, plan);
}

TEST(ShardPlan, TranslatedCopiesStayInOneShard) {
    // Four translated copies G1..G4 of a pair of boxes and one different pair H under the
    // root. The copies bake once, so they are one unit of 2 x 12 = 24 triangles, as costly as
    // H (two 12-triangle boxes of another size): one shard gets all four copies, the other H.
    Scene scene;
    const Id box = scene.addMesh(makeBox({1.0f, 1.0f, 1.0f}));
    const Id other = scene.addMesh(makeBox({2.0f, 0.5f, 1.0f}));
    test::TreeBuilder b(scene);
    std::vector<Id> children, copies;
    for (int g = 0; g < 4; ++g) {
        const glm::dvec3 at(20.0 * g, 0, 0);
        copies.push_back(b.inner({b.leaf(place(scene, box, at)),
                                  b.leaf(place(scene, box, at + glm::dvec3(1.5, 0, 0)))}));
        children.push_back(copies.back());
    }
    const Id h =
        b.inner({b.leaf(place(scene, other, {0, 20, 0})), b.leaf(place(scene, other, {3, 20, 0}))});
    children.push_back(h);
    const ClusterTree tree = b.finish(b.inner(children));
    const std::vector<std::uint64_t> keys = structuralKeys(scene, tree, fastParams());
    ASSERT_EQ(keys[copies[0]], keys[copies[3]]);
    ASSERT_NE(keys[copies[0]], keys[h]);

    const ShardPlan plan = planShards(scene, tree, fastParams(), 2);
    std::vector<std::vector<Id>> got = plan.roots;
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, (std::vector<std::vector<Id>>{copies, {h}}));
    EXPECT_DOUBLE_EQ(plan.cost[0], 24.0);
    EXPECT_DOUBLE_EQ(plan.cost[1], 24.0);
    expectCover(tree, plan);
}

TEST(ShardPlan, CoversTheSampleSceneForAnyShardCount) {
    const Scene scene = makeSampleScene();
    const ClusterTree tree = buildClusterTree(scene, ClusterParams{});
    for (int n : {1, 2, 3, 8, 40}) {
        const ShardPlan plan = planShards(scene, tree, fastParams(), n);
        ASSERT_EQ(plan.roots.size(), static_cast<std::size_t>(n));
        expectCover(tree, plan);
        double sum = plan.topCost;
        for (double c : plan.cost)
            sum += c;
        EXPECT_NEAR(sum, plan.totalCost, 1e-6 * plan.totalCost) << n << " shards";
    }
    EXPECT_THROW(planShards(scene, tree, fastParams(), 0), Error);
}

TEST(ShardPlan, StructuralKeysAreTheBakersKeysWhenNothingIsDissolved) {
    const Scene scene = makeSampleScene();
    const ClusterTree tree = buildClusterTree(scene, ClusterParams{});
    BakeParams params = fastParams();
    params.proxyRatio = 1000.0; // every proxy kept: the inputs are the children
    const BakeResult bake = bakeProxies(scene, tree, params);
    const std::vector<std::uint64_t> keys = structuralKeys(scene, tree, params);
    for (Id id = 0; id < tree.nodes.size(); ++id)
        EXPECT_EQ(keys[id], bake.nodes[id].key) << "node " << id;
}

TEST(ShardPlan, SliceKeepsOnlyTheShardsMeshesAndEveryId) {
    const Scene scene = makeSampleScene();
    const ClusterTree tree = buildClusterTree(scene, ClusterParams{});
    const ShardPlan plan = planShards(scene, tree, fastParams(), 3);
    const Scene slice = sliceScene(scene, tree, plan.roots[0]);
    ASSERT_EQ(slice.meshes.size(), scene.meshes.size());
    EXPECT_EQ(slice.instances.size(), scene.instances.size());
    EXPECT_EQ(slice.nodes.size(), scene.nodes.size());
    std::set<Id> used;
    std::vector<Id> stack(plan.roots[0].begin(), plan.roots[0].end());
    while (!stack.empty()) {
        const ClusterNode& n = tree.nodes[stack.back()];
        stack.pop_back();
        if (n.isLeaf()) used.insert(scene.instances[n.instance].mesh);
        stack.insert(stack.end(), n.children.begin(), n.children.end());
    }
    ASSERT_FALSE(used.empty());
    for (Id m = 0; m < scene.meshes.size(); ++m) {
        EXPECT_EQ(slice.meshes[m].indices.size(),
                  used.count(m) ? scene.meshes[m].indices.size() : 0u)
            << "mesh " << m;
    }
}

TEST(ShardPlan, ShardsFromSlicesThenTheWholeTreeBakeTheSingleMachinesProxies) {
    const Scene scene = makeSampleScene();
    const ClusterTree tree = buildClusterTree(scene, ClusterParams{});
    BakeParams params = fastParams();
    const BakeResult single = bakeProxies(scene, tree, params);

    test::TempDir cache;
    params.cacheDir = cache.path();
    const ShardPlan plan = planShards(scene, tree, params, 3);
    std::size_t shardInner = 0;
    for (const std::vector<Id>& roots : plan.roots) {
        const BakeResult shard = bakeSubtrees(sliceScene(scene, tree, roots), tree, roots, params);
        shardInner += shard.innerNodes;
        for (Id r : roots)
            EXPECT_EQ(shard.nodes[r].key, single.nodes[r].key) << "shard root " << r;
    }
    EXPECT_EQ(shardInner + plan.top.size(), single.innerNodes);

    const BakeResult final = bakeProxies(scene, tree, params);
    EXPECT_LE(final.baked, plan.top.size()); // everything below the cut came from the cache
    EXPECT_EQ(final.damaged, 0u);
    for (Id id = 0; id < tree.nodes.size(); ++id) {
        const NodeBake& a = single.nodes[id];
        const NodeBake& b = final.nodes[id];
        EXPECT_EQ(a.key, b.key) << id;
        EXPECT_EQ(a.dissolved, b.dissolved) << id;
        EXPECT_EQ(a.hasProxy, b.hasProxy) << id;
        EXPECT_EQ(a.proxy.positions, b.proxy.positions) << id;
        EXPECT_EQ(a.proxy.indices, b.proxy.indices) << id;
        EXPECT_EQ(a.proxy.colors, b.proxy.colors) << id;
    }
}

TEST(ShardPlan, TexturedShardBakesTheSameAtlasesFromItsSlice) {
    // Two groups of textured quads, each with its own texture; the shard holding one group
    // gets only that group's texture in its slice, and its atlases are the single machine's.
    Scene scene;
    test::TreeBuilder b(scene);
    std::vector<Id> groups;
    for (int g = 0; g < 2; ++g) {
        auto image = std::make_shared<RgbaImage>(8, 8);
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x)
                image->set(x, y,
                           (x + y + g) % 2 ? glm::u8vec4(0, 0, 0, 255)
                                           : glm::u8vec4(255, 200, 0, 255));
        Texture texture;
        texture.name = "board" + std::to_string(g);
        texture.image = image;
        Material material;
        material.hasTexture = true;
        material.texture = scene.addTexture(texture);
        Mesh quad;
        quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
        quad.normals.assign(4, {0, 0, 1});
        quad.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
        quad.indices = {0, 1, 2, 0, 2, 3};
        quad.material = scene.addMaterial(material);
        const Id mesh = scene.addMesh(quad);
        const glm::dvec3 at(10.0 * g, 0, 0);
        groups.push_back(b.inner({b.leaf(place(scene, mesh, at)),
                                  b.leaf(place(scene, mesh, at + glm::dvec3(1, 0, 0)))}));
    }
    const ClusterTree tree = b.finish(b.inner(groups));
    BakeParams params;
    params.proxyRatio = 1000.0; // kept: every group proxy gets an atlas
    params.threads = 1;
    const BakeResult single = bakeProxies(scene, tree, params);
    ASSERT_TRUE(single.nodes[groups[1]].proxy.hasAtlas());

    const std::vector<Id> roots{groups[1]};
    const Scene slice = sliceScene(scene, tree, roots);
    EXPECT_EQ(slice.textures[0].image, nullptr); // group 0's texture is not read
    ASSERT_NE(slice.textures[1].image, nullptr);
    const BakeResult shard = bakeSubtrees(slice, tree, roots, params);
    const ProxyMesh& a = single.nodes[groups[1]].proxy;
    const ProxyMesh& s = shard.nodes[groups[1]].proxy;
    EXPECT_EQ(shard.nodes[groups[1]].key, single.nodes[groups[1]].key);
    ASSERT_TRUE(s.hasAtlas());
    EXPECT_EQ(s.positions, a.positions);
    EXPECT_EQ(s.uvs, a.uvs);
    EXPECT_EQ(s.atlas->encoded, a.atlas->encoded);
}

TEST(ShardPlan, SubtreeRootsMustBeDistinctInnerNodesNotBelowEachOther) {
    const Scene scene = makeSampleScene();
    const ClusterTree tree = buildClusterTree(scene, ClusterParams{});
    const Id inner = tree.nodes[tree.root].children.front();
    Id leaf = 0;
    while (!tree.nodes[leaf].isLeaf())
        ++leaf;
    EXPECT_THROW(bakeSubtrees(scene, tree, {leaf}, fastParams()), Error);
    EXPECT_THROW(bakeSubtrees(scene, tree, {inner, inner}, fastParams()), Error);
    if (!tree.nodes[inner].isLeaf()) {
        EXPECT_NE(test::problemOf([&] {
                      bakeSubtrees(scene, tree, {tree.root, inner}, fastParams());
                  }).find("lies below"),
                  std::string::npos);
    }
}
