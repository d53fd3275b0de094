// The bake with atlases: a textured scene's kept proxies carry an atlas that survives the
// cache byte for byte, and the keys follow what the texels depend on (texture texels, the
// atlas switch) while a vertex-colour bake keeps its keys.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "ProxyTestUtil.h"
#include "TestUtil.h"
#include "pipeline/proxy/AtlasStep.h"
#include "pipeline/proxy/ProxyCache.h"

using namespace hlod;

namespace {

// Two textured unit quads side by side (x in [0, 2], y in [0, 1], z = 0) under one root, with
// an 8x8 checkerboard texture; a third instance far away keeps the root's children apart.
struct TexturedPair {
    Scene scene;
    ClusterTree tree;

    explicit TexturedPair(std::uint8_t white = 255) {
        auto image = std::make_shared<RgbaImage>(8, 8);
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x)
                image->set(x, y, (x + y) % 2 ? glm::u8vec4(0, 0, 0, 255)
                                             : glm::u8vec4(white, white, white, 255));
        Texture texture;
        texture.name = "board";
        texture.image = image;
        Material material;
        material.hasTexture = true;
        material.texture = scene.addTexture(texture);
        const Id mat = scene.addMaterial(material);
        Mesh quad;
        quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
        quad.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
        quad.indices = {0, 1, 2, 0, 2, 3};
        quad.material = mat;
        const Id mesh = scene.addMesh(quad);
        test::TreeBuilder builder(scene);
        std::vector<Id> leaves;
        for (double x : {0.0, 1.0}) {
            const Id node = scene.addNode("q", 0, glm::translate(glm::dmat4(1.0), glm::dvec3(x, 0, 0)));
            leaves.push_back(builder.leaf(scene.addInstance(mesh, node)));
        }
        tree = builder.finish(builder.inner(leaves));
    }
};

BakeParams keepEverything() {
    BakeParams params;
    params.proxyRatio = 1000.0; // every proxy kept, whatever its size
    params.threads = 1;
    return params;
}

} // namespace

TEST(AtlasStep, KeptProxyOfTexturedQuadsCarriesAnAtlasThroughTheCache) {
    TexturedPair pair;
    const BakeResult result = bakeProxies(pair.scene, pair.tree, keepEverything());
    const ProxyMesh& root = result.nodes[pair.tree.root].proxy;
    ASSERT_TRUE(root.hasAtlas());
    EXPECT_EQ(root.atlas->mimeType, "image/jpeg");
    const auto decoded = decodeProxy(7, encodeProxy(7, root));
    ASSERT_TRUE(decoded);
    ASSERT_TRUE(decoded->hasAtlas());
    EXPECT_EQ(decoded->uvs, root.uvs);
    EXPECT_EQ(decoded->atlas->encoded, root.atlas->encoded);
    EXPECT_EQ(decoded->atlas->image->pixels, root.atlas->image->pixels);
}

TEST(AtlasStep, SourcesOfANodeAreItsLeavesInItsFrame) {
    TexturedPair pair;
    BakeParams params = keepEverything();
    const BakeResult result = bakeProxies(pair.scene, pair.tree, params);
    const SourceSurfaces s = gatherNodeSources(pair.scene, pair.tree, pair.tree.root, result.nodes);
    EXPECT_EQ(s.triangleCount(), 4u);
    ASSERT_EQ(s.materials.size(), 1u);
    EXPECT_NE(s.materials[0].texture, nullptr);
    // The root's frame is its first input's (BakeFrame.h): the first quad's translation (0, 0, 0),
    // so the second quad starts at x = 1.
    EXPECT_FLOAT_EQ(s.positions[0].x, 0.0f);
    EXPECT_FLOAT_EQ(s.positions[4].x, 1.0f);
    EXPECT_FLOAT_EQ(s.positions[0].y, 0.0f);
}

TEST(AtlasStep, KeysFollowTheTexelsAndTheAtlasSwitch) {
    BakeParams params = keepEverything();
    const std::uint64_t base = bakeProxies(TexturedPair().scene, TexturedPair().tree, params)
                                   .nodes[TexturedPair().tree.root]
                                   .key;
    TexturedPair grey(200); // the white checks become grey: other texels, other key
    EXPECT_NE(bakeProxies(grey.scene, grey.tree, params).nodes[grey.tree.root].key, base);
    params.atlas.enabled = false;
    TexturedPair pair;
    const BakeResult off = bakeProxies(pair.scene, pair.tree, params);
    EXPECT_NE(off.nodes[pair.tree.root].key, base);
    EXPECT_FALSE(off.nodes[pair.tree.root].proxy.hasAtlas());
    // Without atlases the texels are not part of any key.
    EXPECT_EQ(bakeProxies(grey.scene, grey.tree, params).nodes[grey.tree.root].key,
              off.nodes[pair.tree.root].key);
}
