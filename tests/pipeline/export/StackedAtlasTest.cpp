// Leaf textures stacked in V into shared pages (StackedAtlas.h): which textures go in, where
// their texels land, how uvs move, and that a leaf group of two textures then writes one
// primitive instead of two.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <tiny_gltf.h>

#include "TestUtil.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/export/Package.h"
#include "pipeline/export/StackedAtlas.h"
#include "pipeline/scene/Primitives.h"

using namespace hlod;
namespace fs = std::filesystem;

namespace {

// A texture whose texel (x, y) is (x, y, id, 255): every texel says where it came from.
Texture codedTexture(int w, int h, int id, const std::string& file) {
    auto img = std::make_shared<RgbaImage>(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            img->set(x, y, glm::u8vec4(x, y, id, 255));
    Texture t;
    t.name = file;
    t.file = "/textures/" + file; // only its name matters (JPEG or not): pixels are decoded
    t.image = std::move(img);
    return t;
}

Id texturedMaterial(Scene& s, Id texture, AlphaMode alpha = AlphaMode::Opaque) {
    Material m;
    m.name = s.textures[texture].name;
    m.hasTexture = true;
    m.texture = texture;
    m.baseColorTexture = s.textures[texture].file;
    m.textureMean = meanLinearColor(*s.textures[texture].image); // as the importers set it
    m.alphaMode = alpha;
    return s.addMaterial(m);
}

// One triangle with the given uvs.
Mesh triangle(std::vector<glm::vec2> uvs, Id material) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.normals.assign(3, {0, 0, 1});
    m.uvs = std::move(uvs);
    m.indices = {0, 1, 2};
    m.material = material;
    return m;
}

void place(Scene& s, Mesh mesh, glm::dvec3 at) {
    const Id node = s.addNode(mesh.name, 0, glm::translate(glm::dmat4(1.0), at));
    s.addInstance(s.addMesh(std::move(mesh)), node);
}

} // namespace

TEST(StackedAtlas, TrianglesMoveByWholePeriodsIntoTheirBand) {
    // v in [2.25, 2.75] is v in [0.25, 0.75] of the repeating texture; u repeats in the page
    // as in the texture, scaled by the repeat.
    const Mesh m = triangle({{3.5f, 2.25f}, {3.75f, 2.25f}, {3.5f, 2.75f}}, 0);
    AtlasBand band;
    band.page = 0;
    band.top = 100; // rows 100..163 of a 400-row page
    band.rows = 64;
    band.repeat = 2; // a 128-wide texture in a 256-wide page
    const std::optional<StackedUvs> s = stackUvs(m, band, 400);
    ASSERT_TRUE(s);
    ASSERT_EQ(s->uvs.size(), 3u);
    // u' = u / 2; v' = (100 + (v - 2) * 64) / 400.
    EXPECT_FLOAT_EQ(s->uvs[0].x, 1.75f);
    EXPECT_FLOAT_EQ(s->uvs[1].x, 1.875f);
    EXPECT_FLOAT_EQ(s->uvs[0].y, (100.0f + 16.0f) / 400.0f);
    EXPECT_FLOAT_EQ(s->uvs[2].y, (100.0f + 48.0f) / 400.0f);
    EXPECT_EQ(s->indices, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(StackedAtlas, AVertexTwoTrianglesMoveDifferentlyIsSplit) {
    // Two triangles sharing the edge 1-2 at v = 1: the first lies in period 0, the second in
    // period 1, so vertices 1 and 2 are needed at the band's bottom (v 1 - 0) and at its top
    // (v 1 - 1): the second triangle gets its own copies, six vertices 0, 1, 2 | 2', 1', 3.
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, 2, 0}};
    m.normals.assign(4, {0, 0, 1});
    m.uvs = {{0.0f, 0.5f}, {0.5f, 1.0f}, {0.0f, 1.0f}, {0.5f, 1.5f}};
    m.indices = {0, 1, 2, 2, 1, 3};
    EXPECT_EQ(periodsNeeded(m), 1);
    AtlasBand band{0, 0, 10, 1};
    const std::optional<StackedUvs> s = stackUvs(m, band, 10);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->source, (std::vector<std::uint32_t>{0, 1, 2, 2, 1, 3}));
    EXPECT_FLOAT_EQ(s->uvs[1].y, 1.0f); // first triangle: v 1 is the band's bottom
    EXPECT_FLOAT_EQ(s->uvs[4].y, 0.0f); // second triangle: v 1 - 1 = its top
    EXPECT_FLOAT_EQ(s->uvs[5].y, 0.5f);
    const Mesh gathered = stackedMesh(m, *s);
    EXPECT_EQ(gathered.positions.size(), 6u);
    EXPECT_EQ(gathered.positions[4], m.positions[1]);
}

