// The compact package (issue 18): translated copies of a cluster share their files, decoded
// positions stay within the stated quantisation error of the plain package, a rebuild writes
// only the files that changed, and the size measured in memory is what lands on disk.
#include <gtest/gtest.h>

#include <functional>
#include <map>

#include <fstream>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "TestUtil.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/export/DiskUsage.h"
#include "pipeline/export/Package.h"
#include "pipeline/io/Import.h"
#include "pipeline/io/SampleScene.h"
#include "pipeline/scene/Primitives.h"

using namespace hlod;
namespace fs = std::filesystem;

namespace {

nlohmann::json readJson(const fs::path& p) {
    std::ifstream in(p);
    return nlohmann::json::parse(in);
}

// Eight modules 100 m apart, each two spheres and a cylinder (shared meshes, 720 triangles a
// sphere: well above the small-subtree limit), translated copies of each other.
Scene plant() {
    Scene s;
    const Id sphere = s.addMesh(makeSphere(1.0f, 24, 16));
    const Id cylinder = s.addMesh(makeCylinder(0.5f, 3.0f, 48));
    for (int m = 0; m < 8; ++m) {
        const Id module = s.addNode("module" + std::to_string(m), 0,
                                    glm::translate(glm::dmat4(1.0), glm::dvec3(100.0 * m, 0, 0)));
        const auto place = [&](Id mesh, glm::dvec3 at, const char* name) {
            s.addInstance(mesh, s.addNode(name, module, glm::translate(glm::dmat4(1.0), at)));
        };
        place(sphere, {0, 0, 0}, "a");
        place(sphere, {3, 0, 0}, "b");
        place(cylinder, {0, 0, 3}, "c");
    }
    s.updateWorldTransforms();
    return s;
}

struct Build {
    Scene scene;
    ClusterTree tree;
    BakeParams params;
    BakeResult bake;
    explicit Build(Scene sc, double screenSize = 300.0) : scene(std::move(sc)) {
        tree = buildClusterTree(scene, ClusterParams{});
        params.threads = 2;
        params.screen.screenSize = screenSize;
        params.proxyRatio = 1.0; // keep every proxy: the tree as clustered
        bake = bakeProxies(scene, tree, params);
    }
};

// The leaves below `n`.
std::size_t leavesBelow(const ClusterTree& t, Id n) {
    if (t.nodes[n].isLeaf()) return 1;
    std::size_t sum = 0;
    for (Id c : t.nodes[n].children)
        sum += leavesBelow(t, c);
    return sum;
}

} // namespace

TEST(PackageCompact, TranslatedCopiesOfAClusterShareTheirFiles) {
    test::TempDir tmp;
    const Build b(plant());
    const PackageSummary s = writePackage(tmp / "pkg", b.scene, b.tree, b.bake, b.params, {});
    const nlohmann::json m = readJson(tmp / "pkg" / "hlod.json");
    // Every module is a cluster of its three leaves (100 m apart, 3 m inside).
    std::set<int> moduleProxyFiles, moduleGroupFiles;
    std::size_t modules = 0;
    for (Id n = 0; n < b.tree.nodes.size(); ++n) {
        if (b.tree.nodes[n].isLeaf() || leavesBelow(b.tree, n) != 3) continue;
        ++modules;
        const auto& tile = m["tiles"][m["nodes"][n]["tile"].get<std::size_t>()];
        moduleProxyFiles.insert(tile["file"].get<int>());
        for (Id c : b.tree.nodes[n].children) {
            if (!b.tree.nodes[c].isLeaf()) continue;
            moduleGroupFiles.insert(
                m["tiles"][m["nodes"][c]["tile"].get<std::size_t>()]["file"].get<int>());
        }
    }
    EXPECT_EQ(modules, 8u);
    EXPECT_EQ(moduleProxyFiles.size(), 1u); // one proxy file for the eight module proxies
    EXPECT_EQ(moduleGroupFiles.size(), 1u); // one leaf file for the eight modules' leaves
    EXPECT_LT(s.files, s.tiles);
    // The sphere's two copies in a module are one mesh under two nodes.
    const Scene back = readPackageScene(readPackage(tmp / "pkg"));
    EXPECT_EQ(back.stats().instances, 24u);
    EXPECT_EQ(back.stats().triangles, b.scene.stats().triangles);
}

