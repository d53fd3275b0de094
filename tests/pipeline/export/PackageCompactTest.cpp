// The compact package (issue 18): translated copies of a cluster share their files, decoded
// positions stay within the stated quantisation error of the plain package, a rebuild writes
// only the files that changed, and the size measured in memory is what lands on disk.
#include <gtest/gtest.h>

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
    // Placed on the globe: only the root transform in tileset.json changes.
    PackageOptions geo;
    geo.geo = parseGeoLocation("57.7,11.97,10");
    const PackageSummary moved = writePackage(tmp / "pkg", b.scene, b.tree, b.bake, b.params, geo);
    EXPECT_EQ(moved.written, 1u);
    EXPECT_EQ(moved.reused, first.files - 1);
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
