// glTF importer tests on tiny hand-written glTF files (JSON + base64 buffers) whose expected
// values follow directly from the bytes written, plus the shared real scenes.
#include <gtest/gtest.h>

#include <cstring>

#include "TestUtil.h"
#include "pipeline/core/Error.h"
#include "pipeline/io/Import.h"

using namespace hlod;
using hlod::test::TempDir;

namespace {

std::string base64(const std::vector<unsigned char>& in) {
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

// One triangle (0,0,0) (1,0,0) (0,1,0) with uint16 indices {i0,i1,i2}.
std::vector<unsigned char> triangleBuffer(std::uint16_t i0 = 0, std::uint16_t i1 = 1,
                                          std::uint16_t i2 = 2, float x = 1.0f) {
    const float pos[9] = {0, 0, 0, x, 0, 0, 0, 1, 0};
    const std::uint16_t idx[4] = {i0, i1, i2, 0};
    std::vector<unsigned char> b(44);
    std::memcpy(b.data(), pos, 36);
    std::memcpy(b.data() + 36, idx, 8);
    return b;
}

std::string gltfJson(const std::string& bufferUri, std::size_t byteLength,
                     const std::string& nodes = R"([{"name":"tri","mesh":0}])",
                     const std::string& sceneNodes = "[0]", int indexCount = 3) {
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":)" + sceneNodes +
           R"(}],"nodes":)" + nodes + R"(,
      "meshes":[{"name":"m","primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0}]}],
      "materials":[{"name":"red","pbrMetallicRoughness":{"baseColorFactor":[1,0,0,1]}}],
      "buffers":[{"uri":")" +
           bufferUri + R"(","byteLength":)" + std::to_string(byteLength) + R"(}],
      "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":8}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
                   {"bufferView":1,"componentType":5123,"count":)" +
           std::to_string(indexCount) + R"(,"type":"SCALAR"}]})";
}

std::filesystem::path writeGltf(const TempDir& dir, const std::string& json,
                                const std::string& name = "scene.gltf") {
    return hlod::test::writeFile(dir / name, json);
}

std::string dataUri(const std::vector<unsigned char>& b) {
    return "data:application/octet-stream;base64," + base64(b);
}

ErrorCode importError(const std::filesystem::path& p, std::string* message = nullptr) {
    try {
        importScene({p});
    } catch (const Error& e) {
        if (message) *message = e.what();
        return e.code();
    }
    ADD_FAILURE() << "expected an error for " << p;
    return ErrorCode::Io;
}

} // namespace

TEST(GltfImporter, ReadsOneTriangleWithItsMaterialColour) {
    TempDir dir;
    const auto b = triangleBuffer();
    const Scene s = importScene({writeGltf(dir, gltfJson(dataUri(b), b.size()))});
    ASSERT_EQ(s.instances.size(), 1u);
    const Mesh& m = s.meshes[s.instances[0].mesh];
    EXPECT_EQ(m.triangleCount(), 1u);
    EXPECT_EQ(m.positions[1], glm::vec3(1, 0, 0));
    // Counter-clockwise in the XY plane: the computed normal is +Z.
    EXPECT_NEAR(m.normals[0].z, 1.0f, 1e-6f);
    EXPECT_EQ(s.materials[m.material].name, "red");
    EXPECT_EQ(s.materials[m.material].baseColor, glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(s.nodes[s.instances[0].node].name, "tri");
}

TEST(GltfImporter, ExternalBufferInsideTheFolderIsRead) {
    TempDir dir;
    const auto b = triangleBuffer();
    hlod::test::writeFile(dir / "tri.bin", std::string(b.begin(), b.end()));
    const Scene s = importScene({writeGltf(dir, gltfJson("tri.bin", b.size()))});
    EXPECT_EQ(s.stats().triangles, 1u);
}

TEST(GltfImporter, ExternalUriEscapingTheFolderIsRefused) {
    TempDir outer;
    std::filesystem::create_directories(outer / "scene");
    const auto b = triangleBuffer();
    hlod::test::writeFile(outer / "secret.bin", std::string(b.begin(), b.end()));
    const auto file =
        hlod::test::writeFile(outer / "scene" / "s.gltf", gltfJson("../secret.bin", b.size()));
    std::string msg;
    EXPECT_EQ(importError(file, &msg), ErrorCode::UnsafePath);
    EXPECT_NE(msg.find("s.gltf"), std::string::npos) << msg;
    const auto abs =
        hlod::test::writeFile(outer / "scene" / "a.gltf", gltfJson("/etc/passwd", b.size()));
    EXPECT_EQ(importError(abs), ErrorCode::UnsafePath);
}

TEST(GltfImporter, IndexOutOfRangeIsMalformed) {
    TempDir dir;
    const auto b = triangleBuffer(0, 1, 7); // only 3 vertices exist
    std::string msg;
    EXPECT_EQ(importError(writeGltf(dir, gltfJson(dataUri(b), b.size())), &msg),
              ErrorCode::Malformed);
    EXPECT_NE(msg.find("index 7 out of range"), std::string::npos) << msg;
}

TEST(GltfImporter, AccessorReadingPastItsBufferViewIsMalformed) {
    TempDir dir;
    const auto b = triangleBuffer();
    // 5 uint16 indices need 10 bytes; the view has 8.
    EXPECT_EQ(
        importError(writeGltf(dir, gltfJson(dataUri(b), b.size(), R"([{"mesh":0}])", "[0]", 5))),
        ErrorCode::Malformed);
}

TEST(GltfImporter, NodeCycleIsMalformed) {
    TempDir dir;
    const auto b = triangleBuffer();
    const std::string nodes = R"([{"mesh":0,"children":[1]},{"children":[0]}])";
    std::string msg;
    EXPECT_EQ(importError(writeGltf(dir, gltfJson(dataUri(b), b.size(), nodes)), &msg),
              ErrorCode::Malformed);
    EXPECT_NE(msg.find("reached twice"), std::string::npos) << msg;
}

TEST(GltfImporter, InfinitePositionIsMalformed) {
    TempDir dir;
    const auto b = triangleBuffer(0, 1, 2, std::numeric_limits<float>::infinity());
    EXPECT_EQ(importError(writeGltf(dir, gltfJson(dataUri(b), b.size()))), ErrorCode::Malformed);
}

TEST(GltfImporter, BadJsonAndTruncatedGlbAreMalformed) {
    TempDir dir;
    EXPECT_EQ(importError(hlod::test::writeFile(dir / "bad.gltf", "{\"asset\": [")),
              ErrorCode::Malformed);
    // A GLB header that promises 1000 bytes but stops after 20.
    std::string glb("glTF\x02\x00\x00\x00\xe8\x03\x00\x00\x10\x00\x00\x00JSON", 20);
    std::string msg;
    EXPECT_EQ(importError(hlod::test::writeFile(dir / "cut.glb", glb), &msg), ErrorCode::Malformed);
    EXPECT_NE(msg.find("cut.glb"), std::string::npos);
}

TEST(GltfImporter, RealEngineSharesMeshesAcrossNodes) {
    const Scene s =
        importScene({hlod::test::dataDir() / "scenes/engine-2cylinder/2CylinderEngine.glb"});
    const SceneStats st = s.stats();
    // SOURCE.txt: 82 nodes, 34 primitives, 67 instances... of 29 meshes; 75,730 unique and
    // 121,496 instanced triangles. Our root adds one node; each primitive is one mesh.
    EXPECT_EQ(st.nodes, 83u);
    EXPECT_EQ(st.meshes, 34u);
    EXPECT_EQ(st.uniqueTriangles, 75730u);
    EXPECT_EQ(st.triangles, 121496u);
    EXPECT_GT(st.instances, 67u); // multi-primitive meshes yield one instance per primitive
}

TEST(GltfImporter, RealRoomKeepsItsSeventeenMeshes) {
    const Scene s = importScene({hlod::test::dataDir() / "scenes/godot-room/room.glb"});
    const SceneStats st = s.stats();
    EXPECT_EQ(st.instances, 17u); // SOURCE.txt: 17 nodes, 17 meshes (no dedup on our side)
    EXPECT_EQ(st.triangles, 63720u);
}
