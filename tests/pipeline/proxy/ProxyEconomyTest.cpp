// The proxy economy (ProxyBaker.h, ProxyEconomy.h): a node keeps its proxy only when it has at
// most rho x the triangles it replaces; otherwise it is dissolved and its children move up.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "TestUtil.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/io/Import.h"
#include "pipeline/proxy/ProxyEconomy.h"
#include "pipeline/proxy/ProxyTestUtil.h"
#include "pipeline/scene/Primitives.h"

using namespace hlod;

namespace {

// Two clusters under the root. "smooth": two finely tessellated spheres (48 x 24 segments,
// 2,208 triangles each, radius 0.5 m): with a budget of about a centimetre a sphere needs a
// tenth of that, so its proxy pays. "boxes": four 1 m boxes 2 m apart (12 triangles each),
// each far larger than the budget and already minimal, so no proxy can drop anything: it
// keeps all 48 triangles and does not pay.
struct Fixture {
    Scene scene;
    ClusterTree tree;
    Id smooth = kNoId, boxes = kNoId;
    std::vector<Id> boxLeaves;

    explicit Fixture(bool lockBoxes = false) {
        const Id sphere = scene.addMesh(makeSphere(0.5f, 48, 24));
        const Id box = scene.addMesh(makeBox(glm::vec3(1.0f)));
        auto place = [&](Id mesh, const glm::dvec3& at) {
            const Id node = scene.addNode("o", 0, glm::translate(glm::dmat4(1.0), at));
            return scene.addInstance(mesh, node);
        };
        test::TreeBuilder b(scene);
        smooth = b.inner({b.leaf(place(sphere, {0, 0, 0})), b.leaf(place(sphere, {1.2, 0, 0}))});
        for (int k = 0; k < 4; ++k)
            boxLeaves.push_back(b.leaf(place(box, {10.0 + 2.0 * k, 0, 0})));
        boxes = b.inner(boxLeaves);
        tree = b.finish(b.inner({smooth, boxes}));
        tree.nodes[boxes].locked = lockBoxes;
    }
};

} // namespace

TEST(ProxyEconomy, AProxyThatPaysIsKeptAndOneThatDoesNotIsDissolved) {
    Fixture f;
    BakeParams params; // rho = 0.35
    const BakeResult r = bakeProxies(f.scene, f.tree, params);
    const NodeBake& smooth = r.nodes[f.smooth];
    EXPECT_FALSE(smooth.dissolved);
    EXPECT_EQ(smooth.inputTriangles, 2u * 2208u);
    EXPECT_LE(smooth.proxy.triangleCount(), 0.35 * 2 * 2208);
    EXPECT_GT(smooth.proxy.triangleCount(), 0u);
    // The boxes' proxy would keep their 48 triangles: 48 > 0.35 * 48.
    EXPECT_TRUE(r.nodes[f.boxes].dissolved);
    EXPECT_EQ(r.nodes[f.boxes].inputTriangles, 48u);
    EXPECT_TRUE(r.nodes[f.boxes].proxy.empty()); // a dissolved node keeps no proxy
    // The root was judged with the boxes themselves among its inputs.
    EXPECT_EQ(r.nodes[f.tree.root].inputTriangles, smooth.proxy.triangleCount() + 48u);
}

TEST(ProxyEconomy, DissolvedNodesChildrenHangFromTheirParent) {
    Fixture f;
    ClusterTree tree = f.tree;
    const BakeResult r = bakeEconomised(f.scene, tree, BakeParams{});
    // 2 spheres + 4 boxes + smooth + root: the boxes' cluster is gone.
    ASSERT_EQ(tree.nodes.size(), f.tree.nodes.size() - 1);
    ASSERT_EQ(r.nodes.size(), tree.nodes.size());
    const ClusterNode& root = tree.nodes[tree.root];
    ASSERT_EQ(root.children.size(), 5u); // smooth + the four boxes
    std::size_t leaves = 0;
    for (Id c : root.children) {
        if (!tree.nodes[c].isLeaf()) continue;
        ++leaves;
        EXPECT_EQ(tree.nodes[c].parent, tree.root);
        EXPECT_EQ(f.scene.instances[tree.nodes[c].instance].mesh, 1u); // a box
    }
    EXPECT_EQ(leaves, 4u);
    EXPECT_EQ(r.dissolved, r.nodes[tree.root].hasProxy ? 1u : 2u);
    EXPECT_EQ(root.level, 2); // smooth (level 1) is its highest child
}

TEST(ProxyEconomy, ALockedClusterIsNeverDissolved) {
    Fixture f(/*lockBoxes=*/true);
    ClusterTree tree = f.tree;
    const BakeResult r = bakeEconomised(f.scene, tree, BakeParams{});
    EXPECT_EQ(tree.nodes.size(), f.tree.nodes.size());
    EXPECT_FALSE(r.nodes[f.boxes].dissolved);
    EXPECT_EQ(r.nodes[f.boxes].proxy.triangleCount(), 48u); // kept although it saves nothing
}

