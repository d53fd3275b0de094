// The package on the sample scene: 3D Tiles rules checked one by one (version, refinement,
// geometric error decreasing to 0 at leaves, boxes containing their children, safe relative
// content URIs), the manifest round trip, and atomicity under cancellation and failure.
#include <gtest/gtest.h>

#include <fstream>

#include "TestUtil.h"
#include "TilesetRules.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/core/Error.h"
#include "pipeline/export/Package.h"
#include "pipeline/export/PackageLayout.h"
#include "pipeline/io/Import.h"
#include "pipeline/io/SampleScene.h"

using namespace hlod;
namespace fs = std::filesystem;

namespace {

struct Built {
    Scene scene = makeSampleScene();
    ClusterTree tree;
    BakeParams params;
    BakeResult bake;
    Built() {
        tree = buildClusterTree(scene, ClusterParams{});
        params.threads = 2;
        bake = bakeProxies(scene, tree, params);
    }
};

const Built& built() {
    static const Built b;
    return b;
}

nlohmann::json readJson(const fs::path& p) {
    std::ifstream in(p);
    return nlohmann::json::parse(in);
}

} // namespace

TEST(Package, TilesetFollowsThe3DTilesRules) {
    hlod::test::TempDir tmp;
    const Built& b = built();
    const PackageSummary s = writePackage(tmp / "pkg", b.scene, b.tree, b.bake, b.params, {});
    const nlohmann::json ts = readJson(tmp / "pkg" / "tileset.json");
    hlod::test::TileCheck tc;
    tc.dir = tmp / "pkg";
    hlod::test::checkTileset(ts, tc);
    const PackageLayout layout = planPackage(b.scene, b.tree, b.bake);
    EXPECT_EQ(tc.tiles, layout.tiles.size());
    EXPECT_EQ(s.tiles, layout.tiles.size());
    // Fewer tiles than nodes: the leaves under a node share its leaf-group tile.
    EXPECT_LT(s.tiles, b.tree.nodes.size());
    EXPECT_FALSE(ts["root"].contains("transform")); // local frame without --geo
}

TEST(Package, RootBoxHoldsTheSceneInZUp) {
    hlod::test::TempDir tmp;
    const Built& b = built();
    writePackage(tmp / "pkg", b.scene, b.tree, b.bake, b.params, {});
    const auto [mn, mx] = hlod::test::boxMinMax(
        readJson(tmp / "pkg" / "tileset.json")["root"]["boundingVolume"]["box"]);
    // Sample yard: x in [-60, 60], y (up) in [-0.5, 12], z in [-40, 40], and the proxies, which
    // may lie up to their budget outside it (a proxy within e of the originals both ways);
    // Z-up: (x, -z, y). The box is padded by the quantisation grid (leaves: 1/16384 of their
    // diameter, a few mm).
    Aabb all;
    all.expand(glm::dvec3(-60.0, -0.5, -40.0));
    all.expand(glm::dvec3(60.0, 12.0, 40.0));
    for (Id id = 0; id < b.tree.nodes.size(); ++id) {
        const NodeBake& nb = b.bake.nodes[id];
        if (b.tree.nodes[id].isLeaf() || nb.dissolved || nb.proxy.empty()) continue;
        for (const glm::vec3& p : nb.proxy.positions)
            all.expand(glm::dvec3(nb.frame.matrix() * glm::dvec4(glm::dvec3(p), 1.0)));
    }
    EXPECT_NEAR(mn.x, all.min.x, 0.01);
    EXPECT_NEAR(mx.x, all.max.x, 0.01);
    EXPECT_NEAR(mn.y, -all.max.z, 0.01);
    EXPECT_NEAR(mn.z, all.min.y, 0.01);
    EXPECT_NEAR(mx.z, all.max.y, 0.01);
    EXPECT_LE(mn.x, -60.0); // but never smaller than the scene
    EXPECT_GE(mx.z, 12.0);
}