TEST(PackageCompact, DecodedPositionsAreWithinTheStatedErrorOfThePlainPackage) {
    test::TempDir tmp;
    const Build b(makeSampleScene());
    PackageOptions plain;
    plain.compression = GlbCompression::None;
    writePackage(tmp / "plain", b.scene, b.tree, b.bake, b.params, plain);
    writePackage(tmp / "packed", b.scene, b.tree, b.bake, b.params, {});
    const nlohmann::json mp = readJson(tmp / "plain" / "hlod.json");
    const nlohmann::json mq = readJson(tmp / "packed" / "hlod.json");
    ASSERT_EQ(mp["tiles"].size(), mq["tiles"].size());
    double worst = 0.0, stated = 0.0;
    std::size_t compared = 0;
    for (std::size_t t = 0; t < mq["tiles"].size(); ++t) {
        const int fp = mp["tiles"][t]["file"], fq = mq["tiles"][t]["file"];
        if (fq < 0) continue;
        const double error = mq["tiles"][t]["positionError"];
        EXPECT_GT(error, 0.0);
        EXPECT_EQ(mp["tiles"][t]["positionError"], 0.0);
        stated = std::max(stated, error);
        const Scene p = importGltf(tmp / "plain" / mp["files"][fp].get<std::string>(), {});
        const Scene q = importGltf(tmp / "packed" / mq["files"][fq].get<std::string>(), {});
        ASSERT_EQ(p.instances.size(), q.instances.size());
        for (std::size_t i = 0; i < q.instances.size(); ++i) {
            const Mesh& mp_ = p.meshes[p.instances[i].mesh];
            const Mesh& mq_ = q.meshes[q.instances[i].mesh];
            ASSERT_EQ(mp_.positions.size(), mq_.positions.size()); // the same vertices, in order
            const glm::dmat4& wp = p.nodes[p.instances[i].node].world;
            const glm::dmat4& wq = q.nodes[q.instances[i].node].world;
            for (std::size_t v = 0; v < mq_.positions.size(); ++v) {
                const glm::dvec3 a(wp * glm::dvec4(glm::dvec3(mp_.positions[v]), 1.0));
                const glm::dvec3 c(wq * glm::dvec4(glm::dvec3(mq_.positions[v]), 1.0));
                for (int k = 0; k < 3; ++k) {
                    const double d = std::abs(a[k] - c[k]);
                    worst = std::max(worst, d / error);
                    // float rounding of the plain package's own coordinates on top
                    EXPECT_LE(d, error + 1e-6 * (1.0 + std::abs(a[k])));
                }
                ++compared;
            }
        }
    }
    EXPECT_GT(compared, 10000u);
    EXPECT_GT(worst, 0.2);   // the stated bound is tight: quantisation does move vertices
    EXPECT_LE(stated, 0.01); // and small: a proxy's budget / 128 at most, here centimetres
}

TEST(PackageCompact, ARebuildWritesOnlyTheFilesThatChanged) {
    test::TempDir tmp;
    const Build b(plant());
    const PackageSummary first = writePackage(tmp / "pkg", b.scene, b.tree, b.bake, b.params, {});
    EXPECT_EQ(first.written, first.files);
    EXPECT_EQ(first.reused, 0u);
    // The same build again: every file is the old one (hard links, nothing written).
    const PackageSummary same = writePackage(tmp / "pkg", b.scene, b.tree, b.bake, b.params, {});
    EXPECT_EQ(same.written, 0u);
    EXPECT_EQ(same.reused, first.files);
    // Placed on the globe: only tileset.json (root transform, extras.hlod) and hlod.json
    // (placement.geo) change.
    PackageOptions geo;
    geo.geo = parseGeoLocation("57.7,11.97,10");
    const PackageSummary moved = writePackage(tmp / "pkg", b.scene, b.tree, b.bake, b.params, geo);
    EXPECT_EQ(moved.written, 2u);
    EXPECT_EQ(moved.reused, first.files - 2);
    // Another screen size: new proxies, but the leaves' files stay as they were.
    const Build other(plant(), 150.0);
    const PackageSummary rebaked =
        writePackage(tmp / "pkg", other.scene, other.tree, other.bake, other.params, geo);
    EXPECT_GT(rebaked.written, 0u);
    EXPECT_GT(rebaked.reused, 0u);
}

