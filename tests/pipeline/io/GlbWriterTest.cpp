#include <gtest/gtest.h>

#include <tiny_gltf.h>

#include "TestUtil.h"
#include "pipeline/io/GlbWriter.h"

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
