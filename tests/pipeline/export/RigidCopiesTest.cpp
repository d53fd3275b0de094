// Rigid copies bake once (issue 26): clusters that are turned and translated copies of each
// other share one bake (BakeFrame.h) and one proxy file and one leaf file in the package, placed
// by tile transforms that carry the turn; what the package places lands where the originals are.
#include <gtest/gtest.h>

#include <fstream>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "TestUtil.h"
#include "TilesetRules.h"
#include "pipeline/export/Package.h"
#include "pipeline/export/PackageLayout.h"
#include "pipeline/proxy/ProxyBaker.h"
#include "pipeline/scene/Primitives.h"
#include "proxy/ProxyTestUtil.h"

using namespace hlod;
namespace fs = std::filesystem;

namespace {

// The turns of the four modules about +Y (radians): none of them a multiple of 90 degrees, so
// no turn is exact in floating point and every copy's placements differ in the last bits.
constexpr double kTurns[4] = {0.3, 1.9, -2.4, 4.0};

// Four modules 100 m apart, each a sphere and a cylinder 3 m beside it (720 and 192
// triangles: above the small-subtree limit), every module turned by kTurns about +Y. The tree
// is built by hand: the root over the four modules, each module over its two leaves.
struct Turned {
    Scene scene;
    ClusterTree tree;
    std::vector<Id> modules;
    BakeParams params;
    BakeResult bake;
    Turned() {
        const Id sphere = scene.addMesh(makeSphere(1.0f, 24, 16));
        const Id cylinder = scene.addMesh(makeCylinder(0.5f, 3.0f, 48));
        std::vector<std::pair<Id, Id>> instances;
        for (int m = 0; m < 4; ++m) {
            glm::dmat4 at = glm::translate(glm::dmat4(1.0), glm::dvec3(100.0 * m, 2.0, -5.0));
            at = glm::rotate(at, kTurns[m], glm::dvec3(0, 1, 0));
            const Id module = scene.addNode("module" + std::to_string(m), 0, at);
            const Id a = scene.addInstance(sphere, scene.addNode("a", module, glm::dmat4(1.0)));
            const Id c = scene.addInstance(
                cylinder,
                scene.addNode("c", module, glm::translate(glm::dmat4(1.0), {3.0, 0.5, 1.0})));
            instances.push_back({a, c});
        }
        scene.updateWorldTransforms();
        test::TreeBuilder b(scene);
        for (const auto& [a, c] : instances)
            modules.push_back(b.inner({b.leaf(a), b.leaf(c)}));
        tree = b.finish(b.inner(modules));
        // Spheres as the clusterer makes them, the same for turned copies (TreeBuilder's come
        // from world boxes, which a turn changes): a leaf's from its mesh's local box, a
        // module's enclosing its two leaves' spheres.
        for (ClusterNode& n : tree.nodes) {
            if (!n.isLeaf()) continue;
            const Aabb local = scene.meshes[scene.instances[n.instance].mesh].localBounds();
            n.sphere.center =
                glm::dvec3(scene.instanceTransform(n.instance) * glm::dvec4(local.center(), 1.0));
            n.sphere.radius = local.diagonal() * 0.5;
        }
        for (Id m : modules) {
            const Sphere& s0 = tree.nodes[tree.nodes[m].children[0]].sphere;
            const Sphere& s1 = tree.nodes[tree.nodes[m].children[1]].sphere;
            const double d = glm::length(s1.center - s0.center);
            tree.nodes[m].sphere.radius = (d + s0.radius + s1.radius) * 0.5;
            tree.nodes[m].sphere.center =
                s0.center +
                (s1.center - s0.center) * ((tree.nodes[m].sphere.radius - s0.radius) / d);
        }
        params.threads = 2;
        params.screen.screenSize = 300.0;
        params.proxyRatio = 1.0; // keep every proxy: the tree as built
        bake = bakeProxies(scene, tree, params);
    }
};

const Turned& turned() {
    static const Turned t;
    return t;
}

nlohmann::json readJson(const fs::path& p) {
    std::ifstream in(p);
    return nlohmann::json::parse(in);
}

// Module m's world rotation (the turn of its node).
glm::dmat3 turnOf(int m) {
    return glm::dmat3(glm::rotate(glm::dmat4(1.0), kTurns[m], glm::dvec3(0, 1, 0)));
}

// Every vertex some triangle of `s` uses, in world space, once per instance (a package keeps
// only the vertices its triangles use).
std::vector<glm::dvec3> worldVertices(const Scene& s) {
    std::vector<glm::dvec3> out;
    for (const MeshInstance& inst : s.instances) {
        const glm::dmat4& w = s.nodes[inst.node].world;
        const Mesh& mesh = s.meshes[inst.mesh];
        std::vector<char> used(mesh.positions.size(), 0);
        for (std::uint32_t i : mesh.indices)
            used[i] = 1;
        for (std::size_t v = 0; v < mesh.positions.size(); ++v)
            if (used[v])
                out.push_back(glm::dvec3(w * glm::dvec4(glm::dvec3(mesh.positions[v]), 1.0)));
    }
    return out;
}

} // namespace

