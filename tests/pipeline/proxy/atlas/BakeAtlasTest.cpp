// The atlas bake on hand-built data: a textured quad pair merged into one proxy quad samples
// back to the right texels (checkerboard in, checkerboard out), a cut-out survives, no texel of
// a box's atlas or its mip levels shows a background colour, and the bytes do not depend on
// the thread count.
#include <gtest/gtest.h>

#include <tbb/task_arena.h>

#include "pipeline/proxy/atlas/BakeAtlas.h"

using namespace hlod;

namespace {

// 64x64 texels, 8x8 checks of 8x8 texels: check (x, y) white when x + y is even, black
// otherwise. Checks many texels wide keep their centres sharp under bilinear filtering.
RgbaImage checkerboard() {
    RgbaImage image(64, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            image.set(x, y,
                      (x / 8 + y / 8) % 2 == 0 ? glm::u8vec4(255) : glm::u8vec4(0, 0, 0, 255));
    return image;
}

// A unit quad in z = 0 at x in [x0, x0 + 1], y in [0, 1], uv = (x - x0, 1 - y).
void addQuad(SourceSurfaces& s, float x0, std::uint32_t material) {
    const auto base = static_cast<std::uint32_t>(s.positions.size());
    for (int k = 0; k < 4; ++k) {
        const float x = (k == 1 || k == 2) ? 1.0f : 0.0f, y = k >= 2 ? 1.0f : 0.0f;
        s.positions.push_back({x0 + x, y, 0.0f});
        s.uvs.push_back({x, 1.0f - y});
        s.colors.push_back(glm::vec4(1.0f));
    }
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u})
        s.indices.push_back(base + i);
    s.triangleMaterial.push_back(material);
    s.triangleMaterial.push_back(material);
}

// The proxy: one quad x in [0, w], y in [0, 1] lifted to z (within the budget), normals +Z.
ProxyMesh proxyQuad(float w, float z) {
    ProxyMesh p;
    p.positions = {{0, 0, z}, {w, 0, z}, {w, 1, z}, {0, 1, z}};
    p.normals.assign(4, glm::vec3(0, 0, 1));
    p.colors.assign(4, glm::u8vec4(128, 128, 128, 255));
    p.indices = {0, 1, 2, 0, 2, 3};
    return p;
}

// The atlas colour (linear) the baked proxy shows at (x, y) on its plane.
glm::vec4 atlasAt(const ProxyMesh& p, float x, float y) {
    for (std::size_t t = 0; t < p.indices.size(); t += 3) {
        const glm::vec3 a = p.positions[p.indices[t]], b = p.positions[p.indices[t + 1]],
                        c = p.positions[p.indices[t + 2]];
        const float d = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        const float w1 = ((x - a.x) * (c.y - a.y) - (y - a.y) * (c.x - a.x)) / d;
        const float w2 = ((b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x)) / d;
        if (w1 < -1e-4f || w2 < -1e-4f || w1 + w2 > 1.0001f) continue;
        const glm::vec2 uv = (1 - w1 - w2) * p.uvs[p.indices[t]] + w1 * p.uvs[p.indices[t + 1]] +
                             w2 * p.uvs[p.indices[t + 2]];
        return sampleBilinear(*p.atlas->image, uv);
    }
    ADD_FAILURE() << "(" << x << ", " << y << ") is not on the proxy";
    return glm::vec4(-1.0f);
}

} // namespace

TEST(BakeAtlas, TexturedQuadPairSamplesBackToItsCheckerboard) {
    const RgbaImage board = checkerboard();
    SourceSurfaces sources;
    sources.materials.push_back({glm::vec4(1.0f), &board, AlphaMode::Opaque, 0.5f});
    addQuad(sources, 0.0f, 0);
    addQuad(sources, 1.0f, 0);
    // A check is 1/8 m; 1/32 m texels give four texels per check. The proxy floats 1 cm above
    // the quads, inside the 5 cm budget.
    TextureMips mips;
    const ProxyMesh baked = bakeAtlas(proxyQuad(2.0f, 0.01f), sources, 0.05, 1.0 / 32.0, {}, mips);
    ASSERT_TRUE(baked.hasAtlas());
    EXPECT_FALSE(baked.atlas->mask);
    EXPECT_EQ(baked.atlas->mimeType, "image/jpeg");
    EXPECT_EQ(baked.triangleCount(), 2u);
    // Every check centre of both quads: white where (column + row) is even. Rows count from
    // the top (v = 1 - y). Tolerance: JPEG and the bilinear lookup, well apart from 0.5.
    int checked = 0;
    for (int row = 0; row < 8; ++row) {
        for (int col = 0; col < 16; ++col) {
            const float x = (col + 0.5f) / 8.0f, y = 1.0f - (row + 0.5f) / 8.0f;
            const float expected = ((col % 8) + row) % 2 == 0 ? 1.0f : 0.0f;
            const glm::vec4 c = atlasAt(baked, x, y);
            EXPECT_NEAR(c.r, expected, 0.1f) << "check " << col << ", " << row;
            EXPECT_NEAR(c.g, expected, 0.1f) << "check " << col << ", " << row;
            ++checked;
        }
    }
    EXPECT_EQ(checked, 128);
}

