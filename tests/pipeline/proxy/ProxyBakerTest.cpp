#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <mutex>

#include <glm/gtc/matrix_transform.hpp>

#include "TestUtil.h"
#include "pipeline/core/Error.h"
#include "pipeline/proxy/ProxyBaker.h"
#include "pipeline/proxy/ProxyCache.h"
#include "pipeline/proxy/ProxyTestUtil.h"
#include "pipeline/scene/Primitives.h"

using namespace hlod;

namespace {

// `groups` x 4 objects (spheres and cylinders) on a grid; tree: root -> one inner node per
// group -> 4 leaves. With 4 groups: 4 level-1 nodes + the root = 5 inner nodes. Group g's
// objects sit 0.1 g further apart than group 0's, so no two groups are translated copies of
// each other (those share one bake, see the copies test below).
struct Fixture {
    Scene scene;
    ClusterTree tree;
    std::vector<Id> groupNodes;

    explicit Fixture(int groups = 4) {
        const Id sphere = scene.addMesh(makeSphere(0.5f, 48, 24));
        const Id cylinder = scene.addMesh(makeCylinder(0.3f, 1.0f, 32));
        Material red;
        red.baseColor = {0.8f, 0.1f, 0.1f, 1.0f};
        scene.meshes[cylinder].material = scene.addMaterial(red);
        std::vector<std::pair<int, Id>> leaves;
        for (int g = 0; g < groups; ++g) {
            for (int k = 0; k < 4; ++k) {
                const double spread = 1.5 + 0.1 * g;
                const glm::dvec3 at(g * 10.0 + (k % 2) * spread, 0.0, (k / 2) * spread);
                const Id node = scene.addNode("o", 0, glm::translate(glm::dmat4(1.0), at));
                leaves.push_back({g, scene.addInstance(k % 2 ? cylinder : sphere, node)});
            }
        }
        rebuildTree(groups, leaves);
    }

    void rebuildTree(int groups, const std::vector<std::pair<int, Id>>& leaves) {
        test::TreeBuilder b(scene);
        std::vector<Id> inner;
        for (int g = 0; g < groups; ++g) {
            std::vector<Id> kids;
            for (const auto& [group, inst] : leaves) {
                if (group == g) kids.push_back(b.leaf(inst));
            }
            inner.push_back(b.inner(kids));
        }
        groupNodes = inner;
        tree = b.finish(b.inner(inner));
    }
};

std::vector<std::vector<std::uint8_t>> proxyBytes(const BakeResult& r) {
    std::vector<std::vector<std::uint8_t>> out;
    for (const NodeBake& n : r.nodes)
        out.push_back(encodeProxy(n.key, n.proxy));
    return out;
}

} // namespace

TEST(ProxyBaker, EveryInnerNodeGetsAProxyFromItsChildren) {
    Fixture f;
    BakeParams params;
    params.proxyRatio = 1.0; // every proxy is kept (the economy is tested below)
    const BakeResult r = bakeProxies(f.scene, f.tree, params);
    EXPECT_EQ(r.innerNodes, 5u);
    EXPECT_EQ(r.baked, 5u);
    EXPECT_EQ(r.reused, 0u);
    // A group's input: 2 spheres (2*48*23 = 2208 triangles each) + 2 cylinders (128 each).
    for (Id g : f.groupNodes) {
        EXPECT_EQ(r.nodes[g].inputTriangles, 2u * 2208u + 2u * 128u);
        EXPECT_FALSE(r.nodes[g].proxy.empty());
        EXPECT_LT(r.nodes[g].proxy.triangleCount(), r.nodes[g].inputTriangles);
    }
    // The root aggregates its children's proxies, not the original meshes again.
    std::size_t childProxies = 0;
    for (Id g : f.groupNodes)
        childProxies += r.nodes[g].proxy.triangleCount();
    EXPECT_EQ(r.nodes[f.tree.root].inputTriangles, childProxies);
    // Leaves get no proxy, but a budget and a switch distance like every node.
    const Id leaf = f.tree.nodes[f.groupNodes[0]].children[0];
    EXPECT_TRUE(r.nodes[leaf].proxy.empty());
    EXPECT_GT(r.nodes[leaf].switchDistance, 0.0);
    // Budget follows the node diameter: e = diameter / 300 at the defaults, rounded down to 10
    // significant bits (BakeFrame.h: at most 0.1 % smaller).
    const NodeBake& root = r.nodes[f.tree.root];
    EXPECT_LE(root.errorBudget, root.diameter / 300.0);
    EXPECT_GT(root.errorBudget, 0.999 * root.diameter / 300.0);
}

