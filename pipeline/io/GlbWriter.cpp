// GLB encoding after the Khronos glTF 2.0 specification (4.4 binary container), with
// KHR_mesh_quantization and EXT_meshopt_compression for compressed scenes; see GlbWriter.h.
#include "pipeline/io/GlbWriter.h"

#include <cstring>
#include <limits>
#include <map>

#include <nlohmann/json.hpp>

#include "pipeline/core/AtomicFile.h"
#include "pipeline/core/Error.h"
#include "pipeline/io/GlbMeshopt.h"

namespace hlod {

namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A; // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;  // "BIN\0"
constexpr int kByte = 5120, kUnsignedByte = 5121, kUnsignedShort = 5123, kUnsignedInt = 5125,
              kFloat = 5126;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr const char* kMeshopt = "EXT_meshopt_compression";
constexpr const char* kQuantization = "KHR_mesh_quantization";

std::size_t pad4(std::size_t n) { return (n + 3) & ~std::size_t(3); }

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

// The document being built: JSON, the BIN chunk (buffer 0) and the size of the meshopt
// fallback buffer (buffer 1, no data).
struct Doc {
    nlohmann::json gltf;
    std::vector<std::uint8_t> bin;
    std::size_t fallbackBytes = 0;
    std::map<std::string, int> materials; // dumped material JSON -> index
    std::map<std::string, int> images;    // URI -> image index