TEST(RigidCopies, TurnedCopiesOfAClusterAreBakedOnce) {
    const Turned& t = turned();
    // One module and the root are baked; the other three modules are the first one's bake.
    EXPECT_EQ(t.bake.baked, 2u);
    EXPECT_EQ(t.bake.reused, 3u);
    const NodeBake& first = t.bake.nodes[t.modules[0]];
    ASSERT_FALSE(first.proxy.empty());
    for (int m = 1; m < 4; ++m) {
        const NodeBake& copy = t.bake.nodes[t.modules[m]];
        EXPECT_EQ(copy.key, first.key);
        EXPECT_EQ(copy.proxy.positions, first.proxy.positions); // bit for bit
    }
}

// The root's inputs are the four modules' proxies, one key turned four ways (CopyParts.h): the
// root simplifies the module proxy once in its own frame and places it four times, so its proxy
// is four blocks, each block the first moved by the motion between the modules; it lies within
// the root's budget of the original meshes both ways, the same for any thread count.
TEST(RigidCopies, ARootOverTurnedCopiesSimplifiesOneAndPlacesItFourTimes) {
    const Turned& t = turned();
    const NodeBake& root = t.bake.nodes[t.tree.root];
    ASSERT_FALSE(root.proxy.empty());
    const std::size_t vertices = root.proxy.positions.size(),
                      triangles = root.proxy.triangleCount();
    // Fewer triangles than the module proxies it replaces (simplified at the root's budget).
    EXPECT_LT(triangles, 4 * t.bake.nodes[t.modules[0]].proxy.triangleCount());
    ASSERT_EQ(vertices % 4, 0u);
    ASSERT_EQ(triangles % 4, 0u);
    const std::size_t block = vertices / 4;
    // Module m's first leaf (its frame's origin and turn) relative to module 0's.
    auto leafWorld = [&](int m) {
        return t.scene.instanceTransform(
            t.tree.nodes[t.tree.nodes[t.modules[static_cast<std::size_t>(m)]].children[0]]
                .instance);
    };
    const glm::dmat4 frame = root.frame.matrix();
    for (int m = 1; m < 4; ++m) {
        const glm::dmat4 motion = leafWorld(m) * glm::inverse(leafWorld(0));
        double worst = 0.0;
        for (std::size_t v = 0; v < block; ++v) {
            const glm::dvec4 p0 = frame * glm::dvec4(glm::dvec3(root.proxy.positions[v]), 1.0);
            const glm::dvec3 pm(frame *
                                glm::dvec4(glm::dvec3(root.proxy.positions[m * block + v]), 1.0));
            worst = std::max(worst, glm::length(glm::dvec3(motion * p0) - pm));
        }
        // Offsets sit on a grid of at most 1/1024 of the root's budget (BakeFrame.h): each
        // block is where the rigid motion puts the first, to within that rounding.
        EXPECT_LT(worst, root.errorBudget / 512.0) << "block " << m;
    }
    // Within the budget of the originals both ways (world space, brute force).
    std::vector<glm::vec3> proxy, originals;
    for (const glm::vec3& p : root.proxy.positions)
        proxy.push_back(glm::vec3(frame * glm::dvec4(glm::dvec3(p), 1.0)));
    std::vector<std::uint32_t> originalIdx;
    for (const MeshInstance& inst : t.scene.instances) {
        const Mesh& mesh = t.scene.meshes[inst.mesh];
        const auto first = static_cast<std::uint32_t>(originals.size());
        for (const glm::vec3& p : mesh.positions)
            originals.push_back(
                glm::vec3(t.scene.nodes[inst.node].world * glm::dvec4(glm::dvec3(p), 1.0)));
        for (std::uint32_t i : mesh.indices)
            originalIdx.push_back(first + i);
    }
    const double e = root.errorBudget * 1.0001; // float positions
    EXPECT_LE(test::sampledDistance(proxy, root.proxy.indices, originals, originalIdx), e);
    EXPECT_LE(test::sampledDistance(originals, originalIdx, proxy, root.proxy.indices), e);
    EXPECT_EQ(root.proxy.errorBound, static_cast<float>(root.errorBudget));
    // One thread bakes the same root proxy.
    BakeParams one = t.params;
    one.threads = 1;
    const BakeResult again = bakeProxies(t.scene, t.tree, one);
    EXPECT_EQ(again.nodes[t.tree.root].proxy.positions, root.proxy.positions);
    EXPECT_EQ(again.nodes[t.tree.root].proxy.indices, root.proxy.indices);
}

