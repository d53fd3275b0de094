// A small glTF scene of ours that exercises every material property HLOD Studio keeps
// (issue 28), laid out like the Khronos sample AlphaBlendModeTest: a row of unit quads in the
// XY plane (front face +Z, 1.5 m apart along X), each with its own material and mesh, all
// sampling one 8x8 texture whose alpha rises left to right (column x has alpha x/7: 0, 36,
// 73, ... 255), so a cut-off shows as a vertical edge. Written as .gltf + .bin + PNG files, so
// the package keeps the textures (embedded images fall back to their mean, TileContent.h).
//
// Quads and materials, in node order (name = material name = node name):
//   Opaque         OPAQUE, textured (its alpha ignored)
//   Blend          BLEND, textured
//   MaskLow        MASK, alphaCutoff 0.25, textured
//   MaskDefault    MASK, cut-off not written (0.5), textured
//   MaskHigh       MASK, alphaCutoff 0.75, textured
//   BlendFactor    BLEND by baseColorFactor alpha 0.5, untextured
//   DoubleSided    OPAQUE, doubleSided, untextured
//   Emissive       emissiveFactor (1, 0.5, 0.25) x emissiveTexture glow.png, textured
//   EmissiveStrong emissiveFactor (1, 1, 1) x KHR_materials_emissive_strength 3, untextured
#pragma once

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "pipeline/io/TextureImage.h"
#include "pipeline/scene/RgbaImage.h"

namespace hlod::test {

inline const std::vector<std::string>& materialsSceneNames() {
    static const std::vector<std::string> names{"Opaque",      "Blend",    "MaskLow",
                                                "MaskDefault", "MaskHigh", "BlendFactor",
                                                "DoubleSided", "Emissive", "EmissiveStrong"};
    return names;
}

// Writes the scene into `folder`; returns the .gltf file.
inline std::filesystem::path writeMaterialsScene(const std::filesystem::path& folder) {
    namespace fs = std::filesystem;
    auto writeBytes = [&](const std::string& name, const void* data, std::size_t size) {
        std::ofstream out(folder / name, std::ios::binary);
        out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
    };
    RgbaImage alpha(8, 8), glow(8, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const bool orange = (x + y) % 2 == 0;
            alpha.set(x, y, orange ? glm::u8vec4(230, 120, 30, 0) : glm::u8vec4(40, 90, 200, 0));
            alpha.set(x, y, glm::u8vec4(glm::u8vec3(alpha.at(x, y)), (x * 255 + 3) / 7));
            glow.set(x, y, glm::u8vec4(255, 255, y < 4 ? 255 : 64, 255));
        }
    const EncodedImage alphaPng = encodePng(alpha), glowPng = encodePng(glow);
    writeBytes("alpha.png", alphaPng.bytes.data(), alphaPng.bytes.size());
    writeBytes("glow.png", glowPng.bytes.data(), glowPng.bytes.size());

    // One quad, shared by every mesh: positions, normals, uvs (v = 0 at the image top), indices.
    const float positions[] = {-0.5f, -0.5f, 0, 0.5f, -0.5f, 0, 0.5f, 0.5f, 0, -0.5f, 0.5f, 0};
    const float normals[] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    const float uvs[] = {0, 1, 1, 1, 1, 0, 0, 0};
    const std::uint16_t indices[] = {0, 1, 2, 0, 2, 3};
    std::vector<std::uint8_t> bin(sizeof positions + sizeof normals + sizeof uvs + sizeof indices);
    std::memcpy(bin.data(), positions, 48);
    std::memcpy(bin.data() + 48, normals, 48);
    std::memcpy(bin.data() + 96, uvs, 32);
    std::memcpy(bin.data() + 128, indices, 12);
    writeBytes("materials.bin", bin.data(), bin.size());

    using nlohmann::json;
    json g;
    g["asset"] = {{"version", "2.0"}, {"generator", "HLOD Studio tests (MaterialsScene.h)"}};
    g["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    g["buffers"] = {{{"uri", "materials.bin"}, {"byteLength", bin.size()}}};
    g["bufferViews"] = {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
                        {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 48}},
                        {{"buffer", 0}, {"byteOffset", 96}, {"byteLength", 32}},
                        {{"buffer", 0}, {"byteOffset", 128}, {"byteLength", 12}}};
    g["accessors"] = {
        {{"bufferView", 0},
         {"componentType", 5126},
         {"count", 4},
         {"type", "VEC3"},
         {"min", {-0.5, -0.5, 0}},
         {"max", {0.5, 0.5, 0}}},
        {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
        {{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
        {{"bufferView", 3}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}};
    g["images"] = {{{"uri", "alpha.png"}}, {{"uri", "glow.png"}}};
    g["samplers"] = {{{"magFilter", 9728}, {"minFilter", 9728}}};
    g["textures"] = {{{"sampler", 0}, {"source", 0}}, {{"sampler", 0}, {"source", 1}}};
    auto textured = [](json pbr = json::object()) {
        pbr["baseColorTexture"] = {{"index", 0}};
        pbr["metallicFactor"] = 0;
        return pbr;
    };
    const json plain = {{"metallicFactor", 0}};
    g["materials"] = {
        {{"name", "Opaque"}, {"pbrMetallicRoughness", textured()}},
        {{"name", "Blend"}, {"pbrMetallicRoughness", textured()}, {"alphaMode", "BLEND"}},
        {{"name", "MaskLow"},
         {"pbrMetallicRoughness", textured()},
         {"alphaMode", "MASK"},
         {"alphaCutoff", 0.25}},
        {{"name", "MaskDefault"}, {"pbrMetallicRoughness", textured()}, {"alphaMode", "MASK"}},
        {{"name", "MaskHigh"},
         {"pbrMetallicRoughness", textured()},
         {"alphaMode", "MASK"},
         {"alphaCutoff", 0.75}},
        {{"name", "BlendFactor"},
         {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 0.5}}, {"metallicFactor", 0}}},
         {"alphaMode", "BLEND"}},
        {{"name", "DoubleSided"}, {"pbrMetallicRoughness", plain}, {"doubleSided", true}},
        {{"name", "Emissive"},
         {"pbrMetallicRoughness", textured()},
         {"emissiveFactor", {1, 0.5, 0.25}},
         {"emissiveTexture", {{"index", 1}}}},
        {{"name", "EmissiveStrong"},
         {"pbrMetallicRoughness", plain},
         {"emissiveFactor", {1, 1, 1}},
         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 3}}}}}}};
    const std::vector<std::string>& names = materialsSceneNames();
    json meshes = json::array(), nodes = json::array(), roots = json::array();
    for (std::size_t i = 0; i < names.size(); ++i) {
        meshes.push_back({{"name", names[i]},
                          {"primitives",
                           {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}},
                             {"indices", 3},
                             {"material", i}}}}});
        nodes.push_back({{"name", names[i]},
                         {"mesh", i},
                         {"translation", {1.5 * static_cast<double>(i), 0, 0}}});
        roots.push_back(i);
    }
    g["meshes"] = meshes;
    g["nodes"] = nodes;
    g["scenes"] = {{{"nodes", roots}}};
    g["scene"] = 0;
    const fs::path file = folder / "materials.gltf";
    std::ofstream(file) << g.dump(1);
    return file;
}

} // namespace hlod::test
