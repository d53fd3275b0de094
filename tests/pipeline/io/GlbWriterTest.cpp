#include <gtest/gtest.h>

#include <cstring>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "TestUtil.h"
#include "pipeline/io/GlbWriter.h"
#include "pipeline/io/GltfMeshopt.h"

using namespace hlod;

namespace {

struct Quad {
    std::vector<glm::vec3> positions{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
    std::vector<glm::vec3> normals{4, glm::vec3(0, 0, 1)};
    std::vector<glm::u8vec4> colors{4, glm::u8vec4(255, 128, 0, 255)};
    std::vector<std::uint32_t> indices{0, 1, 2, 0, 2, 3};
    GlbMesh view() const {
        GlbMesh m;
        m.name = "proxy_7";
        m.translation = {1.0e6, 2.5, -3.0}; // far from the origin: double precision node
        m.positions = positions;
        m.normals = normals;
        m.colors = colors;
        m.indices = indices;
        return m;
    }
};

tinygltf::Model load(const std::vector<std::uint8_t>& bytes) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    const bool ok = loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                                static_cast<unsigned>(bytes.size()));
    EXPECT_TRUE(ok) << err;
    EXPECT_TRUE(err.empty()) << err;
    return model;
}

} // namespace

TEST(GlbWriter, QuadWithNormalsAndColoursLoadsBackInTinyGltf) {
    const Quad q;
    const std::vector<std::uint8_t> bytes = encodeGlb(q.view());
    EXPECT_EQ(bytes.size() % 4, 0u); // GLB chunks are 4-byte aligned
    EXPECT_EQ(bytes.size(), glbByteSize(q.view()));
    const tinygltf::Model model = load(bytes);
    ASSERT_EQ(model.meshes.size(), 1u);
    ASSERT_EQ(model.nodes.size(), 1u);
    EXPECT_EQ(model.nodes[0].translation, (std::vector<double>{1.0e6, 2.5, -3.0}));
    const tinygltf::Primitive& prim = model.meshes[0].primitives[0];
    const tinygltf::Accessor& pos = model.accessors[prim.attributes.at("POSITION")];
    EXPECT_EQ(pos.count, 4u);
    EXPECT_EQ(pos.maxValues, (std::vector<double>{2, 1, 0}));
    const tinygltf::Accessor& color = model.accessors[prim.attributes.at("COLOR_0")];
    EXPECT_EQ(color.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE);
    EXPECT_TRUE(color.normalized);
    const tinygltf::Accessor& idx = model.accessors[prim.indices];
    EXPECT_EQ(idx.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT); // 4 vertices fit
    EXPECT_EQ(idx.count, 6u);
    // The third index of the second triangle, read back through the buffer view.
    const tinygltf::BufferView& view = model.bufferViews[idx.bufferView];
    const unsigned char* data = model.buffers[0].data.data() + view.byteOffset;
    EXPECT_EQ(data[10] | (data[11] << 8), 3);
}

TEST(GlbWriter, SameMeshGivesSameBytesAndFileIsReplacedAtomically) {
    const Quad q;
    EXPECT_EQ(encodeGlb(q.view()), encodeGlb(q.view()));
    test::TempDir dir;
    const auto file = dir / "p.glb";
    writeGlbFile(file, q.view());
    writeGlbFile(file, q.view());
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path()))
        ++entries;
    EXPECT_EQ(entries, 1u); // no temporary left
    EXPECT_EQ(std::filesystem::file_size(file), encodeGlb(q.view()).size());
}

TEST(GlbWriter, EmptyProxyIsAValidFileWithoutMesh) {
    GlbMesh empty;
    empty.name = "nothing";
    const tinygltf::Model model = load(encodeGlb(empty));
    EXPECT_TRUE(model.meshes.empty());
    EXPECT_EQ(model.nodes.size(), 1u);
}

TEST(GlbWriter, RejectsIndicesOutOfRange) {
    Quad q;
    q.indices[4] = 9;
    EXPECT_THROW(encodeGlb(q.view()), std::exception);
}

