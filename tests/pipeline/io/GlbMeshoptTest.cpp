// The compressed GLB (KHR_mesh_quantization + EXT_meshopt_compression) read back through our
// own importer: positions within half a grid step of what was written, normals, uvs and colours
// within their encodings' precision, the same triangles and instances; and the importer's
// errors on broken compressed files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "TestUtil.h"
#include "pipeline/io/GlbMeshopt.h"
#include "pipeline/io/GlbWriter.h"
#include "pipeline/io/GltfMeshopt.h"
#include "pipeline/io/Import.h"

using namespace hlod;

namespace {

// A 2 x 1 quad on z = 0 whose corners sit off any power-of-two grid, uvs beyond [0, 1].
struct Quad {
    std::vector<glm::vec3> positions{
        {0.013f, 0.0f, 0.0f}, {2.0f, 0.0071f, 0.0f}, {2.0f, 1.0f, 0.00031f}, {0.0f, 1.0f, 0.0f}};
    std::vector<glm::vec3> normals{4, glm::normalize(glm::vec3(0.1f, 0.2f, 1.0f))};
    std::vector<glm::vec2> uvs{{0.0f, 0.0f}, {3.25f, 0.0f}, {3.25f, 1.7f}, {0.0f, 1.7f}};
    std::vector<glm::u8vec4> colors{4, glm::u8vec4(255, 128, 7, 255)};
    std::vector<std::uint32_t> indices{0, 1, 2, 0, 2, 3};
    GlbMesh view() const {
        GlbMesh m;
        m.name = "quad";
        m.positions = positions;
        m.normals = normals;
        m.uvs = uvs;
        m.colors = colors;
        m.indices = indices;
        m.imageUri = "textures/t.png";
        m.positionStep = 0.001; // rounds down to 2^-10 m
        return m;
    }
};

// The quad under two nodes: as it is, and turned 90 degrees about y, scaled 3x, far away.
GlbScene twoQuads(const Quad& q, GlbCompression compression) {
    GlbScene s;
    s.compression = compression;
    s.meshes.push_back(q.view());
    GlbNode a;
    a.name = "a";
    a.mesh = 0;
    GlbNode b = a;
    b.name = "b";
    b.trs.translation = {1000.0, 5.0, -2.0};
    b.trs.rotation = glm::angleAxis(glm::radians(90.0), glm::dvec3(0, 1, 0));
    b.trs.scale = glm::dvec3(3.0);
    s.nodes = {a, b};
    return s;
}

Scene roundTrip(const std::vector<std::uint8_t>& bytes, const test::TempDir& dir) {
    std::ofstream(dir / "q.glb", std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return importGltf(dir / "q.glb", ImportOptions{});
}

glm::dvec3 worldOf(const Scene& s, Id instance, std::size_t v) {
    const MeshInstance& inst = s.instances[instance];
    return glm::dvec3(s.nodes[inst.node].world *
                      glm::dvec4(glm::dvec3(s.meshes[inst.mesh].positions[v]), 1.0));
}

} // namespace

TEST(GlbMeshopt, GridStepRoundsDownToAPowerOfTwoButSpansTheExtentIn16Bits) {
    EXPECT_EQ(positionGridStep(10.0, 0.001), 0.0009765625);  // 2^-10 <= 0.001
    EXPECT_EQ(positionGridStep(100.0, 0.0001), 0.001953125); // 100 / 65535 -> 2^-9
    EXPECT_EQ(positionGridStep(0.0, 0.0), 1.0);              // one point: any grid
    const QuantizedPositions q = quantizePositions(Quad{}.positions, 0.001);
    EXPECT_EQ(q.step, 0.0009765625);
    EXPECT_EQ(q.max.x, 2048); // x spans 0 .. 2 (the fourth corner), 2 / 2^-10
    for (std::size_t i = 0; i < 4; ++i) {
        for (int a = 0; a < 3; ++a) {
            const double back = q.offset[a] + q.step * q.values[i * 4 + a];
            EXPECT_LE(std::abs(back - Quad{}.positions[i][a]), q.step / 2 + 1e-9);
        }
    }
}

TEST(GlbMeshopt, CompressedSceneDeclaresBothExtensionsRequired) {
    const Quad q;
    const std::vector<std::uint8_t> bytes = encodeGlb(twoQuads(q, GlbCompression::Meshopt));
    const nlohmann::json j = nlohmann::json::parse(splitGlb(bytes, "q.glb").json);
    EXPECT_EQ(j["extensionsRequired"],
              nlohmann::json({"EXT_meshopt_compression", "KHR_mesh_quantization"}));
    EXPECT_EQ(j["meshes"].size(), 1u); // one mesh, referenced by both nodes
    EXPECT_EQ(j["buffers"][1]["extensions"]["EXT_meshopt_compression"]["fallback"], true);
    EXPECT_EQ(j["accessors"][0]["componentType"], 5123); // POSITION as unsigned short
    // The plain encoding requires nothing.
    const auto plain = encodeGlb(twoQuads(q, GlbCompression::None));
    EXPECT_FALSE(nlohmann::json::parse(splitGlb(plain, "q.glb").json).contains("extensionsUsed"));
}

TEST(GlbMeshopt, CompressedSceneReadsBackWithinItsQuantisation) {
    const Quad q;
    test::TempDir dir;
    const Scene plain = roundTrip(encodeGlb(twoQuads(q, GlbCompression::None)), dir);
    const Scene packed = roundTrip(encodeGlb(twoQuads(q, GlbCompression::Meshopt)), dir);
    ASSERT_EQ(packed.instances.size(), 2u);
    ASSERT_EQ(packed.meshes.size(), 1u); // still instanced
    EXPECT_EQ(packed.meshes[0].indices, q.indices);
    const double step = 0.0009765625;
    for (Id inst = 0; inst < 2; ++inst) {
        const double scale = inst == 0 ? 1.0 : 3.0; // node b scales the grid too
        for (std::size_t v = 0; v < 4; ++v) {
            const glm::dvec3 d = worldOf(packed, inst, v) - worldOf(plain, inst, v);
            for (int a = 0; a < 3; ++a)
                EXPECT_LE(std::abs(d[a]), scale * step / 2 + 1e-6) << inst << " " << v;
        }
    }
    const Mesh& m = packed.meshes[0];
    for (std::size_t v = 0; v < 4; ++v) {
        // 8-bit octahedral normals: within about a degree.
        EXPECT_GT(glm::dot(glm::normalize(m.normals[v]), q.normals[v]), 0.9997f);
        EXPECT_NEAR(m.uvs[v].x, q.uvs[v].x, 1e-4); // 16-bit mantissa: 3.25 -> 2^-14
        EXPECT_NEAR(m.uvs[v].y, q.uvs[v].y, 1e-4);
        EXPECT_NEAR(m.colors[v].g, 128.0f / 255.0f, 1e-6); // colours are not touched
    }
}

// Buffer 0 must be used by some core buffer view, or validators that do not know
// EXT_meshopt_compression report it "may be unused" (GlbWriter.h): without an embedded image,
// the stream smallest once decoded is stored plain there.
TEST(GlbMeshopt, BufferZeroHoldsTheSmallestStreamPlainWhenNothingElseIsThere) {
    const Quad q;
    // The quad: indices 6 x 2 = 12 bytes, the smallest (normals, colours 16, positions, uvs 32).
    const nlohmann::json quad = nlohmann::json::parse(
        splitGlb(encodeGlb(twoQuads(q, GlbCompression::Meshopt)), "q.glb").json);
    const int indexView =
        quad["accessors"][quad["meshes"][0]["primitives"][0]["indices"].get<int>()]["bufferView"];
    int plainViews = 0;
    for (std::size_t v = 0; v < quad["bufferViews"].size(); ++v) {
        const nlohmann::json& view = quad["bufferViews"][v];
        const bool plain = !view.contains("extensions");
        plainViews += plain;
        EXPECT_EQ(view["buffer"], plain ? 0 : 1);
        EXPECT_EQ(plain, static_cast<int>(v) == indexView) << v;
    }
    EXPECT_EQ(plainViews, 1);

    // Three copies of its triangles (36 bytes): now the normals (16 bytes, before the colours)
    // are stored plain, as the octahedral filter decodes them; they read back as compressed ones
    // do.
    Quad tripled;
    for (int k = 0; k < 2; ++k)
        tripled.indices.insert(tripled.indices.end(), q.indices.begin(), q.indices.end());
    const std::vector<std::uint8_t> bytes = encodeGlb(twoQuads(tripled, GlbCompression::Meshopt));
    const nlohmann::json j = nlohmann::json::parse(splitGlb(bytes, "q.glb").json);
    const int normalView =
        j["accessors"][j["meshes"][0]["primitives"][0]["attributes"]["NORMAL"].get<int>()]
         ["bufferView"];
    EXPECT_FALSE(j["bufferViews"][normalView].contains("extensions"));
    EXPECT_EQ(j["bufferViews"][normalView]["byteLength"], 16);
    test::TempDir dir;
    const Scene packed = roundTrip(bytes, dir);
    ASSERT_EQ(packed.meshes.size(), 1u);
    for (std::size_t v = 0; v < 4; ++v)
        EXPECT_GT(glm::dot(glm::normalize(packed.meshes[0].normals[v]), q.normals[v]), 0.9997f);
    EXPECT_EQ(packed.meshes[0].indices.size(), 18u);
}

TEST(GlbMeshopt, CorruptCompressedDataIsAnErrorNamingTheFile) {
    const Quad q;
    std::vector<std::uint8_t> bytes = encodeGlb(twoQuads(q, GlbCompression::Meshopt));
    GlbChunks c = splitGlb(bytes, "q.glb");
    for (std::size_t i = 0; i < c.bin.size(); ++i)
        c.bin[i] = static_cast<std::uint8_t>(0xA5 ^ i); // not a meshopt stream any more
    test::TempDir dir;
    const std::string problem = test::problemOf([&] { roundTrip(makeGlb(c.json, c.bin), dir); });
    EXPECT_NE(problem.find("q.glb"), std::string::npos) << problem;
    EXPECT_NE(problem.find("meshopt data is corrupt"), std::string::npos) << problem;
}

TEST(GlbMeshopt, MissingExternalBufferIsNamed) {
    // A gltfpack-style .gltf whose compressed buffer file is not there.
    test::TempDir dir;
    test::writeFile(dir / "scene.gltf", R"({"asset":{"version":"2.0"},
        "extensionsUsed":["EXT_meshopt_compression"],"extensionsRequired":["EXT_meshopt_compression"],
        "buffers":[{"uri":"scene.bin","byteLength":8},
                   {"byteLength":48,"extensions":{"EXT_meshopt_compression":{"fallback":true}}}],
        "bufferViews":[{"buffer":1,"byteLength":48,"byteStride":12,"extensions":{
            "EXT_meshopt_compression":{"buffer":0,"byteLength":8,"byteStride":12,"count":4,
                                       "mode":"ATTRIBUTES"}}}]})");
    const std::string problem =
        test::problemOf([&] { importGltf(dir / "scene.gltf", ImportOptions{}); });
    EXPECT_NE(problem.find("buffer 0 'scene.bin' is missing"), std::string::npos) << problem;
}

