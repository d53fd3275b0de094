// Textures reach the materials: AC3D objects with several texture lines take the first (TORCS
// .acc), SGI textures beside the scene are decoded, glTF images keep their pixels and alpha
// mode; the shared TORCS track reads all its textures.
#include <gtest/gtest.h>

#include <cstring>

#include "SgiTestFiles.h"
#include "TestUtil.h"
#include "pipeline/io/Ac3dTextures.h"
#include "pipeline/io/Import.h"
#include "pipeline/io/TextureImage.h"

using namespace hlod;
using hlod::test::TempDir;

namespace {

// One quad object (two triangles) with uvs, naming `textures` in order.
std::string acQuad(const std::string& textureLines) {
    return "AC3Db\n"
           "MATERIAL \"\" rgb 1 1 1  amb 0.2 0.2 0.2  emis 0 0 0  spec 0 0 0  shi 0  trans 0\n"
           "OBJECT world\nkids 1\nOBJECT poly\nname \"quad\"\n" +
           textureLines +
           "numvert 4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\nnumsurf 1\nSURF 0x10\nmat 0\nrefs 4\n"
           "0 0 0 5 5\n1 1 0 6 5\n2 1 1 6 6\n3 0 1 5 6\nkids 0\n";
}

// A 2x2 verbatim RGB SGI file: every texel (r, 0, 0).
std::string sgiOfRed(std::uint8_t r) {
    std::vector<std::uint8_t> b = hlod::test::sgiHeader(0, 2, 2, 3);
    b.insert(b.end(), 4, r);
    b.insert(b.end(), 8, 0);
    return {b.begin(), b.end()};
}

} // namespace

TEST(Ac3dTextures, FirstTextureLineOfEachObjectIsKept) {
    const auto file =
        parseAc3dFile(acQuad("texture \"base.rgb\" base\ntexture \"lines.png\" tiled\n"
                             "texture empty_texture_no_mapping skids\n"));
    ASSERT_TRUE(file);
    const auto* objects = &file->objects;
    ASSERT_EQ(objects->size(), 1u);
    ASSERT_EQ(objects->front().kids.size(), 1u);
    EXPECT_EQ(objects->front().kids[0].name, "quad");
    EXPECT_EQ(objects->front().kids[0].firstTexture, "base.rgb");
    EXPECT_EQ(objects->front().firstTexture, "");
}

TEST(TexturedImport, AcObjectWithSeveralTexturesUsesTheFirstAsBaseColour) {
    TempDir dir;
    hlod::test::writeFile(dir / "base.rgb", sgiOfRed(200));
    hlod::test::writeFile(dir / "lines.rgb", sgiOfRed(10));
    const auto file = hlod::test::writeFile(
        dir / "track.acc", acQuad("texture \"base.rgb\" base\ntexture \"lines.rgb\" tiled\n"
                                  "texture empty_texture_no_mapping shad\n"));
    const Scene s = importScene({file});
    ASSERT_EQ(s.meshes.size(), 1u);
    const Material& m = s.materials[s.meshes[0].material];
    EXPECT_EQ(m.baseColorTexture.filename(), "base.rgb");
    ASSERT_NE(m.texture, kNoId);
    const RgbaImage* image = s.textureImage(s.meshes[0].material);
    ASSERT_NE(image, nullptr);
    EXPECT_EQ(image->at(1, 1), glm::u8vec4(200, 0, 0, 255));
    // The first uv pair of each reference (the base texture's), v flipped to glTF's convention.
    ASSERT_EQ(s.meshes[0].uvs.size(), s.meshes[0].positions.size());
    EXPECT_EQ(m.alphaMode, AlphaMode::Opaque);
}

TEST(TexturedImport, UnreadableTextureFallsBackToTheMaterialColourAndIsNamed) {
    TempDir dir;
    hlod::test::writeFile(dir / "bad.rgb", "\x01\xda garbage");
    const auto file = hlod::test::writeFile(dir / "t.ac", acQuad("texture \"bad.rgb\"\n"));
    const Scene s = importScene({file});
    const Material& m = s.materials[s.meshes[0].material];
    ASSERT_NE(m.texture, kNoId);
    EXPECT_EQ(s.textureImage(s.meshes[0].material), nullptr);
    EXPECT_EQ(m.textureMean, glm::vec4(1.0f));
    EXPECT_NE(s.textures[m.texture].error.find("bad.rgb: SGI header truncated"), std::string::npos)
        << s.textures[m.texture].error;
}

