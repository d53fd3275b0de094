// Test helpers: tiny scene files that expand into a great deal of work or memory when read
// naively (issue 22, pipeline/io/ImportLimits.h). Each is generated, a few hundred bytes to a
// few kilobytes; the tests check that the import budget refuses or coarsens them early.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/pipeline/TestUtil.h"

namespace hlod::test {

// COLLADA: node n0 holds one triangle, node n(i) places n(i-1) twice through <instance_node>;
// the visual scene places n(levels): 2^levels triangles, 2^(levels+2) nodes once expanded.
// With `cycle`, n0 also places n(levels), which assimp would follow until its stack ends.
inline std::filesystem::path writeInstancingDae(const std::filesystem::path& file, int levels,
                                                bool cycle = false) {
    std::string nodes = "<node id=\"n0\" name=\"n0\"><instance_geometry url=\"#tri\"/>";
    if (cycle) nodes += "<instance_node url=\"#n" + std::to_string(levels) + "\"/>";
    nodes += "</node>\n";
    for (int i = 1; i <= levels; ++i) {
        const std::string below = "#n" + std::to_string(i - 1);
        nodes += "<node id=\"n" + std::to_string(i) + "\"><node><translate>1 0 0</translate>" +
                 "<instance_node url=\"" + below + "\"/></node><node><translate>0 1 0</translate>" +
                 "<instance_node url=\"" + below + "\"/></node></node>\n";
    }
    return writeFile(
        file,
        "<?xml version=\"1.0\"?>\n<COLLADA "
        "xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
        "<asset><unit meter=\"1\"/><up_axis>Z_UP</up_axis></asset>\n"
        "<library_geometries><geometry id=\"tri\"><mesh>\n"
        "<source id=\"p\"><float_array id=\"pa\" count=\"9\">0 0 0 1 0 0 0 1 0</float_array>\n"
        "<technique_common><accessor source=\"#pa\" count=\"3\" stride=\"3\"><param name=\"X\" "
        "type=\"float\"/><param name=\"Y\" type=\"float\"/><param name=\"Z\" "
        "type=\"float\"/></accessor></technique_common></source>\n"
        "<vertices id=\"v\"><input semantic=\"POSITION\" source=\"#p\"/></vertices>\n"
        "<triangles count=\"1\"><input semantic=\"VERTEX\" source=\"#v\" "
        "offset=\"0\"/><p>0 1 2</p></triangles>\n"
        "</mesh></geometry></library_geometries>\n<library_nodes>\n" +
            nodes +
            "</library_nodes>\n<library_visual_scenes><visual_scene id=\"s\"><node "
            "id=\"root\"><instance_node url=\"#n" +
            std::to_string(levels) +
            "\"/></node></visual_scene></library_visual_scenes>\n"
            "<scene><instance_visual_scene url=\"#s\"/></scene>\n</COLLADA>\n");
}

inline std::string base64(const std::vector<std::uint8_t>& bytes) {
    static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t n = (std::uint32_t(bytes[i]) << 16) |
                                (i + 1 < bytes.size() ? std::uint32_t(bytes[i + 1]) << 8 : 0) |
                                (i + 2 < bytes.size() ? std::uint32_t(bytes[i + 2]) : 0);
        out += abc[(n >> 18) & 63];
        out += abc[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? abc[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? abc[n & 63] : '=';
    }
    return out;
}

// glTF: one buffer of `triangles` triangles (non-indexed, 36 bytes each) and one mesh whose
// `primitives` primitives all read that same POSITION accessor, placed by `nodes` nodes. With
// `distinctMaterials` each primitive has a material of its own (so each is a mesh of its own).
// Stored naively: primitives x triangles triangles from a buffer of `triangles` x 36 bytes.
inline std::filesystem::path writeSharedAccessorGltf(const std::filesystem::path& file,
                                                     int triangles, int primitives, int nodes = 1,
                                                     bool distinctMaterials = false) {
    std::vector<std::uint8_t> buffer;
    const auto putFloat = [&](float f) {
        const auto* b = reinterpret_cast<const std::uint8_t*>(&f);
        buffer.insert(buffer.end(), b, b + 4);
    };
    for (int t = 0; t < triangles; ++t) {
        for (const float v : {0.f, 0.f, float(t), 1.f, 0.f, float(t), 0.f, 1.f, float(t)})
            putFloat(v);
    }
    nlohmann::json prims = nlohmann::json::array();
    nlohmann::json materials = nlohmann::json::array();
    for (int p = 0; p < primitives; ++p) {
        prims.push_back({{"attributes", {{"POSITION", 0}}}});
        if (distinctMaterials) {
            prims.back()["material"] = p;
            materials.push_back({{"name", "m" + std::to_string(p)}});
        }
    }
    nlohmann::json nodeList = nlohmann::json::array(), roots = nlohmann::json::array();
    for (int n = 0; n < nodes; ++n) {
        nodeList.push_back({{"mesh", 0}, {"translation", {0.0, 0.0, 2.0 * n}}});
        roots.push_back(n);
    }
    const float top = float(std::max(triangles - 1, 0));
    nlohmann::json doc = {{"asset", {{"version", "2.0"}}},
                          {"buffers",
                           {{{"byteLength", buffer.size()},
                             {"uri", "data:application/octet-stream;base64," + base64(buffer)}}}},
                          {"bufferViews", {{{"buffer", 0}, {"byteLength", buffer.size()}}}},
                          {"accessors",
                           {{{"bufferView", 0},
                             {"componentType", 5126},
                             {"count", 3 * triangles},
                             {"type", "VEC3"},
                             {"min", {0.0, 0.0, 0.0}},
                             {"max", {1.0, 1.0, top}}}}},
                          {"meshes", {{{"primitives", prims}}}},
                          {"nodes", nodeList},
                          {"scenes", {{{"nodes", roots}}}},
                          {"scene", 0}};
    if (distinctMaterials) doc["materials"] = materials;
    return writeFile(file, doc.dump());
}

// The first bytes of a PNG (signature, IHDR, one empty IDAT, IEND) declaring `width` x `height`
// RGBA texels: what an image reader sees before it allocates. CRCs are zero (stb_image does not
// check them; the header is all that is read before the size check).
inline std::vector<std::uint8_t> pngHeader(std::uint32_t width, std::uint32_t height) {
    std::vector<std::uint8_t> b = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
    const auto be32 = [&](std::uint32_t v) {
        for (int s = 24; s >= 0; s -= 8)
            b.push_back(static_cast<std::uint8_t>(v >> s));
    };
    const auto chunk = [&](const char* type, const std::vector<std::uint8_t>& data) {
        be32(static_cast<std::uint32_t>(data.size()));
        b.insert(b.end(), type, type + 4);
        b.insert(b.end(), data.begin(), data.end());
        be32(0);
    };
    std::vector<std::uint8_t> ihdr;
    for (std::uint32_t v : {width, height}) {
        for (int s = 24; s >= 0; s -= 8)
            ihdr.push_back(static_cast<std::uint8_t>(v >> s));
    }
    ihdr.insert(ihdr.end(), {8, 6, 0, 0, 0}); // 8 bit, RGBA, deflate, no filter, no interlace
    chunk("IHDR", ihdr);
    chunk("IDAT", {0x78, 0x9c, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01});
    chunk("IEND", {});
    return b;
}

// glTF: one triangle whose material's base colour texture is image `i` of `images` (embedded
// as data: URIs), one material and triangle-bearing node per image.
inline std::filesystem::path
writeTexturedGltf(const std::filesystem::path& file,
                  const std::vector<std::vector<std::uint8_t>>& images) {
    std::vector<std::uint8_t> buffer;
    for (const float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) {
        const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
        buffer.insert(buffer.end(), p, p + 4);
    }
    nlohmann::json imgs = nlohmann::json::array(), textures = nlohmann::json::array(),
                   materials = nlohmann::json::array(), meshes = nlohmann::json::array(),
                   nodes = nlohmann::json::array(), roots = nlohmann::json::array();
    for (std::size_t i = 0; i < images.size(); ++i) {
        imgs.push_back({{"uri", "data:image/png;base64," + base64(images[i])}});
        textures.push_back({{"source", i}});
        materials.push_back({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", i}}}}}});
        meshes.push_back({{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"material", i}}}}});
        nodes.push_back({{"mesh", i}});
        roots.push_back(i);
    }
    const nlohmann::json doc = {
        {"asset", {{"version", "2.0"}}},
        {"buffers",
         {{{"byteLength", buffer.size()},
           {"uri", "data:application/octet-stream;base64," + base64(buffer)}}}},
        {"bufferViews", {{{"buffer", 0}, {"byteLength", buffer.size()}}}},
        {"accessors",
         {{{"bufferView", 0},
           {"componentType", 5126},
           {"count", 3},
           {"type", "VEC3"},
           {"min", {0.0, 0.0, 0.0}},
           {"max", {1.0, 1.0, 0.0}}}}},
        {"images", imgs},
        {"textures", textures},
        {"materials", materials},
        {"meshes", meshes},
        {"nodes", nodes},
        {"scenes", {{{"nodes", roots}}}},
        {"scene", 0}};
    return writeFile(file, doc.dump());
}

} // namespace hlod::test
