// Leaf tiles keep their base colour textures: the image file is written once into the package
// (tiles/textures/), shared by every leaf that uses it, and referenced by a relative URI; a
// missing texture falls back to the material colour times the texture's mean.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

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
    writePackage(tmp / "pkg", scene, tree, bake, params, {});

    const fs::path tex = tmp / "pkg" / "tiles" / "textures";
    ASSERT_TRUE(fs::is_directory(tex));
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(tex))
        ++files;
    EXPECT_EQ(files, 1u); // two leaves share one image; the missing one writes nothing
    EXPECT_EQ(readBytes(tex / "0.png"), readBytes(png)); // PNG copied byte for byte

    int withUri = 0, withMean = 0;
    for (Id i = 0; i < tree.nodes.size(); ++i) {
        if (!tree.nodes[i].isLeaf()) continue;
        const tinygltf::Model m = loadGlb(tmp / "pkg" / "tiles" / (std::to_string(i) + ".glb"));
        const auto& pbr = m.materials.at(0).pbrMetallicRoughness;
        if (!m.images.empty()) {
            ++withUri;
            EXPECT_EQ(m.images[0].uri, "textures/0.png");
            EXPECT_EQ(m.images[0].width, 2); // tinygltf found and decoded the shared file
            EXPECT_EQ(pbr.baseColorTexture.index, 0);
            EXPECT_DOUBLE_EQ(pbr.baseColorFactor[0], 0.5); // the factor multiplies the texture
        } else {
            ++withMean;
            EXPECT_EQ(pbr.baseColorTexture.index, -1);
            // base 0.5 times the mean 0.2: the colour proxies use too
            EXPECT_NEAR(pbr.baseColorFactor[0], 0.1, 1e-6);
        }
    }
    EXPECT_EQ(withUri, 2);
    EXPECT_EQ(withMean, 1);
}