TEST(ProxyBaker, OutputIsBitIdenticalForAnyThreadCount) {
    for (ProxyMethod method : {ProxyMethod::Decimate, ProxyMethod::Sloppy, ProxyMethod::Remesh}) {
        // Remesh is the slow method: fewer groups keep the test short.
        Fixture f(method == ProxyMethod::Remesh ? 2 : 6);
        BakeParams params;
        params.method = method;
        params.threads = 1;
        const auto one = proxyBytes(bakeProxies(f.scene, f.tree, params));
        params.threads = 2;
        const auto two = proxyBytes(bakeProxies(f.scene, f.tree, params));
        params.threads = 4;
        const auto four = proxyBytes(bakeProxies(f.scene, f.tree, params));
        EXPECT_EQ(one, two) << toString(method);
        EXPECT_EQ(one, four) << toString(method);
    }
}

TEST(ProxyBaker, BoundedWorkingSetsMakeLargeNodesAloneWithTheSameProxies) {
    // 6 groups of 4,672 input triangles (28,032 below the root): a sixteenth is 1,752, so with
    // the floor lowered every node is made alone; the proxies are those of an unbounded bake.
    Fixture f(6);
    BakeParams params;
    params.threads = 2;
    const BakeResult free = bakeProxies(f.scene, f.tree, params);
    params.boundWorkingSets = true;
    params.inFlightFloor = 1;
    const BakeResult bounded = bakeProxies(f.scene, f.tree, params);
    EXPECT_EQ(proxyBytes(free), proxyBytes(bounded));
    std::size_t largest = 0;
    for (const NodeBake& n : bounded.nodes)
        largest = std::max(largest, n.inputTriangles);
    EXPECT_EQ(bounded.peakInFlightTriangles, largest);
    // A floor above the whole run leaves the bake unbounded: the six groups may go together.
    params.inFlightFloor = 1u << 20;
    const BakeResult roomy = bakeProxies(f.scene, f.tree, params);
    EXPECT_EQ(proxyBytes(free), proxyBytes(roomy));
    EXPECT_GE(roomy.peakInFlightTriangles, largest);
    EXPECT_LE(roomy.peakInFlightTriangles, 2u * 4672u); // two threads
}

TEST(ProxyBaker, RerunReusesEveryProxyAndMatchesTheBakedBytes) {
    Fixture f;
    test::TempDir dir;
    BakeParams params;
    params.cacheDir = dir.path();
    const BakeResult first = bakeProxies(f.scene, f.tree, params);
    EXPECT_EQ(first.baked, 5u);
    params.threads = 1; // the thread count is not part of any key
    const BakeResult second = bakeProxies(f.scene, f.tree, params);
    EXPECT_EQ(second.baked, 0u);
    EXPECT_EQ(second.reused, 5u);
    EXPECT_EQ(proxyBytes(first), proxyBytes(second));
}

TEST(ProxyBaker, CorruptOrTruncatedCacheEntriesAreRebakedNotTrusted) {
    Fixture f;
    test::TempDir dir;
    BakeParams params;
    params.cacheDir = dir.path();
    const BakeResult first = bakeProxies(f.scene, f.tree, params);
    std::vector<std::filesystem::path> entries;
    for (const auto& e : std::filesystem::directory_iterator(dir.path()))
        entries.push_back(e.path());
    std::sort(entries.begin(), entries.end());
    ASSERT_EQ(entries.size(), 5u);
    // One entry cut in half (a disk that filled up under another tool), one with a flipped
    // byte in its geometry (bit rot): both are misses, so exactly those two nodes rebake; their
    // parents' keys do not depend on the files, so the parents are still reused.
    std::filesystem::resize_file(entries[0], std::filesystem::file_size(entries[0]) / 2);
    {
        std::fstream io(entries[1], std::ios::in | std::ios::out | std::ios::binary);
        io.seekg(60);
        const char c = static_cast<char>(io.get() ^ 0x10);
        io.seekp(60);
        io.put(c);
    }
    const BakeResult second = bakeProxies(f.scene, f.tree, params);
    EXPECT_EQ(second.baked, 2u);
    EXPECT_EQ(second.reused, 3u);
    EXPECT_EQ(proxyBytes(first), proxyBytes(second));
    // The rebake healed both entries: a third run reuses everything.
    const BakeResult third = bakeProxies(f.scene, f.tree, params);
    EXPECT_EQ(third.baked, 0u);
    EXPECT_EQ(third.reused, 5u);
}