TEST(Package, ReadsBackWithTheSameTreeAndCounts) {
    hlod::test::TempDir tmp;
    const Built& b = built();
    writePackage(tmp / "pkg", b.scene, b.tree, b.bake, b.params, {});
    ASSERT_TRUE(isPackageFolder(tmp / "pkg"));
    const PackageInfo info = readPackage(tmp / "pkg");
    ASSERT_EQ(info.tree.nodes.size(), b.tree.nodes.size());
    EXPECT_EQ(info.tree.root, b.tree.root);
    for (Id i = 0; i < b.tree.nodes.size(); ++i) {
        EXPECT_EQ(info.tree.nodes[i].children, b.tree.nodes[i].children);
        EXPECT_EQ(info.tree.nodes[i].instance, b.tree.nodes[i].instance);
    }
    // The proxies the package shows: those of nodes with a tile of their own.
    std::size_t shown = 0;
    for (const TilePlan& t : planPackage(b.scene, b.tree, b.bake).tiles)
        shown += t.node == kNoId ? 0 : b.bake.nodes[t.node].proxy.triangleCount();
    EXPECT_EQ(info.proxyTriangles, shown);
    const Scene back = readPackageScene(info);
    const SceneStats orig = b.scene.stats(), st = back.stats();
    EXPECT_EQ(st.triangles, orig.triangles);
    EXPECT_EQ(st.instances, orig.instances);
    const Aabb a = b.scene.worldBounds(), c = back.worldBounds();
    EXPECT_NEAR(glm::length(a.min - c.min), 0.0, 0.005); // quantised (1/16384 of a leaf)
    EXPECT_NEAR(glm::length(a.max - c.max), 0.0, 0.005);
}

TEST(Package, CancelledExportLeavesTheOldPackageUntouched) {
    hlod::test::TempDir tmp;
    const Built& b = built();
    writePackage(tmp / "pkg", b.scene, b.tree, b.bake, b.params, {});
    const std::string before = [&] {
        std::ifstream in(tmp / "pkg" / "hlod.json");
        return std::string(std::istreambuf_iterator<char>(in), {});
    }();
    std::atomic<bool> cancel{false};
    Progress p;
    p.cancel = &cancel;
    p.report = [&](const ProgressInfo& i) { cancel = i.done >= 10; }; // cancel mid-way
    PackageOptions o;
    o.inputs = {"other"};
    EXPECT_THROW(
        {
            try {
                writePackage(tmp / "pkg", b.scene, b.tree, b.bake, b.params, o, p);
            } catch (const Error& e) {
                EXPECT_EQ(e.code(), ErrorCode::Cancelled);
                throw;
            }
        },
        Error);
    std::ifstream in(tmp / "pkg" / "hlod.json");
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), before);
    // No temporary folder is left behind: only the package itself.
    std::size_t entries = 0;
    for (const auto& e : fs::directory_iterator(tmp.path()))
        entries += e.path() != tmp / "pkg";
    EXPECT_EQ(entries, 0u);
}

TEST(Package, AFileInTheWayIsAnErrorAndNothingIsWritten) {
    hlod::test::TempDir tmp;
    const Built& b = built();
    hlod::test::writeFile(tmp / "pkg", "not a folder");
    try {
        writePackage(tmp / "pkg", b.scene, b.tree, b.bake, b.params, {});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ErrorCode::Io);
        EXPECT_NE(std::string(e.what()).find("pkg"), std::string::npos);
    }
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(tmp.path()))
        ++entries;
    EXPECT_EQ(entries, 1u);
}

TEST(Package, GeoPlacementPutsTheRootOnTheEllipsoid) {
    hlod::test::TempDir tmp;
    const Built& b = built();
    PackageOptions o;
    o.geo = parseGeoLocation("57.7,11.97,10"); // Gothenburg
    writePackage(tmp / "pkg", b.scene, b.tree, b.bake, b.params, o);
    const auto t = readJson(tmp / "pkg" / "tileset.json")["root"]["transform"];
    ASSERT_EQ(t.size(), 16u);
    const glm::dvec3 p(t[12], t[13], t[14]);
    // WGS84 radius at 57.7° N lies between the polar (6356.8 km) and equatorial (6378.1 km).
    EXPECT_GT(glm::length(p), 6356752.0);
    EXPECT_LT(glm::length(p), 6378137.0 + 10.0);
    EXPECT_NEAR(glm::length(glm::dvec3(t[8], t[9], t[10])), 1.0, 1e-12); // unit up axis
    EXPECT_THROW(parseGeoLocation("91,0,0"), Error);
    EXPECT_THROW(parseGeoLocation("1,2"), Error);
}