TEST(PackageCompact, MeasuredInMemoryIsWhatLandsOnDisk) {
    test::TempDir tmp;
    const Build b(makeSampleScene());
    const PackageSummary written = writePackage(tmp / "pkg", b.scene, b.tree, b.bake, b.params, {});
    const PackageSummary measured =
        measurePackage(b.scene, b.tree, b.bake, b.params, {}, blockSizeAt(tmp.path()));
    EXPECT_EQ(measured.files, written.files);
    EXPECT_EQ(measured.bytes, written.bytes);
    EXPECT_EQ(measured.bytesOnDisk, written.bytesOnDisk);
    EXPECT_EQ(measured.tiles, written.tiles);
    EXPECT_GE(written.bytesOnDisk, written.bytes); // whole blocks
}

TEST(PackageCompact, SourceOnDiskCountsTheSceneFileAndItsTextures) {
    test::TempDir tmp;
    test::writeFile(tmp / "scene.glb", std::string(5000, 'x'));
    test::writeFile(tmp / "paint.png", std::string(100, 'p'));
    Scene s;
    s.sourceFiles = {tmp / "scene.glb", "sample:plant"}; // not a file: counts nothing
    Material m;
    m.baseColorTexture = tmp / "paint.png";
    s.addMaterial(m);
    s.addMaterial(m); // the same file twice counts once
    const DiskFootprint f = sourceFootprint(s);
    EXPECT_EQ(f.files, 2u);
    EXPECT_EQ(f.bytes, 5100u);
    EXPECT_GE(f.bytesOnDisk, f.bytes); // 5000 bytes take two 4 KiB blocks on ext4
}

TEST(PackageCompact, ASceneOfOneMeshIsOneLeafTile) {
    // The tree is a single leaf: the root tile is its leaf group, error 0, no children.
    Scene s;
    s.addInstance(s.addMesh(makeSphere(1.0f, 24, 16)), s.addNode("ball", 0));
    s.updateWorldTransforms();
    test::TempDir tmp;
    const Build b(std::move(s));
    ASSERT_TRUE(b.tree.nodes[b.tree.root].isLeaf());
    const PackageSummary sum = writePackage(tmp / "pkg", b.scene, b.tree, b.bake, b.params, {});
    EXPECT_EQ(sum.tiles, 1u);
    EXPECT_EQ(sum.files, 3u); // tileset.json, hlod.json, one GLB
    const nlohmann::json ts = readJson(tmp / "pkg" / "tileset.json");
    EXPECT_EQ(ts["root"]["geometricError"], 0.0);
    EXPECT_FALSE(ts["root"].contains("children"));
    // 24 segments x 16 rings: 24 x 14 quads of two triangles plus two fans of 24 at the poles.
    EXPECT_EQ(readPackageScene(readPackage(tmp / "pkg")).stats().triangles, 720u);
}