TEST(RigidCopies, EachCopysFrameCarriesItsTurnAndPlacesTheProxyWhereItsModuleIs) {
    const Turned& t = turned();
    const NodeBake& first = t.bake.nodes[t.modules[0]];
    for (int m = 0; m < 4; ++m) {
        const NodeBake& copy = t.bake.nodes[t.modules[m]];
        // The frame is the module's first leaf's (the sphere at the module's origin, BakeFrame.h),
        // so its rotation is the module's turn.
        const glm::dmat3 r = turnOf(m);
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(copy.frame.rotation[c][k], r[c][k], 1e-12);
        // The rigid motion taking module 0 onto module m takes module 0's placed proxy onto
        // module m's: the same proxy, placed by the two frames, differs only by that motion
        // (float positions of a few metres: 1e-5 is far above their rounding, far below the
        // error budget of a 5 m cluster at 300 px).
        const glm::dmat4 w0 = t.scene.instanceTransform(
            t.tree.nodes[t.tree.nodes[t.modules[0]].children[0]].instance);
        const glm::dmat4 wm = t.scene.instanceTransform(
            t.tree.nodes[t.tree.nodes[t.modules[m]].children[0]].instance);
        const glm::dmat4 motion = wm * glm::inverse(w0);
        double worst = 0.0;
        for (const glm::vec3& v : copy.proxy.positions) {
            const glm::dvec4 p0 = first.frame.matrix() * glm::dvec4(glm::dvec3(v), 1.0);
            const glm::dvec3 pm(copy.frame.matrix() * glm::dvec4(glm::dvec3(v), 1.0));
            worst = std::max(worst, glm::length(glm::dvec3(motion * p0) - pm));
        }
        EXPECT_LT(worst, 1e-5) << "module " << m;
        EXPECT_LT(worst, copy.errorBudget * 1e-3);
    }
}