    std::size_t addBytes(const void* data, std::size_t n) {
        const std::size_t offset = bin.size();
        bin.resize(pad4(offset + n), 0);
        if (n) std::memcpy(bin.data() + offset, data, n);
        return offset;
    }
    int addView(nlohmann::json view) {
        gltf["bufferViews"].push_back(std::move(view));
        return static_cast<int>(gltf["bufferViews"].size()) - 1;
    }
    int plainView(const void* data, std::size_t bytes, int target) {
        nlohmann::json v = {
            {"buffer", 0}, {"byteOffset", addBytes(data, bytes)}, {"byteLength", bytes}};
        if (target) v["target"] = target;
        return addView(std::move(v));
    }
    // An EXT_meshopt_compression view: `count` elements of `stride` bytes once decoded.
    int meshoptView(const std::vector<std::uint8_t>& packed, std::size_t count, std::size_t stride,
                    int target, const char* mode, const char* filter) {
        nlohmann::json ext = {{"buffer", 0},
                              {"byteOffset", addBytes(packed.data(), packed.size())},
                              {"byteLength", packed.size()},
                              {"byteStride", stride},
                              {"count", count},
                              {"mode", mode}};
        if (std::strcmp(filter, "NONE") != 0) ext["filter"] = filter;
        nlohmann::json v = {{"buffer", 1},
                            {"byteOffset", fallbackBytes},
                            {"byteLength", count * stride},
                            {"target", target},
                            {"extensions", {{kMeshopt, std::move(ext)}}}};
        if (target == kArrayBuffer) v["byteStride"] = stride;
        fallbackBytes = pad4(fallbackBytes + count * stride);
        return addView(std::move(v));
    }
    int accessor(int view, int componentType, std::size_t count, const char* type,
                 bool normalized = false) {
        nlohmann::json a = {{"bufferView", view},
                            {"componentType", componentType},
                            {"count", count},
                            {"type", type}};
        if (normalized) a["normalized"] = true;
        gltf["accessors"].push_back(std::move(a));
        return static_cast<int>(gltf["accessors"].size()) - 1;
    }
};

int imageIndex(Doc& doc, const GlbMesh& m) {
    if (m.image.empty()) {
        if (auto it = doc.images.find(m.imageUri); it != doc.images.end()) return it->second;
        doc.gltf["images"].push_back({{"uri", m.imageUri}});
        return doc.images[m.imageUri] = static_cast<int>(doc.gltf["images"].size()) - 1;
    }
    const int view = doc.plainView(m.image.data(), m.image.size(), 0);
    doc.gltf["images"].push_back({{"bufferView", view}, {"mimeType", m.imageMimeType}});
    return static_cast<int>(doc.gltf["images"].size()) - 1;
}

// The mesh's material (glTF 2.0 sections 3.8-3.9), written once per distinct content.
int materialIndex(Doc& doc, const GlbMesh& m) {
    const glm::vec4& c = m.baseColor;
    nlohmann::json pbr = {{"baseColorFactor", {c.r, c.g, c.b, c.a}},
                          {"metallicFactor", 0.0},
                          {"roughnessFactor", 1.0}};
    if (!m.uvs.empty() && (!m.image.empty() || !m.imageUri.empty())) {
        constexpr int kLinear = 9729, kLinearMipmapLinear = 9987, kRepeat = 10497;
        if (!doc.gltf.contains("samplers")) {
            doc.gltf["samplers"] = nlohmann::json::array({{{"magFilter", kLinear},
                                                           {"minFilter", kLinearMipmapLinear},
                                                           {"wrapS", kRepeat},
                                                           {"wrapT", kRepeat}}});
        }
        const int image = imageIndex(doc, m);
        int texture = -1;
        const auto& textures = doc.gltf["textures"];
        for (std::size_t t = 0; t < textures.size(); ++t) {
            if (textures[t]["source"] == image) texture = static_cast<int>(t);
        }
        if (texture < 0) {
            doc.gltf["textures"].push_back({{"sampler", 0}, {"source", image}});
            texture = static_cast<int>(doc.gltf["textures"].size()) - 1;
        }
        pbr["baseColorTexture"] = {{"index", texture}};
    }
    nlohmann::json mat = {{"name", m.materialName.empty() ? m.name : m.materialName},
                          {"pbrMetallicRoughness", pbr}};
    if (m.alphaMask) {
        mat["alphaMode"] = "MASK";
        mat["alphaCutoff"] = m.alphaCutoff;
    } else if (c.a < 1.0f) {
        mat["alphaMode"] = "BLEND";
    }
    nlohmann::json key = mat;
    key.erase("name"); // meshes of the same look share a material whatever their names
    const std::string k = key.dump();
    if (auto it = doc.materials.find(k); it != doc.materials.end()) return it->second;
    doc.gltf["materials"].push_back(std::move(mat));
    return doc.materials[k] = static_cast<int>(doc.gltf["materials"].size()) - 1;
}

// Where a mesh's stored positions sit in its frame: frame = offset + step * stored.
struct Dequantization {
    glm::dvec3 offset{0.0};
    double step = 1.0;
};

nlohmann::json plainAttributes(Doc& doc, const GlbMesh& m) {
    const std::size_t n = m.positions.size();
    nlohmann::json attributes;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : m.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const int pos =
        doc.accessor(doc.plainView(m.positions.data(), n * 12, kArrayBuffer), kFloat, n, "VEC3");
    doc.gltf["accessors"][pos]["min"] = {lo.x, lo.y, lo.z};
    doc.gltf["accessors"][pos]["max"] = {hi.x, hi.y, hi.z};
    attributes["POSITION"] = pos;
    if (!m.normals.empty())
        attributes["NORMAL"] =
            doc.accessor(doc.plainView(m.normals.data(), n * 12, kArrayBuffer), kFloat, n, "VEC3");
    if (!m.uvs.empty())
        attributes["TEXCOORD_0"] =
            doc.accessor(doc.plainView(m.uvs.data(), n * 8, kArrayBuffer), kFloat, n, "VEC2");
    if (!m.colors.empty())
        attributes["COLOR_0"] = doc.accessor(doc.plainView(m.colors.data(), n * 4, kArrayBuffer),
                                             kUnsignedByte, n, "VEC4", true);
    return attributes;
}

nlohmann::json meshoptAttributes(Doc& doc, const GlbMesh& m, Dequantization& dq) {
    const std::size_t n = m.positions.size();
    nlohmann::json attributes;
    const QuantizedPositions q = quantizePositions(m.positions, m.positionStep);
    dq = {q.offset, q.step};
    const int pos = doc.accessor(doc.meshoptView(compressAttributes(q.values.data(), n, 8), n, 8,
                                                 kArrayBuffer, "ATTRIBUTES", "NONE"),
                                 kUnsignedShort, n, "VEC3");
    doc.gltf["accessors"][pos]["min"] = {q.min.x, q.min.y, q.min.z};
    doc.gltf["accessors"][pos]["max"] = {q.max.x, q.max.y, q.max.z};
    attributes["POSITION"] = pos;
    if (!m.normals.empty()) {
        const std::vector<std::int8_t> oct = octahedralNormals(m.normals);
        attributes["NORMAL"] =
            doc.accessor(doc.meshoptView(compressAttributes(oct.data(), n, 4), n, 4, kArrayBuffer,
                                         "ATTRIBUTES", "OCTAHEDRAL"),
                         kByte, n, "VEC3", true);
    }
    if (!m.uvs.empty()) {
        const std::vector<std::uint32_t> exp = exponentialUvs(m.uvs);
        attributes["TEXCOORD_0"] =
            doc.accessor(doc.meshoptView(compressAttributes(exp.data(), n, 8), n, 8, kArrayBuffer,
                                         "ATTRIBUTES", "EXPONENTIAL"),
                         kFloat, n, "VEC2");
    }
    if (!m.colors.empty()) {
        attributes["COLOR_0"] =
            doc.accessor(doc.meshoptView(compressAttributes(m.colors.data(), n, 4), n, 4,
                                         kArrayBuffer, "ATTRIBUTES", "NONE"),
                         kUnsignedByte, n, "VEC4", true);
    }
    return attributes;
}

int indexAccessor(Doc& doc, const GlbMesh& m, bool meshopt) {
    const bool shortIndices = m.positions.size() <= 65535;
    const std::size_t count = m.indices.size(), size = shortIndices ? 2 : 4;
    const int type = shortIndices ? kUnsignedShort : kUnsignedInt;
    if (meshopt) {
        const int view = doc.meshoptView(compressTriangles(m.indices, m.positions.size()), count,
                                         size, kElementArrayBuffer, "TRIANGLES", "NONE");
        return doc.accessor(view, type, count, "SCALAR");
    }
    if (!shortIndices)
        return doc.accessor(doc.plainView(m.indices.data(), count * 4, kElementArrayBuffer), type,
                            count, "SCALAR");
    std::vector<std::uint16_t> narrow(m.indices.begin(), m.indices.end());
    return doc.accessor(doc.plainView(narrow.data(), count * 2, kElementArrayBuffer), type, count,
                        "SCALAR");
}

// The node's TRS composed with its mesh's dequantization: frame = T R S (offset + step q).
nlohmann::json nodeJson(const GlbNode& node, int mesh, const Dequantization& dq) {
    nlohmann::json j = nlohmann::json::object();
    if (!node.name.empty()) j["name"] = node.name;
    Trs trs = node.trs;
    if (mesh >= 0) {
        j["mesh"] = mesh;
        trs.translation += trs.rotation * (trs.scale * dq.offset);
        trs.scale *= dq.step;
    }
    const glm::dvec3& t = trs.translation;
    const glm::dquat& r = trs.rotation;
    if (t != glm::dvec3(0.0)) j["translation"] = {t.x, t.y, t.z};
    if (r != glm::dquat(1.0, 0.0, 0.0, 0.0)) j["rotation"] = {r.x, r.y, r.z, r.w};
    if (trs.scale != glm::dvec3(1.0)) j["scale"] = {trs.scale.x, trs.scale.y, trs.scale.z};
    return j;
}

// The JSON and BIN chunk of `scene`.
Doc buildDoc(const GlbScene& scene) {
    const bool meshopt = scene.compression == GlbCompression::Meshopt;
    Doc doc;
    nlohmann::json& gltf = doc.gltf;
    gltf["asset"] = {{"version", "2.0"}, {"generator", "HLOD Studio " HLOD_VERSION}};
    gltf["scene"] = 0;
    std::vector<int> meshIndex(scene.meshes.size(), -1);
    std::vector<Dequantization> dequant(scene.meshes.size());
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        const GlbMesh& m = scene.meshes[i];
        check(m);
        if (m.indices.empty()) continue;
        nlohmann::json attributes =
            meshopt ? meshoptAttributes(doc, m, dequant[i]) : plainAttributes(doc, m);
        const int indices = indexAccessor(doc, m, meshopt);
        const int material = materialIndex(doc, m);
        gltf["meshes"].push_back({{"primitives",
                                   {{{"attributes", std::move(attributes)},
                                     {"indices", indices},
                                     {"material", material},
                                     {"mode", 4}}}}});
        if (!m.name.empty()) gltf["meshes"].back()["name"] = m.name;
        meshIndex[i] = static_cast<int>(gltf["meshes"].size()) - 1;
    }
    nlohmann::json roots = nlohmann::json::array();
    for (const GlbNode& node : scene.nodes) {
        if (node.mesh < -1 || node.mesh >= static_cast<int>(scene.meshes.size()))
            throw Error(ErrorCode::InvalidArgument,
                        "GLB node '" + node.name + "' names a mesh that does not exist");
        const int mesh = node.mesh < 0 ? -1 : meshIndex[static_cast<std::size_t>(node.mesh)];
        roots.push_back(gltf["nodes"].size());
        gltf["nodes"].push_back(
            nodeJson(node, mesh, mesh < 0 ? Dequantization{} : dequant[std::size_t(node.mesh)]));
    }
    gltf["scenes"] = nlohmann::json::array({{{"nodes", std::move(roots)}}});
    if (!doc.bin.empty()) gltf["buffers"].push_back({{"byteLength", doc.bin.size()}});
    if (doc.fallbackBytes > 0) {
        gltf["buffers"].push_back({{"byteLength", doc.fallbackBytes},
                                   {"extensions", {{kMeshopt, {{"fallback", true}}}}}});
        gltf["extensionsUsed"] = {kMeshopt, kQuantization};
        gltf["extensionsRequired"] = {kMeshopt, kQuantization};
    }
    return doc;
}