namespace {

// Two quads of different looks and a triangle, each under its own node.
struct ThreeMeshes {
    Quad a, b;
    std::vector<glm::vec3> triangle{{5, 0, 0}, {6, 0, 0}, {5, 1, 0}};
    std::vector<std::uint32_t> triangleIndices{0, 1, 2};
    std::vector<glm::vec2> uvs{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    GlbScene scene(GlbCompression compression, bool textured = false) const {
        GlbScene s;
        s.compression = compression;
        s.meshes = {a.view(), b.view(), a.view()};
        s.meshes[1].name = "";
        s.meshes[1].baseColor = {0.4f, 0.4f, 0.4f, 1.0f};
        s.meshes[1].materialName = "grey";
        if (textured) {
            s.meshes[1].uvs = uvs;
            s.meshes[1].imageUri = "textures/t.png";
        }
        s.meshes[2].positions = triangle;
        s.meshes[2].normals = {};
        s.meshes[2].colors = {};
        s.meshes[2].indices = triangleIndices;
        for (int i = 0; i < 3; ++i) {
            GlbNode n;
            n.mesh = i;
            n.trs.translation = {double(i), 0.0, 0.0};
            s.nodes.push_back(n);
        }
        return s;
    }
};

} // namespace

TEST(GlbWriter, OneBufferViewPerStreamAndNoDefaultsInTheJson) {
    const ThreeMeshes t;
    for (GlbCompression c : {GlbCompression::None, GlbCompression::Meshopt}) {
        const std::vector<std::uint8_t> bytes = encodeGlb(t.scene(c, true));
        const std::string text = splitGlb(bytes, "t.glb").json;
        const nlohmann::json j = nlohmann::json::parse(text);
        // Positions, normals, uvs, colours, 16-bit indices: five views for three meshes; the
        // compressed file adds a plain copy of its smallest accessor (GlbWriter.h: buffer 0
        // used by a core view).
        EXPECT_EQ(j["bufferViews"].size(), c == GlbCompression::Meshopt ? 6u : 5u) << toString(c);
        EXPECT_EQ(j["samplers"], nlohmann::json::parse(R"([{"magFilter":9729,"minFilter":9987}])"));
        EXPECT_EQ(j["meshes"].size(), 3u);
        EXPECT_EQ(j["accessors"][0].count("byteOffset"), 0u); // 0 is the default
        // The second mesh's positions start after the first's four.
        const auto& pos1 =
            j["accessors"][j["meshes"][1]["primitives"][0]["attributes"]["POSITION"].get<int>()];
        EXPECT_EQ(pos1["bufferView"], 0);
        EXPECT_EQ(pos1["byteOffset"], c == GlbCompression::Meshopt ? 32 : 48);
        for (const char* absent : {"\"mode\":4", "roughnessFactor", "wrapS", "\"byteOffset\":0",
                                   "\"name\":\"\"", ": ", ", ", "\n", ".0,", ".0]"})
            EXPECT_EQ(text.find(absent), std::string::npos) << absent << " in " << text;
        // Factors as the shortest decimal of the float; white is the default.
        EXPECT_NE(text.find("[0.4,0.4,0.4,1]"), std::string::npos) << text;
        EXPECT_EQ(j["materials"].size(), 2u); // meshes 0 and 2 look alike
        EXPECT_EQ(j["materials"][1]["name"], "grey");
        EXPECT_EQ(j["materials"][0].count("name"), 0u); // no name of its own
        EXPECT_EQ(j["meshes"][1].count("name"), 0u);
        EXPECT_EQ(bytes, encodeGlb(t.scene(c, true))); // deterministic
    }
}

TEST(GlbWriter, MeshesSharingViewsReadBackInTinyGltf) {
    const ThreeMeshes t;
    const tinygltf::Model model = load(encodeGlb(t.scene(GlbCompression::None)));
    ASSERT_EQ(model.meshes.size(), 3u);
    // Every accessor read through its view's offset and stride gives the mesh's own values.
    auto element = [&](int accessor, std::size_t i) {
        const tinygltf::Accessor& a = model.accessors[std::size_t(accessor)];
        const tinygltf::BufferView& v = model.bufferViews[std::size_t(a.bufferView)];
        const std::size_t stride = v.byteStride ? v.byteStride : 2;
        return model.buffers[0].data.data() + v.byteOffset + a.byteOffset + i * stride;
    };
    const std::vector<const std::vector<glm::vec3>*> positions{&t.a.positions, &t.b.positions,
                                                               &t.triangle};
    for (std::size_t m = 0; m < 3; ++m) {
        const tinygltf::Primitive& p = model.meshes[m].primitives[0];
        EXPECT_EQ(p.mode, TINYGLTF_MODE_TRIANGLES); // the default
        for (std::size_t i = 0; i < positions[m]->size(); ++i) {
            glm::vec3 v;
            std::memcpy(&v, element(p.attributes.at("POSITION"), i), 12);
            EXPECT_EQ(v, (*positions[m])[i]) << m << " " << i;
        }
        const std::vector<std::uint32_t>& indices = m == 2 ? t.triangleIndices : t.a.indices;
        ASSERT_EQ(model.accessors[std::size_t(p.indices)].count, indices.size());
        for (std::size_t i = 0; i < indices.size(); ++i) {
            std::uint16_t k;
            std::memcpy(&k, element(p.indices, i), 2);
            EXPECT_EQ(k, indices[i]) << m << " " << i;
        }
    }
    EXPECT_EQ(model.meshes[2].primitives[0].attributes.count("NORMAL"), 0u);
    EXPECT_EQ(model.materials[0].pbrMetallicRoughness.roughnessFactor, 1.0);
    EXPECT_EQ(model.materials[0].pbrMetallicRoughness.baseColorFactor,
              (std::vector<double>{1, 1, 1, 1}));
}

// Materials as given (issue 28): alpha mode and cut-off, doubleSided, emissive factor and
// texture, written once per look; an emissive factor above 1 as KHR_materials_emissive_strength.
TEST(GlbWriter, MaterialLooksAreWrittenAsGiven) {
    const ThreeMeshes t;
    GlbScene s = t.scene(GlbCompression::None, true);
    // Mesh 0: a cut-out at 0.3, two-sided, emitting through its own image (a proxy atlas).
    s.meshes[0].uvs = t.uvs;
    const std::vector<std::uint8_t> bytes{1, 2, 3, 4}; // bytes only: not decoded here
    s.meshes[0].image = bytes;                         // a view: the bytes outlive the encoding
    s.meshes[0].imageMimeType = "image/png";
    s.meshes[0].alphaMode = AlphaMode::Mask;
    s.meshes[0].alphaCutoff = 0.3f;
    s.meshes[0].doubleSided = true;
    s.meshes[0].emissive = {1.0f, 0.5f, 0.25f};
    s.meshes[0].emissiveUsesImage = true;
    // Mesh 1 (textured by file): blends, emits 3 x white through a second file.
    s.meshes[1].alphaMode = AlphaMode::Blend;
    s.meshes[1].emissive = glm::vec3(3.0f);
    s.meshes[1].emissiveUri = "textures/glow.png";
    const nlohmann::json j = nlohmann::json::parse(splitGlb(encodeGlb(s), "t.glb").json);
    ASSERT_EQ(j["materials"].size(), 3u);
    const auto& cut = j["materials"][0];
    EXPECT_EQ(cut["alphaMode"], "MASK");
    EXPECT_FLOAT_EQ(cut["alphaCutoff"].get<float>(), 0.3f);
    EXPECT_EQ(cut["doubleSided"], true);
    EXPECT_EQ(cut["emissiveFactor"], nlohmann::json::parse("[1,0.5,0.25]"));
    // The base colour texture again: one texture, one image for both.
    EXPECT_EQ(cut["emissiveTexture"]["index"],
              cut["pbrMetallicRoughness"]["baseColorTexture"]["index"]);
    const auto& glow = j["materials"][1];
    EXPECT_EQ(glow["alphaMode"], "BLEND");
    EXPECT_EQ(glow.count("doubleSided"), 0u); // false is the default
    EXPECT_EQ(glow["emissiveFactor"], nlohmann::json::parse("[1,1,1]"));
    EXPECT_EQ(glow["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"], 3);
    const int glowTexture = glow["emissiveTexture"]["index"];
    EXPECT_EQ(j["images"][j["textures"][glowTexture]["source"].get<int>()]["uri"],
              "textures/glow.png");
    EXPECT_EQ(j["extensionsUsed"], nlohmann::json::parse(R"(["KHR_materials_emissive_strength"])"));
    EXPECT_EQ(j.count("extensionsRequired"), 0u); // an engine without it still draws
    // Mesh 2 keeps the default look: no alphaMode, doubleSided or emissive written.
    const auto& plain = j["materials"][2];
    for (const char* absent : {"alphaMode", "doubleSided", "emissiveFactor", "emissiveTexture"})
        EXPECT_EQ(plain.count(absent), 0u) << absent;
}