TEST(RigidCopies, PackageStoresOneProxyAndOneLeafFilePlacedByTurnedTileTransforms) {
    test::TempDir tmp;
    const Turned& t = turned();
    PackageOptions plain;
    plain.compression = GlbCompression::None;
    writePackage(tmp / "pkg", t.scene, t.tree, t.bake, t.params, plain);
    const nlohmann::json m = readJson(tmp / "pkg" / "hlod.json");
    std::set<int> proxyFiles, leafFiles;
    for (Id n : t.modules) {
        proxyFiles.insert(m["tiles"][m["nodes"][n]["tile"].get<std::size_t>()]["file"].get<int>());
        for (Id c : t.tree.nodes[n].children)
            leafFiles.insert(
                m["tiles"][m["nodes"][c]["tile"].get<std::size_t>()]["file"].get<int>());
    }
    EXPECT_EQ(proxyFiles.size(), 1u); // one proxy file for the four module proxies
    EXPECT_EQ(leafFiles.size(), 1u);  // one leaf file for the four modules' leaves
    // The module tiles (children of the root tile) carry their module's turn, seen Z up: a turn
    // by a about glTF +Y is a turn by a about tiles' +Z (A R A^-1, A: (x, y, z) -> (x, -z, y)).
    const nlohmann::json ts = readJson(tmp / "pkg" / "tileset.json");
    const PackageLayout layout = planPackage(t.scene, t.tree, t.bake);
    ASSERT_EQ(ts["root"]["children"].size(), 4u);
    for (int k = 0; k < 4; ++k) {
        const nlohmann::json& tile = ts["root"]["children"][static_cast<std::size_t>(k)];
        const glm::dmat3 got(test::transformOf(tile));
        const int index = layout.tileOfNode[t.modules[static_cast<std::size_t>(k)]];
        ASSERT_GE(index, 0);
        EXPECT_EQ(layout.tiles[static_cast<std::size_t>(index)].parent, 0);
        const double a = kTurns[k];
        const glm::dmat3 want(std::cos(a), std::sin(a), 0, -std::sin(a), std::cos(a), 0, 0, 0, 1);
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r)
                EXPECT_NEAR(got[c][r], want[c][r], 1e-9) << "module " << k;
    }
    // The 3D Tiles rules hold with turned tiles (boxes as oriented boxes in the turned frames,
    // every content vertex inside its tile's box).
    test::TileCheck tc;
    tc.dir = tmp / "pkg";
    test::checkTileset(ts, tc);
    EXPECT_EQ(tc.tiles, layout.tiles.size());
}

TEST(RigidCopies, LeavesReadBackFromThePackageLandOnTheOriginals) {
    test::TempDir tmp;
    const Turned& t = turned();
    PackageOptions plain;
    plain.compression = GlbCompression::None;
    writePackage(tmp / "pkg", t.scene, t.tree, t.bake, t.params, plain);
    const Scene back = readPackageScene(readPackage(tmp / "pkg"));
    const std::vector<glm::dvec3> want = worldVertices(t.scene);
    const std::vector<glm::dvec3> got = worldVertices(back);
    ASSERT_FALSE(got.empty());
    // Every vertex read back has an original within 1e-5 m and vice versa (the leaves may be
    // merged and reordered, so nearest points, brute force over ~2,000 vertices). 1e-5: both
    // sides keep float coordinates of a few metres in a frame placed in double (rounding about
    // 5e-7), and the quantised placement moves a point by less than 1e-9 here (BakeFrame.h).
    const auto farthest = [](const std::vector<glm::dvec3>& from,
                             const std::vector<glm::dvec3>& to) {
        double worst = 0.0;
        for (const glm::dvec3& p : from) {
            double best = 1e300;
            for (const glm::dvec3& q : to)
                best = std::min(best, glm::length(p - q));
            worst = std::max(worst, best);
        }
        return worst;
    };
    EXPECT_LT(farthest(got, want), 1e-5);
    EXPECT_LT(farthest(want, got), 1e-5);
}