TEST(StackedAtlas, ATriangleOverSeveralPeriodsNeedsABandAsTall) {
    // A road strip whose v runs 0.5..2.75 along it repeats the texture: a band of one period
    // cannot hold it; a band of the texture three times over, from v 0, holds it as it is.
    const Mesh m = triangle({{0.0f, 0.5f}, {1.0f, 0.5f}, {0.0f, 2.75f}}, 0);
    EXPECT_EQ(periodsNeeded(m), 3);
    EXPECT_FALSE(stackUvs(m, AtlasBand{0, 0, 8, 1, 1}, 8));
    EXPECT_FALSE(stackUvs(m, AtlasBand{0, 0, 8, 1, 2}, 16));
    // Rows 10..33 of a 40-row page: v' = (10 + v * 8) / 40.
    const std::optional<StackedUvs> s = stackUvs(m, AtlasBand{0, 10, 8, 1, 3}, 40);
    ASSERT_TRUE(s);
    EXPECT_FLOAT_EQ(s->uvs[0].y, (10.0f + 4.0f) / 40.0f);
    EXPECT_FLOAT_EQ(s->uvs[2].y, (10.0f + 22.0f) / 40.0f);
    // The same strip moved by seven periods moves back by seven.
    const Mesh far = triangle({{0.0f, 7.5f}, {1.0f, 7.5f}, {0.0f, 9.75f}}, 0);
    EXPECT_EQ(periodsNeeded(far), 3);
    EXPECT_EQ(stackUvs(far, AtlasBand{0, 10, 8, 1, 3}, 40)->uvs, s->uvs);
    // No uvs, or a coordinate that is not a number: no band.
    Mesh bad = m;
    bad.uvs[1].y = NAN;
    EXPECT_EQ(periodsNeeded(bad), 0);
}

TEST(StackedAtlas, PngTexturesShareAPageBlendedAndJpegsDoNot) {
    Scene s;
    const Id wide = s.addTexture(codedTexture(256, 16, 1, "wide.png"));
    const Id narrow = s.addTexture(codedTexture(64, 8, 2, "narrow.rgb"));
    const Id blended = s.addTexture(codedTexture(64, 8, 3, "glass.png"));
    const Id photo = s.addTexture(codedTexture(64, 8, 4, "photo.jpg"));
    const Id road = s.addTexture(codedTexture(64, 8, 5, "road.png"));
    const Id mWide = texturedMaterial(s, wide), mNarrow = texturedMaterial(s, narrow);
    const Id mGlass = texturedMaterial(s, blended, AlphaMode::Blend);
    const Id mPhoto = texturedMaterial(s, photo), mRoad = texturedMaterial(s, road);
    const std::vector<glm::vec2> inOnePeriod{{0, 0}, {1, 0}, {0, 1}};
    place(s, triangle(inOnePeriod, mWide), {0, 0, 0});
    place(s, triangle(inOnePeriod, mNarrow), {2, 0, 0});
    place(s, triangle(inOnePeriod, mGlass), {4, 0, 0});
    place(s, triangle(inOnePeriod, mPhoto), {6, 0, 0});
    // The road: most of its triangles repeat along v over more periods than a band may hold
    // (kAtlasMaxPeriods), one fits. It
    // would be stored twice if stacked: it keeps its own file. The kerb: most fit, one does
    // not: stacked, and that one reads its own file.
    const Id kerb = s.addTexture(codedTexture(64, 8, 6, "kerb.png"));
    const Id mKerb = texturedMaterial(s, kerb);
    const std::vector<glm::vec2> alongV{{0, 0}, {1, 0}, {0, kAtlasMaxPeriods + 2}};
    place(s, triangle(alongV, mRoad), {8, 0, 0});  // mesh 4
    place(s, triangle(alongV, mRoad), {10, 0, 0}); // mesh 5
    place(s, triangle(inOnePeriod, mRoad), {12, 0, 0});
    place(s, triangle(inOnePeriod, mKerb), {14, 0, 0}); // mesh 7
    place(s, triangle(inOnePeriod, mKerb), {16, 0, 0});
    place(s, triangle(alongV, mKerb), {18, 0, 0}); // mesh 9
    s.updateWorldTransforms();

    const StackedAtlases atlases(s);
    ASSERT_NE(atlases.band(mWide), nullptr);
    ASSERT_NE(atlases.band(mNarrow), nullptr);
    EXPECT_EQ(atlases.band(mGlass), nullptr); // blending is drawn in its own order
    EXPECT_EQ(atlases.band(mPhoto), nullptr); // a JPEG keeps its own file
    EXPECT_EQ(atlases.band(mRoad), nullptr);
    ASSERT_NE(atlases.band(mKerb), nullptr);
    EXPECT_TRUE(atlases.stacks(0));
    EXPECT_FALSE(atlases.stacks(4));
    EXPECT_FALSE(atlases.stacks(6)); // the road's fitting triangle reads the road's file
    EXPECT_TRUE(atlases.stacks(7));
    EXPECT_FALSE(atlases.stacks(9));

    // One page, 256 wide (the 64-wide textures repeated 4 times), three bands padded to
    // kAtlasMinSlotRows each (short textures get more mean rows).
    ASSERT_EQ(atlases.pages().size(), 1u);
    const RgbaImage& page = atlases.pages()[0];
    EXPECT_EQ(page.width, 256);
    EXPECT_EQ(page.height, 3 * kAtlasMinSlotRows);
    const AtlasBand& n = *atlases.band(mNarrow);
    EXPECT_EQ(n.repeat, 4);
    EXPECT_EQ(n.rows, 8);
    // Texel (x, y) of the narrow texture sits at (x + 64 k, top + y) for every k.
    EXPECT_EQ(page.at(3 + 128, n.top + 5), glm::u8vec4(3, 5, 2, 255));
    // Above the band its last rows, wrapped (bilinear filtering at v = 0 reads row -1 = 7).
    EXPECT_EQ(page.at(3, n.top - 1), glm::u8vec4(3, 7, 2, 255));
    EXPECT_EQ(page.at(3, n.top + 8), glm::u8vec4(3, 0, 2, 255));
    // Farther out, the texture's mean colour (the same on every column).
    const glm::u8vec4 mean = page.at(0, n.top - kAtlasPadRows);
    EXPECT_EQ(page.at(200, n.top - kAtlasPadRows), mean);
    EXPECT_EQ(mean.b, 2); // the id channel is 2 everywhere, so its mean is 2
    const AtlasBand& w = *atlases.band(mWide);
    EXPECT_EQ(w.repeat, 1);
    EXPECT_EQ(page.at(255, w.top + 15), glm::u8vec4(255, 15, 1, 255));
}

