// GLB encoding after the Khronos glTF 2.0 specification (4.4 binary container), see GlbWriter.h.
#include "pipeline/io/GlbWriter.h"

#include <atomic>
#include <cstring>
#include <fstream>
#include <limits>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "pipeline/core/AtomicFile.h"
#include "pipeline/core/Error.h"

namespace hlod {

namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A; // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;  // "BIN\0"
constexpr int kFloat = 5126, kUnsignedByte = 5121, kUnsignedShort = 5123, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

std::size_t pad4(std::size_t n) { return (n + 3) & ~std::size_t(3); }

// One binary stream of the BIN chunk.
struct Stream {
    const void* data = nullptr;
    std::size_t bytes = 0;
    std::size_t offset = 0;
    bool shortIndices = false; // indices narrowed to uint16
};

struct Layout {
    std::string json;
    std::vector<Stream> streams;
    std::size_t binBytes = 0;
};

void check(const GlbMesh& m) {
    const std::size_t n = m.positions.size();
    auto bad = [&](const char* what) {
        throw Error(ErrorCode::InvalidArgument,
                    "GLB mesh '" + m.name + "': " + what + " count differs from positions");
    };
    if (!m.normals.empty() && m.normals.size() != n) bad("normal");
    if (!m.uvs.empty() && m.uvs.size() != n) bad("uv");
    if (!m.colors.empty() && m.colors.size() != n) bad("colour");
    if (m.indices.size() % 3 != 0) {
        throw Error(ErrorCode::InvalidArgument,
                    "GLB mesh '" + m.name + "': index count not a multiple of 3");
    }
    for (std::uint32_t i : m.indices) {
        if (i >= n)
            throw Error(ErrorCode::InvalidArgument,
                        "GLB mesh '" + m.name + "': index out of range");
    }
}

int addAccessor(nlohmann::json& gltf, Layout& layout, const void* data, std::size_t count,
                std::size_t elementBytes, int componentType, const char* type, int target,
                bool normalized = false) {
    Stream s;
    s.data = data;
    s.bytes = count * elementBytes;
    s.offset = layout.binBytes;
    layout.binBytes = pad4(layout.binBytes + s.bytes);
    const int view = static_cast<int>(gltf["bufferViews"].size());
    gltf["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", s.offset}, {"byteLength", s.bytes}, {"target", target}});
    nlohmann::json acc = {
        {"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}};
    if (normalized) acc["normalized"] = true;
    gltf["accessors"].push_back(std::move(acc));
    layout.streams.push_back(s);
    return view; // one accessor per view, same index
}

// The mesh's one material; an embedded texture adds a bufferView, an image, a sampler and a
// texture (glTF 2.0 sections 3.8-3.9).
nlohmann::json material(nlohmann::json& gltf, Layout& layout, const GlbMesh& m) {
    const glm::vec4& c = m.baseColor;
    nlohmann::json pbr = {{"baseColorFactor", {c.r, c.g, c.b, c.a}},
                          {"metallicFactor", 0.0},
                          {"roughnessFactor", 1.0}};
    const bool embedded = !m.image.empty();
    if (!m.uvs.empty() && (embedded || !m.imageUri.empty())) {
        if (embedded) {
            Stream s;
            s.data = m.image.data();
            s.bytes = m.image.size();
            s.offset = layout.binBytes;
            layout.binBytes = pad4(layout.binBytes + s.bytes);
            layout.streams.push_back(s);
            const auto view = gltf["bufferViews"].size();
            gltf["bufferViews"].push_back(
                {{"buffer", 0}, {"byteOffset", s.offset}, {"byteLength", s.bytes}});
            gltf["images"] =
                nlohmann::json::array({{{"bufferView", view}, {"mimeType", m.imageMimeType}}});
        } else {
            gltf["images"] = nlohmann::json::array({{{"uri", m.imageUri}}});
        }
        constexpr int kLinear = 9729, kLinearMipmapLinear = 9987, kRepeat = 10497;
        gltf["samplers"] = nlohmann::json::array({{{"magFilter", kLinear},
                                                   {"minFilter", kLinearMipmapLinear},
                                                   {"wrapS", kRepeat},
                                                   {"wrapT", kRepeat}}});
        gltf["textures"] = nlohmann::json::array({{{"sampler", 0}, {"source", 0}}});
        pbr["baseColorTexture"] = {{"index", 0}};
    }
    nlohmann::json mat = {{"name", m.name}, {"pbrMetallicRoughness", pbr}};
    if (m.alphaMask) {
        mat["alphaMode"] = "MASK";
        mat["alphaCutoff"] = m.alphaCutoff;
    } else if (c.a < 1.0f) {
        mat["alphaMode"] = "BLEND";
    }
    return mat;
}

Layout buildLayout(const GlbMesh& m) {
    check(m);
    Layout layout;
    nlohmann::json gltf;
    gltf["asset"] = {{"version", "2.0"}, {"generator", "HLOD Studio " HLOD_VERSION}};
    gltf["scene"] = 0;
    gltf["scenes"] = nlohmann::json::array({{{"nodes", {0}}}});
    nlohmann::json node = {{"name", m.name}};
    const glm::dvec3& t = m.translation;
    if (t != glm::dvec3(0.0)) node["translation"] = {t.x, t.y, t.z};
    if (!m.indices.empty()) {
        node["mesh"] = 0;
        gltf["bufferViews"] = nlohmann::json::array();
        gltf["accessors"] = nlohmann::json::array();
        nlohmann::json attributes;
        const std::size_t n = m.positions.size();
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (const glm::vec3& p : m.positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        attributes["POSITION"] =
            addAccessor(gltf, layout, m.positions.data(), n, 12, kFloat, "VEC3", kArrayBuffer);
        gltf["accessors"].back()["min"] = {lo.x, lo.y, lo.z};
        gltf["accessors"].back()["max"] = {hi.x, hi.y, hi.z};
        if (!m.normals.empty()) {
            attributes["NORMAL"] =
                addAccessor(gltf, layout, m.normals.data(), n, 12, kFloat, "VEC3", kArrayBuffer);
        }
        if (!m.uvs.empty()) {
            attributes["TEXCOORD_0"] =
                addAccessor(gltf, layout, m.uvs.data(), n, 8, kFloat, "VEC2", kArrayBuffer);
        }
        if (!m.colors.empty()) {
            attributes["COLOR_0"] = addAccessor(gltf, layout, m.colors.data(), n, 4, kUnsignedByte,
                                                "VEC4", kArrayBuffer, true);
        }
        const bool shortIndices = n <= 65535;
        const int indices = addAccessor(
            gltf, layout, m.indices.data(), m.indices.size(), shortIndices ? 2 : 4,
            shortIndices ? kUnsignedShort : kUnsignedInt, "SCALAR", kElementArrayBuffer);
        layout.streams.back().shortIndices = shortIndices;
        gltf["materials"] = nlohmann::json::array({material(gltf, layout, m)});
        gltf["meshes"] = nlohmann::json::array({{{"name", m.name},
                                                 {"primitives",
                                                  {{{"attributes", attributes},
                                                    {"indices", indices},
                                                    {"material", 0},
                                                    {"mode", 4}}}}}});
        gltf["buffers"] = nlohmann::json::array({{{"byteLength", layout.binBytes}}});
    }
    gltf["nodes"] = nlohmann::json::array({node});
    layout.json = gltf.dump();
    return layout;
}

void putU32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i)
        out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

std::size_t totalBytes(const Layout& layout) {
    std::size_t total = 12 + 8 + pad4(layout.json.size());
    if (layout.binBytes > 0) total += 8 + layout.binBytes;
    return total;
}

} // namespace

