// The package draws what the source authored (issue 28): leaf tiles keep each material's alpha
// mode and cut-off, double-sidedness and emission; leaves of different looks never share a
// primitive; a proxy over two-sided or emitting originals stays two-sided and emits.
// Checked on the written GLBs' materials (plain glTF, which tinygltf reads as it is).
#include <gtest/gtest.h>

#include <map>

#include <glm/gtc/matrix_transform.hpp>
#include <tiny_gltf.h>

#include "TestUtil.h"
#include "io/MaterialsScene.h"
#include "io/SgiTestFiles.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/export/Package.h"
#include "pipeline/io/Import.h"
#include "pipeline/scene/Primitives.h"

using namespace hlod;
namespace fs = std::filesystem;

namespace {

struct WrittenMaterial {
    tinygltf::Material material;
    std::string baseUri, emissiveUri; // the image files the textures name
    bool proxy = false;               // in a proxy tile's GLB
};

// Every material of every GLB of the package, with the URIs of its textures.
std::vector<WrittenMaterial> packageMaterials(const fs::path& pkg) {
    std::vector<WrittenMaterial> out;
    for (const auto& e : fs::directory_iterator(pkg / "tiles")) {
        if (e.path().extension() != ".glb") continue;
        tinygltf::TinyGLTF loader;
        tinygltf::Model m;
        std::string err, warn;
        EXPECT_TRUE(loader.LoadBinaryFromFile(&m, &err, &warn, e.path().string())) << err;
        auto uriOf = [&](int texture) {
            if (texture < 0) return std::string();
            const tinygltf::Image& image =
                m.images.at(static_cast<std::size_t>(m.textures.at(texture).source));
            return image.uri.empty() ? std::string("(embedded)") : image.uri;
        };
        const bool proxy = !m.meshes.empty() && m.meshes[0].name == "proxy";
        for (const tinygltf::Material& mat : m.materials)
            out.push_back({mat, uriOf(mat.pbrMetallicRoughness.baseColorTexture.index),
                           uriOf(mat.emissiveTexture.index), proxy});
    }
    return out;
}

// `proxyRatio`: the economy's rho (ProxyBaker.h); large keeps every proxy.
fs::path buildPackage(const Scene& scene, const fs::path& out, bool textures = true,
                      double proxyRatio = BakeParams{}.proxyRatio) {
    const ClusterTree tree = buildClusterTree(scene, ClusterParams{});
    BakeParams params;
    params.threads = 1;
    params.atlas.enabled = textures;
    params.proxyRatio = proxyRatio;
    const BakeResult bake = bakeProxies(scene, tree, params);
    PackageOptions options;
    options.compression = GlbCompression::None;
    writePackage(out, scene, tree, bake, params, options);
    return out;
}

// An 8x8 RGBA SGI texture: opaque grey left half, alpha 0 right half (a fence's cut-out).
std::string sgiCutOut() {
    std::vector<std::uint8_t> b = hlod::test::sgiHeader(0, 8, 8, 4);
    for (int channel = 0; channel < 4; ++channel)
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x)
                b.push_back(channel < 3 ? 128 : (x < 4 ? 255 : 0));
    return {b.begin(), b.end()};
}

// A TORCS-like track piece: material 0 `rgb 0.4 emis 0.4` as TORCS writes every material, one
// object of a one-sided quad (SURF 0x10) and a fence of a two-sided quad (SURF 0x30) under
// the cut-out texture, 4 m apart.
std::string torcsLikeTrack() {
    return "AC3Db\n"
           "MATERIAL \"\" rgb 0.4 0.4 0.4  amb 0.8 0.8 0.8  emis 0.4 0.4 0.4  spec 0.5 0.5 0.5"
           "  shi 50  trans 0\n"
           "OBJECT world\nkids 2\n"
           "OBJECT poly\nname \"road\"\ntexture \"fence.rgb\"\n"
           "numvert 4\n0 0 0\n4 0 0\n4 0 4\n0 0 4\nnumsurf 1\n"
           "SURF 0x10\nmat 0\nrefs 4\n0 0 0\n3 0 1\n2 1 1\n1 1 0\nkids 0\n"
           "OBJECT poly\nname \"fence\"\ntexture \"fence.rgb\"\n"
           "numvert 4\n8 0 0\n12 0 0\n12 2 0\n8 2 0\nnumsurf 1\n"
           "SURF 0x30\nmat 0\nrefs 4\n0 0 0\n1 1 0\n2 1 1\n3 0 1\nkids 0\n";
}

const WrittenMaterial* leafNamed(const std::vector<WrittenMaterial>& all, const std::string& name) {
    for (const WrittenMaterial& w : all)
        if (!w.proxy && w.material.name == name) return &w;
    return nullptr;
}

} // namespace

