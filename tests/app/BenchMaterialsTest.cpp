// `hlod bench` draws materials as engines do (issue 28): a one-sided surface seen from behind
// is culled, a double-sided one is drawn, and emission is added after lighting. Frames of a
// hand-made glTF scene from a fixed camera; the Original's frame is read back from the
// side-by-side image (Image.h composeGrid: one tile at (8, height - 8 - tile height)).
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include <nlohmann/json.hpp>
#include <stb_image.h>

#include "RunCli.h"

using hlod::test::runCli;
namespace fs = std::filesystem;

namespace {

struct TempDir {
    fs::path path;
    TempDir() {
        std::random_device rd;
        path = fs::temp_directory_path() / ("hlod-bench-mat-" + std::to_string(rd()));
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

// Three unit quads in the plane z = 0 at x = -1.5, 0, 1.5. The camera looks along +Z from
// z = -4, so world +X is on the left of the image:
//   x = +1.5 (image left):   front face +Z (seen from behind), grey, doubleSided
//   x =  0   (image centre): front face -Z (towards the camera), black, emitting (1, 0, 0)
//   x = -1.5 (image right):  front face +Z (seen from behind), grey, one-sided
fs::path writeScene(const fs::path& dir) {
    std::vector<float> positions, normals;
    std::vector<std::uint16_t> indices;
    const float xs[3] = {1.5f, 0.0f, -1.5f};
    for (int q = 0; q < 3; ++q) {
        const float nz = q == 1 ? -1.0f : 1.0f;
        for (auto [x, y] : {std::pair{-0.5f, -0.5f}, {0.5f, -0.5f}, {0.5f, 0.5f}, {-0.5f, 0.5f}}) {
            positions.insert(positions.end(), {xs[q] + x, y, 0.0f});
            normals.insert(normals.end(), {0.0f, 0.0f, nz});
        }
        // Each primitive indexes its own 4 vertices: counter-clockwise seen from +Z, the centre
        // quad reversed to face -Z.
        if (q == 1)
            indices.insert(indices.end(), {0, 2, 1, 0, 3, 2});
        else
            indices.insert(indices.end(), {0, 1, 2, 0, 2, 3});
    }
    std::ofstream bin(dir / "quads.bin", std::ios::binary);
    bin.write(reinterpret_cast<const char*>(positions.data()), 144);
    bin.write(reinterpret_cast<const char*>(normals.data()), 144);
    bin.write(reinterpret_cast<const char*>(indices.data()), 36);
    bin.close();
    using nlohmann::json;
    json g;
    g["asset"] = {{"version", "2.0"}};
    g["buffers"] = {{{"uri", "quads.bin"}, {"byteLength", 324}}};
    g["bufferViews"] = {{{"buffer", 0}, {"byteLength", 144}},
                        {{"buffer", 0}, {"byteOffset", 144}, {"byteLength", 144}},
                        {{"buffer", 0}, {"byteOffset", 288}, {"byteLength", 36}}};
    json accessors = json::array(), meshes = json::array(), nodes = json::array();
    const char* names[3] = {"twoSided", "emitter", "oneSided"};
    for (int q = 0; q < 3; ++q) {
        accessors.push_back({{"bufferView", 0},
                             {"byteOffset", 48 * q},
                             {"componentType", 5126},
                             {"count", 4},
                             {"type", "VEC3"},
                             {"min", {xs[q] - 0.5, -0.5, 0}},
                             {"max", {xs[q] + 0.5, 0.5, 0}}});
        accessors.push_back({{"bufferView", 1},
                             {"byteOffset", 48 * q},
                             {"componentType", 5126},
                             {"count", 4},
                             {"type", "VEC3"}});
        accessors.push_back({{"bufferView", 2},
                             {"byteOffset", 12 * q},
                             {"componentType", 5123},
                             {"count", 6},
                             {"type", "SCALAR"}});
        meshes.push_back({{"primitives",
                           {{{"attributes", {{"POSITION", 3 * q}, {"NORMAL", 3 * q + 1}}},
                             {"indices", 3 * q + 2},
                             {"material", q}}}}});
        nodes.push_back({{"name", names[q]}, {"mesh", q}});
    }
    g["accessors"] = accessors;
    g["meshes"] = meshes;
    g["nodes"] = nodes;
    g["scenes"] = {{{"nodes", {0, 1, 2}}}};
    g["scene"] = 0;
    const json grey = {{"baseColorFactor", {0.5, 0.5, 0.5, 1}}, {"metallicFactor", 0}};
    g["materials"] = {
        {{"pbrMetallicRoughness", grey}, {"doubleSided", true}},
        {{"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}, {"metallicFactor", 0}}},
         {"emissiveFactor", {1, 0, 0}}},
        {{"pbrMetallicRoughness", grey}}};
    std::ofstream(dir / "quads.gltf") << g.dump();
    std::ofstream(dir / "path.json") << R"({"fov_deg": 60, "up": [0, 1, 0], "keys": [
        {"t": 0, "eye": [0, 0, -4], "target": [0, 0, 0]},
        {"t": 1, "eye": [0, 0, -4], "target": [0, 0, 0]}]})";
    return dir / "quads.gltf";
}

} // namespace

TEST(BenchMaterials, BackFacesAreCulledUnlessDoubleSidedAndEmissionIsAdded) {
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display) GTEST_SKIP() << "needs an X display (run under xvfb-run)";
    TempDir dir;
    const fs::path scene = writeScene(dir.path);
    const fs::path out = dir.path / "bench";
    for (const char* shading : {"textured", "colour", "geometry"}) {
        const auto r = runCli({"bench", scene.string(), "--out", out.string(), "--frames", "2",
                               "--size", "96x64", "--configs", "original", "--shading", shading,
                               "--path", (dir.path / "path.json").string()},
                              300, 4ull << 30);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        int w = 0, h = 0, n = 0;
        unsigned char* image =
            stbi_load((out / "side_by_side_00.0s.png").string().c_str(), &w, &h, &n, 3);
        ASSERT_NE(image, nullptr);
        // The frame's row 32 at 28 %, 50 % and 72 % of its width.
        auto at = [&](double share) {
            const int x = 8 + static_cast<int>(share * 96), y = h - 8 - 64 + 32;
            const unsigned char* p = image + 3 * (static_cast<std::size_t>(y) * w + x);
            return std::array<int, 3>{p[0], p[1], p[2]};
        };
        const std::array<int, 3> background{237, 240, 245}; // the renderer's clear colour
        const auto twoSided = at(0.28), emitter = at(0.5), oneSided = at(0.72);
        stbi_image_free(image);
        EXPECT_EQ(oneSided, background) << shading << ": a back face was drawn";
        EXPECT_NE(twoSided, background) << shading << ": a double-sided back face was culled";
        if (std::string(shading) != "geometry") {
            // Black lit, plus emission (1, 0, 0): pure red.
            EXPECT_GE(emitter[0], 250) << shading;
            EXPECT_LE(emitter[1], 5) << shading;
            EXPECT_LE(emitter[2], 5) << shading;
        }
    }
}