TEST(TexturedImport, TorcsTrackDecodesEveryTextureItNames) {
    const Scene s = importScene({hlod::test::dataDir() / "scenes/torcs-spring/spring.acc"});
    // SOURCE.txt: 28 SGI textures, and raceline.png is never a base texture (always second).
    std::size_t sgi = 0;
    for (const Texture& t : s.textures) {
        EXPECT_NE(t.image, nullptr) << t.error;
        EXPECT_NE(t.name, "raceline.png");
        sgi += t.name.ends_with(".rgb") ? 1 : 0;
    }
    EXPECT_EQ(sgi, 28u);
    EXPECT_EQ(s.textures.size(), 28u);
    // The tree (arbor2_n.rgb) has a cut-out alpha channel.
    bool treeMasked = false;
    for (const Material& m : s.materials)
        treeMasked |=
            m.alphaMode == AlphaMode::Mask && m.baseColorTexture.filename() == "arbor2_n.rgb";
    EXPECT_TRUE(treeMasked);
}

namespace {

std::string base64(const std::vector<std::uint8_t>& in) {
    static const char* tbl = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < in.size(); i += 3) {
        const unsigned v = (in[i] << 16) | ((i + 1 < in.size() ? in[i + 1] : 0) << 8) |
                           (i + 2 < in.size() ? in[i + 2] : 0);
        out += tbl[(v >> 18) & 63];
        out += tbl[(v >> 12) & 63];
        out += i + 1 < in.size() ? tbl[(v >> 6) & 63] : '=';
        out += i + 2 < in.size() ? tbl[v & 63] : '=';
    }
    return out;
}

} // namespace

TEST(TexturedImport, GltfEmbeddedImageKeepsItsPixelsAndAlphaMode) {
    // One triangle with uvs; the material's texture is a 2x2 PNG in a data URI, alpha cut out
    // at 0.3. Positions (0,0,0) (1,0,0) (0,1,0), uvs (0,0) (1,0) (0,1), indices 0 1 2.
    RgbaImage texels(2, 2, glm::u8vec4(0, 0, 255, 255));
    texels.set(1, 0, glm::u8vec4(255, 0, 0, 0)); // top right: transparent red
    const EncodedImage png = encodePng(texels);
    std::vector<std::uint8_t> buffer(36 + 24 + 8);
    const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const float uv[6] = {0, 0, 1, 0, 0, 1};
    const std::uint16_t idx[4] = {0, 1, 2, 0};
    std::memcpy(buffer.data(), pos, 36);
    std::memcpy(buffer.data() + 36, uv, 24);
    std::memcpy(buffer.data() + 60, idx, 8);
    const std::string json =
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
      "meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"indices":2,"material":0}]}],
      "materials":[{"alphaMode":"MASK","alphaCutoff":0.3,
                    "pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],
      "textures":[{"source":0}],
      "images":[{"uri":"data:image/png;base64,)" +
        base64(png.bytes) + R"("}],
      "buffers":[{"uri":"data:application/octet-stream;base64,)" +
        base64(buffer) + R"(","byteLength":68}],
      "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},
                     {"buffer":0,"byteOffset":36,"byteLength":24},
                     {"buffer":0,"byteOffset":60,"byteLength":8}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
                   {"bufferView":1,"componentType":5126,"count":3,"type":"VEC2"},
                   {"bufferView":2,"componentType":5123,"count":3,"type":"SCALAR"}]})";
    TempDir dir;
    const Scene s = importScene({hlod::test::writeFile(dir / "t.gltf", json)});
    const Id mat = s.meshes[0].material;
    EXPECT_EQ(s.materials[mat].alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(s.materials[mat].alphaCutoff, 0.3f);
    EXPECT_TRUE(s.materials[mat].baseColorTexture.empty()); // embedded: no file
    const RgbaImage* image = s.textureImage(mat);
    ASSERT_NE(image, nullptr);
    EXPECT_EQ(image->at(1, 0), glm::u8vec4(255, 0, 0, 0));
    EXPECT_EQ(image->at(0, 1), glm::u8vec4(0, 0, 255, 255));
    // Mean: three blue texels and one red, alpha 3/4.
    EXPECT_NEAR(s.materials[mat].textureMean.a, 0.75f, 1e-6f);
    EXPECT_NEAR(s.materials[mat].textureMean.b, 0.75f, 1e-6f);
}