TEST(GlbMeshopt, GltfpackStyleSceneWithExternalBufferImports) {
    // The same compressed scene as .gltf + .bin, as gltfpack writes it: the importer reads the
    // buffer next to the scene and records it as a file the scene pulled in.
    const Quad q;
    const GlbChunks c = splitGlb(encodeGlb(twoQuads(q, GlbCompression::Meshopt)), "q.glb");
    nlohmann::json j = nlohmann::json::parse(c.json);
    j["buffers"][0]["uri"] = "q.bin";
    test::TempDir dir;
    test::writeFile(dir / "q.gltf", j.dump());
    test::writeFile(dir / "q.bin", std::string(c.bin.begin(), c.bin.end()));
    const Scene s = importGltf(dir / "q.gltf", ImportOptions{});
    EXPECT_EQ(s.instances.size(), 2u);
    EXPECT_EQ(s.meshes.at(0).indices, q.indices);
    ASSERT_EQ(s.referencedFiles.size(), 1u);
    EXPECT_EQ(s.referencedFiles[0].filename(), "q.bin");
}

TEST(GlbMeshopt, GridOriginIsAShortDecimalThatStillSpansTheBoundsIn16Bits) {
    // 2^-10 m asked over 3 m: 16 bits leave 61 m of slack, so the origin rounds to whole metres.
    const PositionGrid g = positionGrid(glm::dvec3(-33.83799743652344, 0.013, 1.5),
                                        glm::dvec3(-30.9, 2.0, 4.5), 0.001);
    EXPECT_EQ(g.step, 0.0009765625);
    EXPECT_EQ(g.offset, glm::dvec3(-34.0, 0.0, 1.0));
    // Finest grid: hardly any slack; the origin stays at or below the bounds and spans them.
    const glm::dvec3 lo(0.123456789, -7.654321, 1000.000123), hi = lo + glm::dvec3(100.0);
    const PositionGrid f = positionGrid(lo, hi, 0.0);
    EXPECT_EQ(f.step, positionGridStep(100.0, 0.0));
    for (int a = 0; a < 3; ++a) {
        EXPECT_LE(f.offset[a], lo[a]);
        EXPECT_LE(hi[a] - f.offset[a], 65535.0 * f.step);
    }
}