TEST(PackageMaterials, GltfLeavesKeepAlphaSidesAndEmissionAsAuthored) {
    hlod::test::TempDir tmp;
    const Scene scene = importScene({hlod::test::writeMaterialsScene(tmp.path())});
    const auto all = packageMaterials(buildPackage(scene, tmp / "pkg"));
    for (const std::string& name : hlod::test::materialsSceneNames())
        ASSERT_NE(leafNamed(all, name), nullptr) << name << " has no material of its own";
    // glTF's defaults are what tinygltf reads for properties left out: OPAQUE, 0.5, false.
    EXPECT_EQ(leafNamed(all, "Opaque")->material.alphaMode, "OPAQUE");
    EXPECT_EQ(leafNamed(all, "Blend")->material.alphaMode, "BLEND");
    EXPECT_EQ(leafNamed(all, "MaskLow")->material.alphaMode, "MASK");
    EXPECT_FLOAT_EQ(leafNamed(all, "MaskLow")->material.alphaCutoff, 0.25);
    EXPECT_FLOAT_EQ(leafNamed(all, "MaskDefault")->material.alphaCutoff, 0.5);
    EXPECT_FLOAT_EQ(leafNamed(all, "MaskHigh")->material.alphaCutoff, 0.75);
    EXPECT_EQ(leafNamed(all, "BlendFactor")->material.alphaMode, "BLEND");
    EXPECT_EQ(leafNamed(all, "BlendFactor")->material.pbrMetallicRoughness.baseColorFactor[3], 0.5);
    EXPECT_TRUE(leafNamed(all, "DoubleSided")->material.doubleSided);
    EXPECT_FALSE(leafNamed(all, "Opaque")->material.doubleSided);
    // The textured ones share the one image file, written once under textures/.
    const std::string alphaUri = leafNamed(all, "MaskLow")->baseUri;
    EXPECT_EQ(alphaUri.rfind("textures/", 0), 0u) << alphaUri;
    EXPECT_EQ(leafNamed(all, "Blend")->baseUri, alphaUri);
    const WrittenMaterial& glow = *leafNamed(all, "Emissive");
    EXPECT_EQ(glow.material.emissiveFactor, (std::vector<double>{1, 0.5, 0.25}));
    EXPECT_EQ(glow.emissiveUri.rfind("textures/", 0), 0u);
    EXPECT_NE(glow.emissiveUri, alphaUri); // glow.png, a file of its own
    // Strength 3 on white: factor 1 and the extension's strength 3.
    const WrittenMaterial& strong = *leafNamed(all, "EmissiveStrong");
    EXPECT_EQ(strong.material.emissiveFactor, (std::vector<double>{1, 1, 1}));
    EXPECT_EQ(strong.material.extensions.at("KHR_materials_emissive_strength")
                  .Get("emissiveStrength")
                  .GetNumberAsDouble(),
              3.0);
}

TEST(PackageMaterials, AcTrackLeavesAreCutOutTwoSidedAndEmitThroughTheirTexture) {
    hlod::test::TempDir tmp;
    hlod::test::writeFile(tmp / "fence.rgb", sgiCutOut());
    const Scene scene = importScene({hlod::test::writeFile(tmp / "track.acc", torcsLikeTrack())});
    const auto all = packageMaterials(buildPackage(scene, tmp / "pkg"));
    std::vector<const WrittenMaterial*> leaves;
    for (const WrittenMaterial& w : all)
        if (!w.proxy) leaves.push_back(&w);
    // One look each: the fence is two-sided, the road is not, so they never merge.
    ASSERT_EQ(leaves.size(), 2u);
    int twoSided = 0;
    for (const WrittenMaterial* w : leaves) {
        // The texture has texels of alpha 0: a cut-out (AC3D has no alpha mode of its own).
        EXPECT_EQ(w->material.alphaMode, "MASK");
        EXPECT_EQ(w->material.pbrMetallicRoughness.baseColorFactor,
                  (std::vector<double>{0.4, 0.4, 0.4, 1}));
        // emis 0.4 through the same texture: (lit + 0.4) x texture, as TORCS draws it.
        EXPECT_EQ(w->material.emissiveFactor, (std::vector<double>{0.4, 0.4, 0.4}));
        EXPECT_EQ(w->material.emissiveTexture.index,
                  w->material.pbrMetallicRoughness.baseColorTexture.index);
        EXPECT_FALSE(w->baseUri.empty());
        twoSided += w->material.doubleSided ? 1 : 0;
    }
    EXPECT_EQ(twoSided, 1);
}

TEST(PackageMaterials, ProxyOverTwoSidedEmittingOriginalsKeepsBoth) {
    // Twelve small two-sided, emitting boxes in a row: the tree gets inner nodes, and their
    // proxies stand for two-sided originals whose emission is 0.4 / 0.4 of their base colour.
    Scene s;
    Material m;
    m.name = "lit";
    m.baseColor = {0.4f, 0.4f, 0.4f, 1.0f};
    m.emissive = glm::vec3(0.4f);
    m.doubleSided = true;
    const Id lit = s.addMaterial(m);
    for (int i = 0; i < 12; ++i) {
        Mesh box = makeBox({1, 1, 1});
        box.material = lit;
        const Id node = s.addNode("box" + std::to_string(i), 0,
                                  glm::translate(glm::dmat4(1.0), glm::dvec3(1.5 * i, 0, 0)));
        s.addInstance(s.addMesh(std::move(box)), node);
    }
    s.updateWorldTransforms();
    hlod::test::TempDir tmp;
    // Without textures a proxy keeps vertex colours: its emission is the emitted colour itself.
    const auto all = packageMaterials(buildPackage(s, tmp / "pkg", false, 1000.0));
    int proxies = 0;
    for (const WrittenMaterial& w : all) {
        EXPECT_TRUE(w.material.doubleSided) << (w.proxy ? "proxy" : w.material.name);
        EXPECT_EQ(w.material.emissiveFactor, (std::vector<double>{0.4, 0.4, 0.4}));
        proxies += w.proxy ? 1 : 0;
    }
    EXPECT_GT(proxies, 0);
}
