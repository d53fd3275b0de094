// Leaf tiles keep their base colour textures: the image file is written once into the package
// (tiles/textures/), shared by every leaf that uses it, and referenced by a relative URI; a
// missing texture falls back to the material colour times the texture's mean.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <stb_image_write.h>
#include <tiny_gltf.h>

#include "TestUtil.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/export/Package.h"
#include "pipeline/scene/Primitives.h"

using namespace hlod;
namespace fs = std::filesystem;

namespace {

std::vector<char> readBytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

tinygltf::Model loadGlb(const fs::path& p) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&model, &err, &warn, p.string())) << err;
    return model;
}

// Three boxes with uvs: two use the textured material, one a material whose texture file does
// not exist.
Scene texturedScene(const fs::path& png) {
    Scene s;
    Material textured;
    textured.name = "painted";
    textured.baseColor = {0.5f, 0.5f, 0.5f, 1.0f};
    textured.hasTexture = true;
    textured.baseColorTexture = png;
    const Id tm = s.addMaterial(textured);
    Material missing = textured;
    missing.name = "lost";
    missing.baseColorTexture = png.parent_path() / "gone.png";
    missing.textureMean = {0.2f, 0.4f, 0.6f, 1.0f};
    const Id mm = s.addMaterial(missing);
    for (int i = 0; i < 3; ++i) {
        Mesh box = makeBox({1, 1, 1});
        box.uvs.assign(box.positions.size(), glm::vec2(0.5f));
        box.material = i < 2 ? tm : mm;
        const Id node = s.addNode("box" + std::to_string(i), 0,
                                  glm::translate(glm::dmat4(1.0), glm::dvec3(3.0 * i, 0, 0)));
        s.addInstance(s.addMesh(std::move(box)), node);
    }
    s.updateWorldTransforms();
    return s;
}

} // namespace

TEST(PackageTextures, OneSharedFilePerTextureReferencedByItsLeaves) {
    hlod::test::TempDir tmp;
    const fs::path png = tmp / "paint.png";
    const unsigned char pixels[12] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
    ASSERT_TRUE(stbi_write_png(png.string().c_str(), 2, 2, 3, pixels, 6));
    const Scene scene = texturedScene(png);
    const ClusterTree tree = buildClusterTree(scene, ClusterParams{});
    BakeParams params;
    params.threads = 1;
    const BakeResult bake = bakeProxies(scene, tree, params);
    PackageOptions options;
    options.compression = GlbCompression::None; // tinygltf reads it as it is
    writePackage(tmp / "pkg", scene, tree, bake, params, options);

    const fs::path tex = tmp / "pkg" / "tiles" / "textures";
    ASSERT_TRUE(fs::is_directory(tex));
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(tex))
        files.push_back(e.path());
    ASSERT_EQ(files.size(), 1u); // two leaves share one image; the missing one writes nothing
    EXPECT_EQ(readBytes(files[0]), readBytes(png)); // PNG copied byte for byte
    const std::string uri = "textures/" + files[0].filename().string();
    EXPECT_EQ(files[0].extension(), ".png");
    EXPECT_EQ(files[0].stem().string().size(), 16u); // named by its content hash

    // The leaves' looks over every tile: the textured one and the mean-colour fallback.
    std::set<std::pair<std::string, double>> looks;
    for (const auto& e : fs::directory_iterator(tmp / "pkg" / "tiles")) {
        if (e.path().extension() != ".glb") continue;
        const tinygltf::Model m = loadGlb(e.path());
        for (const tinygltf::Material& mat : m.materials) {
            const auto& pbr = mat.pbrMetallicRoughness;
            if (pbr.baseColorTexture.index < 0) {
                if (mat.name != "proxy") looks.insert({"", pbr.baseColorFactor[0]});
                continue;
            }
            const tinygltf::Image& image = m.images.at(
                static_cast<std::size_t>(m.textures.at(pbr.baseColorTexture.index).source));
            EXPECT_EQ(image.width, 2); // tinygltf found and decoded the shared file
            looks.insert({image.uri, pbr.baseColorFactor[0]});
        }
    }
    // The factor 0.5 multiplies the texture; without it, base 0.5 times the mean 0.2 (the
    // colour proxies use too).
    ASSERT_EQ(looks.size(), 2u);
    EXPECT_EQ(looks.begin()->first, "");
    EXPECT_NEAR(looks.begin()->second, 0.1, 1e-6);
    EXPECT_EQ(looks.rbegin()->first, uri);
    EXPECT_DOUBLE_EQ(looks.rbegin()->second, 0.5);
}