TEST(ProxyBaker, ParameterChangeRebakesExactlyWhatItAffects) {
    Fixture f;
    test::TempDir dir;
    BakeParams params;
    params.cacheDir = dir.path();
    bakeProxies(f.scene, f.tree, params);

    // The pixel tolerance changes every node's budget: everything rebakes...
    params.screen.pixelError = 2.0;
    BakeResult r = bakeProxies(f.scene, f.tree, params);
    EXPECT_EQ(r.baked, 5u);
    EXPECT_EQ(r.reused, 0u);
    // ...and going back finds the first bake still cached.
    params.screen.pixelError = 1.0;
    r = bakeProxies(f.scene, f.tree, params);
    EXPECT_EQ(r.baked, 0u);
    EXPECT_EQ(r.reused, 5u);

    // Another method shares no proxy with decimate.
    params.method = ProxyMethod::Sloppy;
    r = bakeProxies(f.scene, f.tree, params);
    EXPECT_EQ(r.baked, 5u);
    params.method = ProxyMethod::Decimate;

    // Moving one object (an edit inside group 0, keeping the node boxes) rebakes only its
    // group node and the root; the other three groups are reused.
    const Id inst = f.tree.nodes[f.tree.nodes[f.groupNodes[0]].children[1]].instance;
    Node& n = f.scene.nodes[f.scene.instances[inst].node];
    n.local = glm::rotate(n.local, 0.3, glm::dvec3(0, 1, 0));
    f.scene.updateWorldTransforms();
    r = bakeProxies(f.scene, f.tree, params);
    EXPECT_EQ(r.baked, 2u);
    EXPECT_EQ(r.reused, 3u);
    EXPECT_FALSE(r.nodes[f.groupNodes[0]].reused);
    EXPECT_FALSE(r.nodes[f.tree.root].reused);
}

TEST(ProxyBaker, CancelStopsBeforeTheNextNodeAndLeavesOnlyCompleteCacheFiles) {
    Fixture f(16); // 17 inner nodes
    test::TempDir dir;
    std::atomic<bool> cancel{false};
    std::atomic<std::size_t> finishedAtCancel{0}, lastDone{0};
    Progress progress;
    progress.cancel = &cancel;
    progress.report = [&](const ProgressInfo& info) {
        lastDone = std::max<std::size_t>(lastDone, info.done);
        if (info.done >= 3 && !cancel.exchange(true)) finishedAtCancel = info.done;
    };
    BakeParams params;
    params.cacheDir = dir.path();
    params.threads = 2;
    try {
        bakeProxies(f.scene, f.tree, params, progress);
        FAIL() << "expected Error(Cancelled)";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ErrorCode::Cancelled);
    }
    // Nodes already running finish (at most one per thread); none starts after the flag.
    EXPECT_LE(lastDone.load(), finishedAtCancel.load() + 2);
    EXPECT_LT(lastDone.load(), 17u);
    // The cache holds complete proxies only: each file decodes, no temporary file is left.
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
        ASSERT_EQ(entry.path().extension(), ".hlodproxy") << entry.path();
        ++files;
    }
    EXPECT_EQ(files, lastDone.load());
    // The keys of a complete bake (without the disk cache, so it writes nothing there).
    BakeParams uncached = params;
    uncached.cacheDir.clear();
    const BakeResult complete = bakeProxies(f.scene, f.tree, uncached);
    const ProxyCache cache(dir.path());
    std::size_t loadable = 0;
    for (Id id = 0; id < f.tree.nodes.size(); ++id)
        if (!f.tree.nodes[id].isLeaf()) loadable += cache.load(complete.nodes[id].key).has_value();
    EXPECT_EQ(loadable, files);
    // A rerun picks up where the cancelled one stopped.
    const BakeResult resumed = bakeProxies(f.scene, f.tree, params);
    EXPECT_EQ(resumed.reused, files);
    EXPECT_EQ(resumed.baked, 17u - files);
}