TEST(BakeAtlas, CutOutSurvivesAsAMaskedPngAtlas) {
    // 2x1 texture: left texel transparent, right opaque green; MASK at 0.5.
    RgbaImage leaf(2, 1, glm::u8vec4(0, 255, 0, 255));
    leaf.set(0, 0, glm::u8vec4(0, 255, 0, 0));
    SourceSurfaces sources;
    sources.materials.push_back({glm::vec4(1.0f), &leaf, AlphaMode::Mask, 0.5f});
    addQuad(sources, 0.0f, 0);
    TextureMips mips;
    const ProxyMesh baked = bakeAtlas(proxyQuad(1.0f, 0.0f), sources, 0.05, 1.0 / 32.0, {}, mips);
    ASSERT_TRUE(baked.hasAtlas());
    EXPECT_TRUE(baked.atlas->mask);
    EXPECT_EQ(baked.atlas->mimeType, "image/png");
    // The left quarter samples the transparent texel, the right quarter the green one.
    EXPECT_LT(atlasAt(baked, 0.1f, 0.5f).a, 0.5f);
    EXPECT_GT(atlasAt(baked, 0.9f, 0.5f).a, 0.5f);
    EXPECT_NEAR(atlasAt(baked, 0.9f, 0.5f).g, 1.0f, 0.02f);
}

TEST(BakeAtlas, BoxAtlasAndItsMipsShowNoBackgroundAtSeams) {
    // A unit box proxy (six charts) over a red unit box source: every texel of the atlas and
    // of every mip level down to 4 texels wide must be red, gutters included.
    const glm::vec3 corners[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                  {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    const std::uint32_t faces[36] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                     1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
    ProxyMesh box;
    box.positions.assign(corners, corners + 8);
    box.indices.assign(faces, faces + 36);
    box.colors.assign(8, glm::u8vec4(255, 0, 0, 255));
    SourceSurfaces sources;
    sources.materials.push_back({glm::vec4(1, 0, 0, 1), nullptr, AlphaMode::Opaque, 0.5f});
    sources.positions = box.positions;
    sources.indices = box.indices;
    sources.uvs.assign(8, glm::vec2(0.0f));
    sources.colors.assign(8, glm::vec4(1.0f));
    sources.triangleMaterial.assign(12, 0);
    TextureMips mips;
    AtlasOptions options;
    options.skipUntextured = false;
    const ProxyMesh baked = bakeAtlas(box, sources, 0.01, 1.0 / 16.0, options, mips);
    ASSERT_TRUE(baked.hasAtlas());
    RgbaImage level = *baked.atlas->image;
    int levels = 0;
    while (level.width >= 4) {
        for (int y = 0; y < level.height; ++y)
            for (int x = 0; x < level.width; ++x) {
                const glm::u8vec4 c = level.at(x, y);
                ASSERT_GE(c.r, 235) << "level " << levels << " texel " << x << ", " << y;
                ASSERT_LE(c.g, 20) << "level " << levels << " texel " << x << ", " << y;
                ASSERT_LE(c.b, 20) << "level " << levels << " texel " << x << ", " << y;
            }
        level = downsample(level);
        ++levels;
    }
    EXPECT_GE(levels, 3);
}

TEST(BakeAtlas, UntexturedSourcesKeepTheVertexColours) {
    SourceSurfaces sources;
    sources.materials.push_back({glm::vec4(1, 0, 0, 1), nullptr, AlphaMode::Opaque, 0.5f});
    addQuad(sources, 0.0f, 0);
    TextureMips mips;
    const ProxyMesh baked = bakeAtlas(proxyQuad(1.0f, 0.0f), sources, 0.05, 1.0 / 32.0, {}, mips);
    EXPECT_FALSE(baked.hasAtlas());
    EXPECT_EQ(baked.vertexCount(), 4u);
}

TEST(BakeAtlas, BytesDoNotDependOnTheThreadCount) {
    const RgbaImage board = checkerboard();
    SourceSurfaces sources;
    sources.materials.push_back({glm::vec4(1.0f), &board, AlphaMode::Opaque, 0.5f});
    addQuad(sources, 0.0f, 0);
    addQuad(sources, 1.0f, 0);
    auto bake = [&](int threads) {
        tbb::task_arena arena(threads);
        std::vector<std::uint8_t> bytes;
        arena.execute([&] {
            TextureMips mips;
            bytes = bakeAtlas(proxyQuad(2.0f, 0.01f), sources, 0.05, 1.0 / 40.0, {}, mips)
                        .atlas->encoded;
        });
        return bytes;
    };
    const std::vector<std::uint8_t> one = bake(1);
    EXPECT_FALSE(one.empty());
    EXPECT_EQ(one, bake(4));
}
