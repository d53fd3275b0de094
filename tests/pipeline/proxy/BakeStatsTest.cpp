#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/proxy/BakeStats.h"
#include "pipeline/proxy/ProxyTestUtil.h"
#include "pipeline/scene/Primitives.h"

using namespace hlod;

TEST(BakeStats, HlodRowIsOriginalPlusOneMeshPerProxy) {
    Scene s;
    const Id box = s.addMesh(makeBox({1, 1, 1})); // 12 triangles, 24 vertices, no uvs
    const Id a = s.addInstance(box, s.addNode("a", 0));
    const Id b = s.addInstance(box, s.addNode("b", 0, glm::translate(glm::dmat4(1.0), {3, 0, 0})));
    test::TreeBuilder builder(s);
    const Id root = builder.inner({builder.leaf(a), builder.leaf(b)});
    const ClusterTree tree = builder.finish(root);
    BakeResult bake;
    bake.nodes.resize(tree.nodes.size());
    ProxyMesh& p = bake.nodes[root].proxy;
    p.positions.assign(8, glm::vec3(0.0f));
    p.colors.assign(8, glm::u8vec4(255));
    p.indices.assign(36, 0u);
    bake.proxyTriangles = 12;

    const GeometryStats original = originalStats(s);
    EXPECT_EQ(original.triangles, 24u);
    EXPECT_EQ(original.vertices, 48u);
    EXPECT_EQ(original.meshes, 2u);
    // 24 vertices * (12 position + 12 normal) + 36 indices * 2 bytes, per instance.
    EXPECT_EQ(original.bytes, 2u * (24u * 24u + 36u * 2u));

    const GeometryStats hlod = hlodStats(s, tree, bake, hlodVersionName(tree));
    EXPECT_EQ(hlod.version, "HLOD, sphere");
    EXPECT_EQ(hlod.triangles, 24u + 12u);
    EXPECT_EQ(hlod.vertices, 48u + 8u);
    EXPECT_EQ(hlod.meshes, 3u);
    // Proxy: 8 vertices * (12 + 12 + 4 colour bytes) + 36 * 2.
    EXPECT_EQ(hlod.bytes, original.bytes + 8u * 28u + 36u * 2u);

    const ProxyShare share = proxyShare(s, tree, bake);
    EXPECT_DOUBLE_EQ(share.allProxies, 0.5); // 12 of 24
    EXPECT_DOUBLE_EQ(share.rootProxy, 0.5);  // the only proxy is the root's
    EXPECT_DOUBLE_EQ(share.replaced, 0.5);   // it replaces both boxes
}