TEST(ProxyBaker, ProgressCountsEveryInnerNodeOnce) {
    Fixture f;
    std::mutex mutex;
    std::vector<std::uint64_t> done;
    Progress progress;
    progress.report = [&](const ProgressInfo& info) {
        std::lock_guard lock(mutex);
        EXPECT_EQ(info.stage, "bake");
        EXPECT_EQ(info.total, 5u);
        done.push_back(info.done);
    };
    bakeProxies(f.scene, f.tree, BakeParams{}, progress);
    std::sort(done.begin(), done.end());
    EXPECT_EQ(done, (std::vector<std::uint64_t>{0, 1, 2, 3, 4, 5}));
}

TEST(ProxyBaker, RejectsOutOfRangeParameters) {
    Fixture f(1);
    BakeParams params;
    params.screen.screenSize = 0.0;
    EXPECT_THROW(bakeProxies(f.scene, f.tree, params), Error);
    params = BakeParams{};
    params.threads = -1;
    EXPECT_THROW(bakeProxies(f.scene, f.tree, params), Error);
}

// Every kept proxy, the root's included (baked from its children's proxies, not from the
// meshes), lies within its node's budget of the original meshes under it and they within the
// budget of it: the children's own errors are taken off the parent's budget (DecimateProxy.h),
// so they never add up past it. Checked by brute force over a dense sampling, both ways, at a
// coarse screen size (S = 30 px) where every proxy simplifies a lot; rho = 1000 keeps them all.
TEST(ProxyBaker, EveryProxyStaysWithinItsBudgetOfTheOriginalMeshes) {
    Fixture f(2);
    BakeParams params;
    params.threads = 1;
    params.proxyRatio = 1000.0;
    params.atlas.enabled = false;
    params.screen.screenSize = 30.0;
    const BakeResult r = bakeProxies(f.scene, f.tree, params);
    int checked = 0;
    for (Id id = 0; id < f.tree.nodes.size(); ++id) {
        const ClusterNode& node = f.tree.nodes[id];
        const NodeBake& nb = r.nodes[id];
        if (node.isLeaf() || !nb.hasProxy || nb.proxy.empty()) continue;
        // The proxy and the original meshes under the node, in world space.
        std::vector<glm::vec3> proxy, originals;
        std::vector<std::uint32_t> proxyIdx, originalIdx;
        for (const glm::vec3& p : nb.proxy.positions)
            proxy.push_back(glm::vec3(nb.proxy.origin + glm::dvec3(p)));
        proxyIdx = nb.proxy.indices;
        std::vector<Id> stack{id};
        while (!stack.empty()) {
            const Id n = stack.back();
            stack.pop_back();
            for (Id c : f.tree.nodes[n].children)
                stack.push_back(c);
            if (!f.tree.nodes[n].isLeaf()) continue;
            const MeshInstance& inst = f.scene.instances[f.tree.nodes[n].instance];
            const Mesh& mesh = f.scene.meshes[inst.mesh];
            const glm::dmat4& world = f.scene.nodes[inst.node].world;
            const auto first = static_cast<std::uint32_t>(originals.size());
            for (const glm::vec3& p : mesh.positions)
                originals.push_back(glm::vec3(world * glm::dvec4(glm::dvec3(p), 1.0)));
            for (std::uint32_t i : mesh.indices)
                originalIdx.push_back(first + i);
        }
        const double e = nb.errorBudget * 1.0001; // float positions of metre-sized scenes
        EXPECT_LE(test::sampledDistance(proxy, proxyIdx, originals, originalIdx), e) << id;
        EXPECT_LE(test::sampledDistance(originals, originalIdx, proxy, proxyIdx), e) << id;
        EXPECT_EQ(nb.proxy.errorBound, static_cast<float>(nb.errorBudget));
        ++checked;
    }
    EXPECT_EQ(checked, 3); // two groups and the root
}
