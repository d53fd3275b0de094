// Textures embedded in leaf tiles: PNG/JPEG pass through, other formats become PNG, garbage is
// refused; the GLB carries the image in its BIN chunk and tinygltf decodes it back.
#include <gtest/gtest.h>

#include <cstring>

#include <stb_image.h>
#include <stb_image_write.h>
#include <tiny_gltf.h>

#include "pipeline/io/GlbWriter.h"
#include "pipeline/io/TextureImage.h"

using namespace hlod;

namespace {

void append(void* ctx, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(ctx);
    out->insert(out->end(), static_cast<std::uint8_t*>(data),
                static_cast<std::uint8_t*>(data) + size);
}

// 2 x 2 RGB image: red, green / blue, white.
const std::uint8_t kPixels[12] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};

std::vector<std::uint8_t> encodePng() {
    std::vector<std::uint8_t> out;
    stbi_write_png_to_func(&append, &out, 2, 2, 3, kPixels, 6);
    return out;
}

std::vector<std::uint8_t> encodeBmp() {
    std::vector<std::uint8_t> out;
    stbi_write_bmp_to_func(&append, &out, 2, 2, 3, kPixels);
    return out;
}

// The GLB of `m` as tinygltf reads it back (images decoded).
tinygltf::Model encodeAndLoad(const GlbMesh& m) {
    const std::vector<std::uint8_t> bytes = encodeGlb(m);
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    EXPECT_TRUE(loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                            static_cast<unsigned>(bytes.size())))
        << err;
    return model;
}

} // namespace

TEST(TextureImage, PngPassesThroughByteForByte) {
    const std::vector<std::uint8_t> png = encodePng();
    const auto image = encodeForGltf(png);
    ASSERT_TRUE(image);
    EXPECT_EQ(image->mimeType, "image/png");
    EXPECT_EQ(image->bytes, png); // no recompression
}

TEST(TextureImage, BmpIsReencodedAsPngWithTheSamePixels) {
    const auto image = encodeForGltf(encodeBmp());
    ASSERT_TRUE(image);
    EXPECT_EQ(image->mimeType, "image/png");
    ASSERT_GE(image->bytes.size(), 8u);
    EXPECT_EQ(image->bytes[1], 'P'); // PNG signature 89 'P' 'N' 'G'
    int w = 0, h = 0, c = 0;
    unsigned char* px = stbi_load_from_memory(image->bytes.data(),
                                              static_cast<int>(image->bytes.size()), &w, &h, &c, 3);
    ASSERT_NE(px, nullptr);
    EXPECT_EQ(w, 2);
    EXPECT_EQ(h, 2);
    EXPECT_EQ(std::memcmp(px, kPixels, 12), 0); // lossless round trip
    stbi_image_free(px);
}

TEST(TextureImage, GarbageAndTruncatedPngAreRefused) {
    const std::vector<std::uint8_t> garbage{1, 2, 3, 4, 5, 6, 7, 8, 9};
    EXPECT_FALSE(encodeForGltf(garbage));
    std::vector<std::uint8_t> png = encodePng();
    png.resize(12); // signature and part of the IHDR length: no size can be read
    EXPECT_FALSE(encodeForGltf(png));
    EXPECT_FALSE(loadTextureForGltf("/nonexistent/texture.png"));
}

TEST(GlbWriter, EmbeddedTextureIsReferencedByTheMaterialAndDecodesBack) {
    const std::vector<glm::vec3> positions{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    const std::vector<glm::vec3> normals(3, glm::vec3(0, 0, 1));
    const std::vector<glm::vec2> uvs{{0, 1}, {1, 1}, {1, 0}};
    const std::vector<std::uint32_t> indices{0, 1, 2};
    const std::vector<std::uint8_t> png = encodePng();
    GlbMesh m;
    m.name = "leaf";
    m.positions = positions;
    m.normals = normals;
    m.uvs = uvs;
    m.indices = indices;
    m.image = png;
    m.imageMimeType = "image/png";
    const tinygltf::Model model = encodeAndLoad(m);
    ASSERT_EQ(model.images.size(), 1u);
    EXPECT_EQ(model.images[0].mimeType, "image/png");
    EXPECT_EQ(model.images[0].width, 2); // tinygltf decoded the embedded bytes
    EXPECT_EQ(model.bufferViews[static_cast<std::size_t>(model.images[0].bufferView)].byteLength,
              png.size());
    ASSERT_EQ(model.textures.size(), 1u);
    EXPECT_EQ(model.materials[0].pbrMetallicRoughness.baseColorTexture.index, 0);
    EXPECT_TRUE(model.meshes[0].primitives[0].attributes.count("TEXCOORD_0"));
}

TEST(GlbWriter, ImageWithoutUvsIsLeftOut) {
    const std::vector<glm::vec3> positions{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    const std::vector<std::uint32_t> indices{0, 1, 2};
    const std::vector<std::uint8_t> png = encodePng();
    GlbMesh m;
    m.positions = positions;
    m.indices = indices;
    m.image = png;
    m.imageMimeType = "image/png";
    const tinygltf::Model model = encodeAndLoad(m);
    EXPECT_TRUE(model.images.empty()); // a texture nobody can sample would only cost bytes
}