TEST(StackedAtlas, ATextureWhoseTrianglesSpanThreePeriodsSitsThreeTimesOver) {
    // A kerb texture whose strips run v 0.25..2.5 (three periods from v 0) and a wall in one
    // period: the kerb's band holds its 8 rows three times, and the strip reads them there.
    Scene s;
    const Id mKerb = texturedMaterial(s, s.addTexture(codedTexture(64, 8, 1, "kerb.png")));
    const Id mWall = texturedMaterial(s, s.addTexture(codedTexture(64, 8, 2, "wall.png")));
    place(s, triangle({{0.0f, 0.25f}, {1.0f, 0.25f}, {0.0f, 2.5f}}, mKerb), {0, 0, 0});
    place(s, triangle({{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}}, mWall), {2, 0, 0});
    s.updateWorldTransforms();
    const StackedAtlases atlases(s);
    ASSERT_EQ(atlases.pages().size(), 1u);
    EXPECT_TRUE(atlases.stacks(0));
    const AtlasBand& k = *atlases.band(mKerb);
    EXPECT_EQ(k.periods, 3);
    EXPECT_EQ(k.rows, 8);
    EXPECT_EQ(atlases.band(mWall)->periods, 1);
    const RgbaImage& page = atlases.pages()[0];
    // Row r of the band is row r mod 8 of the texture, wrapped rows next to it.
    for (int r = -kAtlasWrapRows; r < 3 * 8 + kAtlasWrapRows; ++r)
        EXPECT_EQ(page.at(70, k.top + r), glm::u8vec4(6, (r + 8) % 8, 1, 255)) << r;
    // The strip's uvs span rows top + 2 .. top + 20 (v 0.25 and 2.5 of 8-row periods).
    const std::optional<StackedUvs> uvs = stackUvs(s.meshes[0], k, page.height);
    ASSERT_TRUE(uvs);
    EXPECT_FLOAT_EQ(uvs->uvs[0].y * page.height, k.top + 2.0f);
    EXPECT_FLOAT_EQ(uvs->uvs[2].y * page.height, k.top + 20.0f);
}