void putU32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i)
        out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

} // namespace

const char* toString(GlbCompression compression) {
    return compression == GlbCompression::Meshopt ? "meshopt" : "none";
}

GlbCompression glbCompressionFromString(const std::string& text) {
    if (text == "meshopt") return GlbCompression::Meshopt;
    if (text == "none") return GlbCompression::None;
    throw Error(ErrorCode::InvalidArgument, "unknown compression '" + text + "' (meshopt or none)");
}

std::vector<std::uint8_t> encodeGlb(const GlbScene& scene) {
    const Doc doc = buildDoc(scene);
    const std::string json = doc.gltf.dump();
    const std::size_t jsonBytes = pad4(json.size());
    const std::size_t total = 12 + 8 + jsonBytes + (doc.bin.empty() ? 0 : 8 + doc.bin.size());
    std::vector<std::uint8_t> out;
    out.reserve(total);
    putU32(out, kGlbMagic);
    putU32(out, 2);
    putU32(out, static_cast<std::uint32_t>(total));
    putU32(out, static_cast<std::uint32_t>(jsonBytes));
    putU32(out, kChunkJson);
    out.insert(out.end(), json.begin(), json.end());
    out.resize(20 + jsonBytes, ' ');
    if (doc.bin.empty()) return out;
    putU32(out, static_cast<std::uint32_t>(doc.bin.size()));
    putU32(out, kChunkBin);
    out.insert(out.end(), doc.bin.begin(), doc.bin.end());
    return out;
}

std::vector<std::uint8_t> encodeGlb(const GlbMesh& mesh, GlbCompression compression) {
    GlbScene scene;
    scene.compression = compression;
    scene.meshes.push_back(mesh);
    GlbNode node;
    node.name = mesh.name;
    node.mesh = 0;
    node.trs.translation = mesh.translation;
    scene.nodes.push_back(node);
    return encodeGlb(scene);
}

std::size_t glbByteSize(const GlbMesh& mesh) { return encodeGlb(mesh).size(); }

void writeGlbFile(const std::filesystem::path& file, const GlbMesh& mesh) {
    const std::vector<std::uint8_t> bytes = encodeGlb(mesh);
    writeFileAtomic(file,
                    std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

} // namespace hlod