TEST(PackageCompact, SmallSubtreesJoinTheirParentsLeafGroup) {
    // A fence: 64 posts of 12 triangles in a row, and two big spheres at its ends. Clusters of
    // a few posts hold far fewer than kSmallSubtreeTriangles: they get no tiles of their own;
    // their leaves join the leaf group of the nearest node that has a tile, merged with their
    // siblings' into one primitive per look (one draw for the whole group, not one per small
    // subtree).
    Scene s;
    const Id post = s.addMesh(makeBox({0.1f, 1.0f, 0.1f}));
    const Id ball = s.addMesh(makeSphere(2.0f, 48, 32));
    for (int i = 0; i < 64; ++i)
        s.addInstance(post, s.addNode("post" + std::to_string(i), 0,
                                      glm::translate(glm::dmat4(1.0), glm::dvec3(i * 1.5, 0, 0))));
    s.addInstance(ball,
                  s.addNode("west", 0, glm::translate(glm::dmat4(1.0), glm::dvec3(-5, 0, 0))));
    s.addInstance(ball,
                  s.addNode("east", 0, glm::translate(glm::dmat4(1.0), glm::dvec3(100, 0, 0))));
    s.updateWorldTransforms();
    const Build b(std::move(s));
    const PackageLayout layout = planPackage(b.scene, b.tree, b.bake);
    // Original triangles below each node.
    std::vector<std::size_t> tris(b.tree.nodes.size(), 0);
    std::vector<Id> post_order;
    std::vector<Id> stack{b.tree.root};
    while (!stack.empty()) {
        const Id n = stack.back();
        stack.pop_back();
        post_order.push_back(n);
        for (Id c : b.tree.nodes[n].children)
            stack.push_back(c);
    }
    for (auto it = post_order.rbegin(); it != post_order.rend(); ++it) {
        const ClusterNode& node = b.tree.nodes[*it];
        if (node.isLeaf()) {
            tris[*it] = b.scene.meshes[b.scene.instances[node.instance].mesh].triangleCount();
            continue;
        }
        for (Id c : node.children)
            tris[*it] += tris[c];
    }
    std::size_t folded = 0;
    for (Id n = 0; n < b.tree.nodes.size(); ++n) {
        const ClusterNode& node = b.tree.nodes[n];
        if (node.isLeaf() || n == b.tree.root || tris[n] > kSmallSubtreeTriangles) continue;
        ++folded;
        // Shown by a leaf group (no tile of its own) under a tile of an ancestor.
        const int t = layout.tileOfNode[n];
        ASSERT_GE(t, 0);
        EXPECT_EQ(layout.tiles[static_cast<std::size_t>(t)].node, kNoId);
        const int parentTile = layout.tiles[static_cast<std::size_t>(t)].parent;
        ASSERT_GE(parentTile, 0);
        const Id owner = layout.tiles[static_cast<std::size_t>(parentTile)].node;
        EXPECT_GT(tris[owner], kSmallSubtreeTriangles);
    }
    EXPECT_GE(folded, 4u) << "the fence should make several small clusters";
    std::size_t postsSeen = 0;
    for (const TilePlan& t : layout.tiles) {
        EXPECT_TRUE(t.node == kNoId || t.node == b.tree.root ||
                    tris[t.node] > kSmallSubtreeTriangles);
        if (t.node != kNoId || t.content < 0) continue;
        const ContentPlan& c = layout.contents[static_cast<std::size_t>(t.content)];
        for (const LeafSlot& slot : c.leaves)
            if (b.scene.instances[slot.instance].mesh == post) {
                ++postsSeen;
                EXPECT_TRUE(slot.merged); // 12 triangles: merged, not instanced
            }
    }
    EXPECT_EQ(postsSeen, 64u); // every post in exactly one group
    // The posts under a node share one content, or, where they spread wider than
    // kGroupSpreadShare of the node, a few parts in space of at least kMinPartTriangles each
    // (PackageLayout.h): never one content per small subtree.
    std::map<int, std::vector<std::size_t>> partsOf; // parent tile -> triangles of each part
    std::size_t groupsWithPosts = 0;
    for (const TilePlan& t : layout.tiles) {
        if (t.node != kNoId || t.content < 0) continue;
        const ContentPlan& c = layout.contents[static_cast<std::size_t>(t.content)];
        if (std::any_of(c.leaves.begin(), c.leaves.end(), [&](const LeafSlot& leaf) {
                return b.scene.instances[leaf.instance].mesh == post;
            })) {
            ++groupsWithPosts;
            std::size_t triangles = 0;
            for (const LeafSlot& slot : c.leaves)
                triangles += b.scene.meshes[b.scene.instances[slot.instance].mesh].triangleCount();
            partsOf[t.parent].push_back(triangles);
        }
    }
    for (const auto& [parent, parts] : partsOf) {
        if (parts.size() > 1) {
            for (std::size_t triangles : parts)
                EXPECT_GE(triangles, kMinPartTriangles);
        }
    }
    EXPECT_LT(groupsWithPosts, folded);
}