TEST(Package, LocalPackageCarriesWhereItIsAndAViewThatFramesIt) {
    hlod::test::TempDir tmp;
    const Built& b = built();
    writePackage(tmp / "pkg", b.scene, b.tree, b.bake, b.params, {});
    const nlohmann::json h = readJson(tmp / "pkg" / "tileset.json")["extras"]["hlod"];
    // Sample yard: x in [-60, 60], y (up) in [-0.5, 12], z in [-40, 40]: centre (0, 5.75, 0),
    // radius half the diagonal sqrt(120^2 + 12.5^2 + 80^2) / 2 = 72.38; Z up: (x, -z, y).
    EXPECT_EQ(h["frame"], "local");
    EXPECT_EQ(h["units"], "metre");
    EXPECT_EQ(h["maximumScreenSpaceError"], 1.0);
    const glm::dvec3 c(h["boundingSphere"]["center"][0], h["boundingSphere"]["center"][1],
                       h["boundingSphere"]["center"][2]);
    EXPECT_NEAR(glm::distance(c, glm::dvec3(0.0, 0.0, 5.75)), 0.0, 1e-4);
    const double r = h["boundingSphere"]["radius"];
    EXPECT_NEAR(r, 72.38, 0.01);
    EXPECT_EQ(h["sceneUp"], nlohmann::json({0.0, 0.0, 1.0})); // glTF-like source: +Y, Z up here
    // The view: the automatic path's first camera, looking at the centre from r / sin(30°) =
    // 2r away (the sphere fills a 60° view), 35° above the horizon.
    auto v3 = [](const nlohmann::json& a) { return glm::dvec3(a[0], a[1], a[2]); };
    const glm::dvec3 eye = v3(h["view"]["eye"]), target = v3(h["view"]["target"]);
    EXPECT_NEAR(glm::distance(target, c), 0.0, 1e-3);
    EXPECT_NEAR(glm::distance(eye, target), 2.0 * r, 0.01 * r);
    EXPECT_NEAR((eye - target).z / glm::distance(eye, target), std::sin(glm::radians(35.0)), 0.01);
    EXPECT_EQ(h["view"]["fovYDegrees"], 60.0);
    EXPECT_FALSE(h.contains("localToWorld"));
    // hlod.json says the same in the package frame (Y up).
    const nlohmann::json m = readJson(tmp / "pkg" / "hlod.json")["placement"];
    EXPECT_EQ(m["frame"], "package");
    EXPECT_TRUE(m["geo"].is_null());
    EXPECT_NEAR(glm::distance(v3(m["boundingSphere"]["center"]), glm::dvec3(0.0, 5.75, 0.0)), 0.0,
                1e-4);
    EXPECT_EQ(m["sceneUp"], nlohmann::json({0.0, 1.0, 0.0}));
}

TEST(Package, GeoPackageSaysItsFrameIsEastNorthUp) {
    hlod::test::TempDir tmp;
    const Built& b = built();
    PackageOptions o;
    o.geo = parseGeoLocation("57.7,11.97,10");
    writePackage(tmp / "pkg", b.scene, b.tree, b.bake, b.params, o);
    const nlohmann::json ts = readJson(tmp / "pkg" / "tileset.json");
    const nlohmann::json h = ts["extras"]["hlod"];
    EXPECT_EQ(h["frame"], "east-north-up");
    EXPECT_EQ(h["geo"]["latitudeDeg"], 57.7);
    ASSERT_EQ(h["localToWorld"].size(), 16u);
    // The root transform is localToWorld times the root tile's own frame (a translation here):
    // the same rotation columns.
    for (int i = 0; i < 12; ++i)
        EXPECT_NEAR(h["localToWorld"][i].get<double>(), ts["root"]["transform"][i].get<double>(),
                    1e-12)
            << i;
}

TEST(Package, UnsafeContentPathIsRefusedOnRead) {
    hlod::test::TempDir tmp;
    const Built& b = built();
    writePackage(tmp / "pkg", b.scene, b.tree, b.bake, b.params, {});
    nlohmann::json m = readJson(tmp / "pkg" / "hlod.json");
    m["files"][0] = "../../etc/passwd";
    std::ofstream(tmp / "pkg" / "hlod.json") << m.dump();
    try {
        readPackage(tmp / "pkg");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ErrorCode::UnsafePath);
    }
}

TEST(Package, ImportSceneOpensAPackageAsItsOriginalMeshes) {
    // What the editor does with File > Open on a package folder.
    hlod::test::TempDir tmp;
    const Built& b = built();
    writePackage(tmp / "pkg", b.scene, b.tree, b.bake, b.params, {});
    const Scene back = importScene({tmp / "pkg"}, ImportOptions{});
    const auto src = b.scene.stats(), got = back.stats();
    EXPECT_EQ(got.triangles, src.triangles); // 10,020: the leaves, not the proxies
    EXPECT_EQ(got.instances, src.instances);
}