TEST(ProxyEconomy, RhoOfOneKeepsTheTreeAsClustered) {
    Fixture f;
    ClusterTree tree = f.tree;
    BakeParams params;
    params.proxyRatio = 1.0; // a proxy never has more triangles than its input
    const BakeResult r = bakeEconomised(f.scene, tree, params);
    EXPECT_EQ(tree.nodes.size(), f.tree.nodes.size());
    EXPECT_EQ(r.dissolved, 0u);
}

TEST(ProxyEconomy, ARootWhoseProxyDoesNotPayKeepsNoneAndIsAlwaysRefined) {
    // The four boxes alone under the root: nothing to drop, and no parent to move up to.
    Scene scene;
    const Id box = scene.addMesh(makeBox(glm::vec3(1.0f)));
    test::TreeBuilder b(scene);
    std::vector<Id> leaves;
    for (int k = 0; k < 4; ++k) {
        const Id node = scene.addNode("b", 0, glm::translate(glm::dmat4(1.0), {2.0 * k, 0, 0}));
        leaves.push_back(b.leaf(scene.addInstance(box, node)));
    }
    ClusterTree tree = b.finish(b.inner(leaves));
    const BakeResult r = bakeEconomised(scene, tree, BakeParams{});
    EXPECT_EQ(tree.nodes.size(), 5u);
    EXPECT_TRUE(rootHasNoProxy(tree, r));
    EXPECT_TRUE(r.nodes[tree.root].proxy.empty());
    EXPECT_EQ(r.proxyTriangles, 0u);
}

TEST(ProxyEconomy, TranslatedCopiesOfAClusterAreBakedOnce) {
    // Three copies of the smooth pair, 20 m apart: bake frames are relative to each cluster's
    // first input (BakeFrame.h), so the three keys agree and only the first is baked.
    Scene scene;
    const Id sphere = scene.addMesh(makeSphere(0.5f, 48, 24));
    test::TreeBuilder b(scene);
    std::vector<Id> pairs;
    for (int c = 0; c < 3; ++c) {
        std::vector<Id> kids;
        for (int k = 0; k < 2; ++k) {
            const glm::dvec3 at(1000.0 + 20.0 * c + 1.2 * k, 3.0, -7.0);
            const Id node = scene.addNode("s", 0, glm::translate(glm::dmat4(1.0), at));
            kids.push_back(b.leaf(scene.addInstance(sphere, node)));
        }
        pairs.push_back(b.inner(kids));
    }
    const ClusterTree tree = b.finish(b.inner(pairs));
    const BakeResult r = bakeProxies(scene, tree, BakeParams{});
    EXPECT_EQ(r.baked, 2u); // one pair and the root
    EXPECT_EQ(r.reused, 2u);
    EXPECT_EQ(r.nodes[pairs[0]].key, r.nodes[pairs[1]].key);
    EXPECT_EQ(r.nodes[pairs[1]].proxy.positions, r.nodes[pairs[2]].proxy.positions);
}

TEST(ProxyEconomy, EveryKeptProxyPaysAndAllTogetherStayWithinTheBoundOnARealScene) {
    // as1-assembly (STEP, 18 instances of 5 parts), clustered and baked at the defaults.
    const Scene scene = importScene({test::dataDir() / "scenes/as1-assembly/as1-oc-214.stp"});
    ClusterParams cluster;
    cluster.levelGrowth = kDefaultLevelGrowth;
    ClusterTree tree = buildClusterTree(scene, cluster);
    const BakeParams params;
    const BakeResult r = bakeEconomised(scene, tree, params);
    std::size_t original = 0;
    for (const MeshInstance& inst : scene.instances)
        original += scene.meshes[inst.mesh].triangleCount();
    std::size_t proxies = 0, kept = 0;
    for (Id id = 0; id < tree.nodes.size(); ++id) {
        if (tree.nodes[id].isLeaf() || !r.nodes[id].hasProxy) continue;
        ++kept;
        EXPECT_LE(static_cast<double>(r.nodes[id].proxy.triangleCount()),
                  params.proxyRatio * static_cast<double>(r.nodes[id].inputTriangles));
        proxies += r.nodes[id].proxy.triangleCount();
    }
    EXPECT_GT(kept, 0u);
    EXPECT_EQ(proxies, r.proxyTriangles);
    // Each kept level holds at most rho of the one below: rho / (1 - rho) of the original.
    EXPECT_LE(static_cast<double>(proxies),
              params.proxyRatio / (1.0 - params.proxyRatio) * static_cast<double>(original));
}