TEST(PackageCompact, SubtreesLaidOutApartSpliceIntoTheWholeLayoutUnchanged) {
    // A distributed bake's shards lay out their subtrees (planSubtree) and the final step
    // splices them in (planPackage with LayoutBlocks) without the meshes below them: the layout
    // must be the one of the whole tree, tile for tile.
    const Build b(makeSampleScene());
    const PackageLayout whole = planPackage(b.scene, b.tree, b.bake);
    // Blocks: every inner grandchild of the root (the root's children stay laid out here).
    LayoutBlocks blocks;
    std::vector<PackageLayout> parts;
    std::vector<Id> roots;
    const std::function<std::size_t(Id)> triangles = [&](Id n) -> std::size_t {
        const ClusterNode& node = b.tree.nodes[n];
        if (node.isLeaf())
            return b.scene.meshes[b.scene.instances[node.instance].mesh].triangleCount();
        std::size_t sum = 0;
        for (Id c : node.children)
            sum += triangles(c);
        return sum;
    };
    for (Id c : b.tree.nodes[b.tree.root].children)
        if (triangles(c) > kSmallSubtreeTriangles)
            for (Id g : b.tree.nodes[c].children)
                if (!b.tree.nodes[g].isLeaf() && triangles(g) > kSmallSubtreeTriangles)
                    roots.push_back(g);
    ASSERT_GE(roots.size(), 2u);
    parts.reserve(roots.size());
    for (Id r : roots)
        parts.push_back(planSubtree(b.scene, b.tree, b.bake, r));
    for (std::size_t i = 0; i < roots.size(); ++i)
        blocks.byRoot[roots[i]] = &parts[i];
    // The meshes below the blocks are not read: emptied.
    Scene hollow = b.scene;
    for (const Mesh& m : b.scene.meshes)
        blocks.meshTriangles.push_back(m.triangleCount());
    std::vector<char> above(b.scene.meshes.size(), 0);
    for (Id n = 0; n < b.tree.nodes.size(); ++n) {
        const ClusterNode& node = b.tree.nodes[n];
        if (!node.isLeaf()) continue;
        bool inBlock = false;
        for (Id a = node.parent; a != kNoId; a = b.tree.nodes[a].parent)
            inBlock = inBlock || blocks.byRoot.count(a) > 0;
        if (!inBlock) above[b.scene.instances[node.instance].mesh] = 1;
    }
    for (std::size_t m = 0; m < hollow.meshes.size(); ++m)
        if (!above[m]) hollow.meshes[m] = Mesh{};
    const PackageLayout spliced = planPackage(hollow, b.tree, b.bake, blocks);

    ASSERT_EQ(spliced.tiles.size(), whole.tiles.size());
    ASSERT_EQ(spliced.contents.size(), whole.contents.size());
    EXPECT_EQ(spliced.tileOfNode, whole.tileOfNode);
    std::size_t fromBlocks = 0;
    for (std::size_t i = 0; i < whole.tiles.size(); ++i) {
        const TilePlan &a = spliced.tiles[i], &w = whole.tiles[i];
        EXPECT_EQ(a.node, w.node) << "tile " << i;
        EXPECT_EQ(a.parent, w.parent) << "tile " << i;
        EXPECT_EQ(a.children, w.children) << "tile " << i;
        EXPECT_EQ(a.content, w.content) << "tile " << i;
        EXPECT_EQ(a.frame, w.frame) << "tile " << i;
        EXPECT_EQ(a.geometricError, w.geometricError) << "tile " << i;
        EXPECT_EQ(a.worldBox.min, w.worldBox.min) << "tile " << i;
        EXPECT_EQ(a.worldBox.max, w.worldBox.max) << "tile " << i;
    }
    for (std::size_t i = 0; i < whole.contents.size(); ++i) {
        EXPECT_EQ(spliced.contents[i].node, whole.contents[i].node) << "content " << i;
        ASSERT_EQ(spliced.contents[i].leaves.size(), whole.contents[i].leaves.size());
        for (std::size_t s = 0; s < whole.contents[i].leaves.size(); ++s)
            EXPECT_EQ(spliced.contents[i].leaves[s].leaf, whole.contents[i].leaves[s].leaf);
        fromBlocks += spliced.sources[i].block != kNoId ? 1 : 0;
    }
    EXPECT_GT(fromBlocks, 0u);
    EXPECT_LT(fromBlocks, whole.contents.size());
}