std::size_t glbByteSize(const GlbMesh& mesh) { return totalBytes(buildLayout(mesh)); }

std::vector<std::uint8_t> encodeGlb(const GlbMesh& mesh) {
    const Layout layout = buildLayout(mesh);
    std::vector<std::uint8_t> out;
    out.reserve(totalBytes(layout));
    putU32(out, kGlbMagic);
    putU32(out, 2);
    putU32(out, static_cast<std::uint32_t>(totalBytes(layout)));
    putU32(out, static_cast<std::uint32_t>(pad4(layout.json.size())));
    putU32(out, kChunkJson);
    out.insert(out.end(), layout.json.begin(), layout.json.end());
    out.resize(20 + pad4(layout.json.size()), ' ');
    if (layout.binBytes == 0) return out;
    putU32(out, static_cast<std::uint32_t>(layout.binBytes));
    putU32(out, kChunkBin);
    const std::size_t binStart = out.size();
    out.resize(binStart + layout.binBytes, 0);
    for (const Stream& s : layout.streams) {
        std::uint8_t* dst = out.data() + binStart + s.offset;
        if (s.shortIndices) {
            const auto* src = static_cast<const std::uint32_t*>(s.data);
            for (std::size_t i = 0; i < s.bytes / 2; ++i) {
                const auto v = static_cast<std::uint16_t>(src[i]);
                std::memcpy(dst + 2 * i, &v, 2);
            }
        } else {
            std::memcpy(dst, s.data, s.bytes);
        }
    }
    return out;
}

void writeGlbFile(const std::filesystem::path& file, const GlbMesh& mesh) {
    const std::vector<std::uint8_t> bytes = encodeGlb(mesh);
    writeFileAtomic(file,
                    std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

} // namespace hlod