TEST(StackedAtlas, CutOutsShareAPageOfTheirOwn) {
    // Two fences (translucent texels, MASK) and two opaque walls of one width: two pages, so
    // no cut-out's band neighbours an opaque one.
    Scene s;
    std::vector<Id> materials;
    for (int i = 0; i < 4; ++i) {
        Texture t = codedTexture(64, 8, i, "t" + std::to_string(i) + ".png");
        const bool fence = i < 2;
        if (fence) {
            auto img = std::make_shared<RgbaImage>(*t.image);
            img->set(0, 0, glm::u8vec4(0, 0, 0, 0));
            t.image = img;
        }
        materials.push_back(
            texturedMaterial(s, s.addTexture(t), fence ? AlphaMode::Mask : AlphaMode::Opaque));
        place(s, triangle({{0, 0}, {1, 0}, {0, 1}}, materials.back()), {2.0 * i, 0, 0});
    }
    s.updateWorldTransforms();
    const StackedAtlases atlases(s);
    ASSERT_EQ(atlases.pages().size(), 2u);
    for (Id m : materials)
        ASSERT_NE(atlases.band(m), nullptr);
    EXPECT_EQ(atlases.band(materials[0])->page, atlases.band(materials[1])->page);
    EXPECT_EQ(atlases.band(materials[2])->page, atlases.band(materials[3])->page);
    EXPECT_NE(atlases.band(materials[0])->page, atlases.band(materials[2])->page);
}

TEST(StackedAtlas, APageOfOneTextureIsNotMade) {
    // A lone 512-wide texture (no other texture of its width): a page would merge nothing.
    Scene s;
    const Id alone = texturedMaterial(s, s.addTexture(codedTexture(512, 8, 1, "hull.png")));
    const Id small = texturedMaterial(s, s.addTexture(codedTexture(64, 8, 2, "deck.png")));
    place(s, triangle({{0, 0}, {1, 0}, {0, 1}}, alone), {0, 0, 0});
    place(s, triangle({{0, 0}, {1, 0}, {0, 1}}, small), {2, 0, 0});
    s.updateWorldTransforms();
    const StackedAtlases atlases(s);
    EXPECT_EQ(atlases.band(alone), nullptr);
    EXPECT_EQ(atlases.band(small), nullptr);
    EXPECT_FALSE(atlases.stacks(0));
    EXPECT_TRUE(atlases.pages().empty());
}

TEST(StackedAtlas, ALeafGroupOfTwoTexturesWritesOnePrimitive) {
    // Two boxes of different textures under one node: merged per look they were two
    // primitives (one per texture); stacked, one primitive reading one page.
    Scene s;
    const Id a = texturedMaterial(s, s.addTexture(codedTexture(32, 32, 1, "a.png")));
    const Id b = texturedMaterial(s, s.addTexture(codedTexture(32, 32, 2, "b.png")));
    for (int i = 0; i < 2; ++i) {
        Mesh box = makeBox({1, 1, 1});
        box.uvs.assign(box.positions.size(), glm::vec2(0.25f, 0.5f));
        box.material = i == 0 ? a : b;
        place(s, std::move(box), {2.0 * i, 0, 0});
    }
    s.updateWorldTransforms();
    const ClusterTree tree = buildClusterTree(s, ClusterParams{});
    BakeParams params;
    params.threads = 1;
    const BakeResult bake = bakeProxies(s, tree, params);
    hlod::test::TempDir tmp;
    PackageOptions options;
    options.compression = GlbCompression::None;
    writePackage(tmp / "pkg", s, tree, bake, params, options);

    std::size_t leafPrimitives = 0;
    std::set<std::string> images;
    for (const auto& e : fs::directory_iterator(tmp / "pkg" / "tiles")) {
        if (e.path().extension() != ".glb") continue;
        tinygltf::TinyGLTF loader;
        tinygltf::Model m;
        std::string err, warn;
        ASSERT_TRUE(loader.LoadBinaryFromFile(&m, &err, &warn, e.path().string())) << err;
        for (const tinygltf::Mesh& mesh : m.meshes) {
            if (mesh.name == "proxy") continue;
            leafPrimitives += mesh.primitives.size();
            for (const tinygltf::Image& img : m.images)
                images.insert(img.uri);
        }
    }
    EXPECT_EQ(leafPrimitives, 1u);
    ASSERT_EQ(images.size(), 1u);
    // The page: 32 wide texture repeated to 256, two bands of 32 rows and their padding.
    std::size_t files = 0;
    for (const auto& e : fs::directory_iterator(tmp / "pkg" / "tiles" / "textures")) {
        ++files;
        EXPECT_EQ("textures/" + e.path().filename().string(), *images.begin());
    }
    EXPECT_EQ(files, 1u); // the two source textures are not written on their own
}
