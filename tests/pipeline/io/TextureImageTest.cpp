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

namespace {

// A PNG chunk with its CRC-32 (ISO 3309, the PNG spec's CRC over type and data).
std::vector<std::uint8_t> chunk(const char* type, const std::vector<std::uint8_t>& data) {
    std::vector<std::uint8_t> c{std::uint8_t(data.size() >> 24), std::uint8_t(data.size() >> 16),
                                std::uint8_t(data.size() >> 8), std::uint8_t(data.size())};
    c.insert(c.end(), type, type + 4);
    c.insert(c.end(), data.begin(), data.end());
    std::uint32_t crc = 0xFFFFFFFFu;
    for (std::size_t i = 4; i < c.size(); ++i) {
        crc ^= c[i];
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    crc ^= 0xFFFFFFFFu;
    for (int k = 3; k >= 0; --k)
        c.push_back(std::uint8_t(crc >> (8 * k)));
    return c;
}

// The 2 x 2 PNG with colour-space metadata after IHDR (signature 8 bytes + IHDR 25 bytes): a
// gamma of 1.0 (100000), an ICC profile stub, unequal pixel aspect, a text chunk, and tRNS
// making pure red transparent.
std::vector<std::uint8_t> pngWithMetadata() {
    const std::vector<std::uint8_t> plain = encodePng();
    std::vector<std::uint8_t> png(plain.begin(), plain.begin() + 33);
    for (const auto& c : {chunk("gAMA", {0, 1, 0x86, 0xA0}),
                          chunk("iCCP", {'p', 0, 0, 0x78, 0x9C, 3, 0, 0, 0, 0, 1}),
                          chunk("pHYs", {0, 0, 0x0B, 0x13, 0, 0, 0x16, 0x26, 1}),
                          chunk("tEXt", {'a', 0, 'b'}), chunk("tRNS", {0, 255, 0, 0, 0, 0})})
        png.insert(png.end(), c.begin(), c.end());
    png.insert(png.end(), plain.begin() + 33, plain.end());
    return png;
}

std::vector<std::string> chunkTypes(const std::vector<std::uint8_t>& png) {
    std::vector<std::string> types;
    for (std::size_t p = 8; p + 12 <= png.size();) {
        const std::size_t n = (std::size_t(png[p]) << 24) | (std::size_t(png[p + 1]) << 16) |
                              (std::size_t(png[p + 2]) << 8) | png[p + 3];
        types.emplace_back(reinterpret_cast<const char*>(&png[p + 4]), 4);
        p += 12 + n;
    }
    return types;
}

} // namespace

TEST(TextureImage, PngLosesItsColourSpaceMetadataButNotItsPixels) {
    const std::vector<std::uint8_t> png = pngWithMetadata();
    ASSERT_EQ(chunkTypes(png), (std::vector<std::string>{"IHDR", "gAMA", "iCCP", "pHYs", "tEXt",
                                                         "tRNS", "IDAT", "IEND"}));
    const auto image = encodeForGltf(png);
    ASSERT_TRUE(image);
    // Critical chunks and tRNS (it changes what the pixels are) are kept, in order.
    EXPECT_EQ(chunkTypes(image->bytes), (std::vector<std::string>{"IHDR", "tRNS", "IDAT", "IEND"}));
    // Decoded: the same samples, and red (255, 0, 0) transparent through tRNS in both.
    int w = 0, h = 0, c = 0;
    unsigned char* before =
        stbi_load_from_memory(png.data(), static_cast<int>(png.size()), &w, &h, &c, 4);
    unsigned char* after = stbi_load_from_memory(
        image->bytes.data(), static_cast<int>(image->bytes.size()), &w, &h, &c, 4);
    ASSERT_NE(before, nullptr);
    ASSERT_NE(after, nullptr);
    EXPECT_EQ(std::memcmp(before, after, 16), 0);
    EXPECT_EQ(after[3], 0);   // red: transparent
    EXPECT_EQ(after[7], 255); // green: opaque
    stbi_image_free(before);
    stbi_image_free(after);
    // A chunk length past the end of the file is a broken structure.
    std::vector<std::uint8_t> broken = png;
    broken[33 + 3] = 200; // gAMA claims 200 bytes
    broken.resize(80);
    EXPECT_FALSE(pngWithoutMetadata(broken));
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