namespace {

// Each triangle rotated to start at its smallest corner.
std::vector<std::uint32_t> rotated(std::vector<std::uint32_t> indices) {
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
        while (indices[t] > indices[t + 1] || indices[t] > indices[t + 2])
            std::rotate(indices.begin() + long(t), indices.begin() + long(t) + 1,
                        indices.begin() + long(t) + 3);
    return indices;
}

} // namespace

TEST(GlbMeshopt, MeshesSharingCompressedStreamsReadBackWithinTheirQuantisation) {
    // Three meshes of different sizes and placements in one file: their positions, normals,
    // uvs and indices each one compressed view, every accessor a range of it.
    const Quad q;
    std::vector<glm::vec3> far = q.positions, big = q.positions;
    for (glm::vec3& p : far)
        p += glm::vec3(-123.4f, 56.7f, 8.9f);
    for (glm::vec3& p : big)
        p *= 37.0f;
    const std::vector<std::uint32_t> reversed{0, 2, 1, 0, 3, 2};
    GlbScene s = twoQuads(q, GlbCompression::Meshopt);
    s.meshes.push_back(q.view());
    s.meshes.back().positions = far;
    s.meshes.back().indices = reversed;
    s.meshes.push_back(q.view());
    s.meshes.back().positions = big;
    s.meshes.back().positionStep = 0.01;
    for (int i : {1, 2}) {
        GlbNode n;
        n.mesh = i;
        s.nodes.push_back(n);
    }
    const std::vector<std::uint8_t> bytes = encodeGlb(s);
    const nlohmann::json j = nlohmann::json::parse(splitGlb(bytes, "q.glb").json);
    // Positions, normals, uvs, colours, indices, and the plain copy of the smallest accessor.
    EXPECT_EQ(j["bufferViews"].size(), 6u);
    test::TempDir dir;
    const Scene packed = roundTrip(bytes, dir);
    ASSERT_EQ(packed.instances.size(), 4u);
    ASSERT_EQ(packed.meshes.size(), 3u);
    const std::vector<const std::vector<glm::vec3>*> positions{&q.positions, &far, &big};
    const double steps[] = {0.0009765625, 0.0009765625, 0.0078125};
    for (Id inst = 0; inst < 4; ++inst) {
        if (inst == 1) continue; // the turned copy: CompressedSceneReadsBackWithinItsQuantisation
        const Id mesh = packed.instances[inst].mesh;
        const std::size_t k = inst == 0 ? 0 : inst - 1;
        // The index codec may rotate a triangle's corners (never its winding).
        EXPECT_EQ(rotated(packed.meshes[mesh].indices), rotated(k == 1 ? reversed : q.indices));
        for (std::size_t v = 0; v < 4; ++v) {
            const glm::dvec3 d = worldOf(packed, inst, v) - glm::dvec3((*positions[k])[v]);
            for (int a = 0; a < 3; ++a)
                EXPECT_LE(std::abs(d[a]), steps[k] / 2 + 1e-5) << inst << " " << v;
            EXPECT_NEAR(packed.meshes[mesh].uvs[v].x, q.uvs[v].x, 1e-4);
            EXPECT_GT(glm::dot(glm::normalize(packed.meshes[mesh].normals[v]), q.normals[v]),
                      0.9997f);
        }
    }
}
