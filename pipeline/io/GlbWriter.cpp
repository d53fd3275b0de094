// GLB encoding after the Khronos glTF 2.0 specification (4.4 binary container), with
// KHR_mesh_quantization and EXT_meshopt_compression for compressed scenes; see GlbWriter.h.
#include "pipeline/io/GlbWriter.h"

#include <algorithm>
#include <charconv>
#include <cmath>
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

// A float as the shortest decimal that reads back as the same float (0.4, not
// 0.4000000059604645); whole numbers as integers. std::to_chars: whatever the C locale.
nlohmann::json shortFloat(float f) {
    if (!std::isfinite(f)) return double(f);
    if (f == std::floor(f) && std::abs(f) < 1e9f) return static_cast<std::int64_t>(f);
    char text[32];
    const auto end = std::to_chars(text, text + sizeof(text), f).ptr;
    double d = f;
    std::from_chars(text, end, d); // the double nearest that decimal: nlohmann prints it back
    return d;
}

// A double as JSON: whole numbers without a fraction ("-20", not "-20.0"), others as the
// shortest decimal that reads back as the same double (nlohmann's default).
nlohmann::json shortDouble(double d) {
    if (d == std::floor(d) && std::abs(d) < 9.0e15) return static_cast<std::int64_t>(d);
    return d;
}

// The file's streams, each one buffer view (see the header).
enum Stream { kPositions, kNormals, kUvs, kColors, kIndices16, kIndices32, kStreams };

struct StreamData {
    std::vector<std::uint8_t> bytes;    // vertex streams: as stored (meshopt: before the codec)
    std::vector<std::uint32_t> indices; // index streams
    std::size_t count = 0;              // elements
};

// Element size of a stream as stored: meshopt positions are 16-bit x, y, z, 0; normals
// octahedral bytes; uvs exponential words. Plain: floats.
std::size_t strideOf(Stream s, bool meshopt) {
    switch (s) {
    case kPositions:
        return meshopt ? 8 : 12;
    case kNormals:
        return meshopt ? 4 : 12;
    case kUvs:
        return 8;
    case kColors:
        return 4;
    case kIndices16:
        return 2;
    default:
        return 4;
    }
}

// The document being built: JSON, the BIN chunk (buffer 0) and the size of the meshopt
// fallback buffer (buffer 1, no data).
struct Doc {
    bool meshopt = false;
    nlohmann::json gltf;
    std::vector<std::uint8_t> bin;
    std::size_t fallbackBytes = 0;
    std::map<std::string, int> materials; // dumped material JSON -> index
    std::map<std::string, int> images;    // URI -> image index
    bool emissiveStrength = false;        // some material uses KHR_materials_emissive_strength
    StreamData streams[kStreams];
    std::vector<std::pair<int, Stream>> streamAccessors; // accessor, its stream

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
    static void putOffset(nlohmann::json& j, std::size_t offset) {
        if (offset > 0) j["byteOffset"] = offset;
    }
    int plainView(const void* data, std::size_t bytes, int target, std::size_t stride = 0) {
        nlohmann::json v = {{"buffer", 0}, {"byteLength", bytes}};
        putOffset(v, addBytes(data, bytes));
        if (target) v["target"] = target;
        if (stride) v["byteStride"] = stride;
        return addView(std::move(v));
    }
    // An EXT_meshopt_compression view: `count` elements of `stride` bytes once decoded.
    int meshoptView(const std::vector<std::uint8_t>& packed, std::size_t count, std::size_t stride,
                    int target, const char* mode, const char* filter) {
        nlohmann::json ext = {{"buffer", 0},
                              {"byteLength", packed.size()},
                              {"byteStride", stride},
                              {"count", count},
                              {"mode", mode}};
        putOffset(ext, addBytes(packed.data(), packed.size()));
        if (std::strcmp(filter, "NONE") != 0) ext["filter"] = filter;
        nlohmann::json v = {{"buffer", 1},
                            {"byteLength", count * stride},
                            {"target", target},
                            {"extensions", {{kMeshopt, std::move(ext)}}}};
        putOffset(v, fallbackBytes);
        if (target == kArrayBuffer) v["byteStride"] = stride;
        fallbackBytes = pad4(fallbackBytes + count * stride);
        return addView(std::move(v));
    }
    // An accessor of `count` elements of stream `s` from its element `first` on.
    int accessor(Stream s, std::size_t first, std::size_t count, int componentType,
                 const char* type, bool normalized = false) {
        nlohmann::json a = {{"componentType", componentType}, {"count", count}, {"type", type}};
        putOffset(a, first * strideOf(s, meshopt));
        if (normalized) a["normalized"] = true;
        gltf["accessors"].push_back(std::move(a));
        const int index = static_cast<int>(gltf["accessors"].size()) - 1;
        streamAccessors.push_back({index, s});
        return index;
    }
    // Appends `count` elements to vertex stream `s`; returns the first.
    std::size_t append(Stream s, const void* data, std::size_t count) {
        StreamData& d = streams[s];
        const std::size_t first = d.count;
        const auto* p = static_cast<const std::uint8_t*>(data);
        d.bytes.insert(d.bytes.end(), p, p + count * strideOf(s, meshopt));
        d.count += count;
        return first;
    }
};

// The image of `uri`, written once per file (shared texture files).
int uriImageIndex(Doc& doc, const std::string& uri) {
    if (auto it = doc.images.find(uri); it != doc.images.end()) return it->second;
    doc.gltf["images"].push_back({{"uri", uri}});
    return doc.images[uri] = static_cast<int>(doc.gltf["images"].size()) - 1;
}

int imageIndex(Doc& doc, const GlbMesh& m) {
    if (m.image.empty()) return uriImageIndex(doc, m.imageUri);
    const int view = doc.plainView(m.image.data(), m.image.size(), 0);
    doc.gltf["images"].push_back({{"bufferView", view}, {"mimeType", m.imageMimeType}});
    return static_cast<int>(doc.gltf["images"].size()) - 1;
}

// The texture sampling `image` with the one sampler, written once per image.
int textureIndex(Doc& doc, int image) {
    constexpr int kLinear = 9729, kLinearMipmapLinear = 9987; // wrap: repeat by default
    if (!doc.gltf.contains("samplers")) {
        doc.gltf["samplers"] =
            nlohmann::json::array({{{"magFilter", kLinear}, {"minFilter", kLinearMipmapLinear}}});
    }
    const auto& textures = doc.gltf["textures"];
    for (std::size_t t = 0; t < textures.size(); ++t) {
        if (textures[t]["source"] == image) return static_cast<int>(t);
    }
    doc.gltf["textures"].push_back({{"sampler", 0}, {"source", image}});
    return static_cast<int>(doc.gltf["textures"].size()) - 1;
}

// emissiveFactor (each channel at most 1, glTF 2.0 3.9.3), with KHR_materials_emissive_strength
// carrying the rest, and emissiveTexture.
void putEmissive(Doc& doc, const GlbMesh& m, int baseTexture, nlohmann::json& mat) {
    const glm::vec3 e = glm::max(m.emissive, glm::vec3(0.0f));
    if (e == glm::vec3(0.0f) || !std::isfinite(e.r + e.g + e.b)) return;
    const float strength = std::max({e.r, e.g, e.b, 1.0f});
    const glm::vec3 f = e / strength;
    mat["emissiveFactor"] = {shortFloat(f.r), shortFloat(f.g), shortFloat(f.b)};
    if (strength > 1.0f) {
        mat["extensions"]["KHR_materials_emissive_strength"] = {
            {"emissiveStrength", shortFloat(strength)}};
        doc.emissiveStrength = true;
    }
    int texture = -1;
    if (m.emissiveUsesImage)
        texture = baseTexture;
    else if (!m.uvs.empty() && !m.emissiveUri.empty())
        texture = textureIndex(doc, uriImageIndex(doc, m.emissiveUri));
    if (texture >= 0) mat["emissiveTexture"] = {{"index", texture}};
}

// The mesh's material (glTF 2.0 sections 3.8-3.9), written once per distinct content.
int materialIndex(Doc& doc, const GlbMesh& m) {
    const glm::vec4& c = m.baseColor;
    nlohmann::json pbr = {{"metallicFactor", 0}}; // roughnessFactor: 1 by default
    if (c != glm::vec4(1.0f))
        pbr["baseColorFactor"] = {shortFloat(c.r), shortFloat(c.g), shortFloat(c.b),
                                  shortFloat(c.a)};
    int baseTexture = -1;
    if (!m.uvs.empty() && (!m.image.empty() || !m.imageUri.empty())) {
        baseTexture = textureIndex(doc, imageIndex(doc, m));
        pbr["baseColorTexture"] = {{"index", baseTexture}};
    }
    nlohmann::json mat = {{"pbrMetallicRoughness", pbr}};
    if (m.alphaMode == AlphaMode::Mask) {
        mat["alphaMode"] = "MASK";
        if (m.alphaCutoff != 0.5f) mat["alphaCutoff"] = shortFloat(m.alphaCutoff);
    } else if (m.alphaMode == AlphaMode::Blend) {
        mat["alphaMode"] = "BLEND";
    }
    if (m.doubleSided) mat["doubleSided"] = true;
    putEmissive(doc, m, baseTexture, mat);
    // Meshes of the same look share a material whatever their names.
    const std::string k = mat.dump();
    if (auto it = doc.materials.find(k); it != doc.materials.end()) return it->second;
    if (!m.materialName.empty()) mat["name"] = m.materialName;
    doc.gltf["materials"].push_back(std::move(mat));
    return doc.materials[k] = static_cast<int>(doc.gltf["materials"].size()) - 1;
}

// A mesh's vertices into the streams; its attributes (accessor indices). Compressed: the
// positions' grid goes to `grid`.
nlohmann::json addVertices(Doc& doc, const GlbMesh& m, PositionGrid& grid) {
    const std::size_t n = m.positions.size();
    nlohmann::json attributes;
    if (doc.meshopt) {
        const QuantizedPositions q = quantizePositions(m.positions, m.positionStep);
        grid = {q.offset, q.step};
        const int pos = doc.accessor(kPositions, doc.append(kPositions, q.values.data(), n), n,
                                     kUnsignedShort, "VEC3");
        doc.gltf["accessors"][pos]["min"] = {q.min.x, q.min.y, q.min.z};
        doc.gltf["accessors"][pos]["max"] = {q.max.x, q.max.y, q.max.z};
        attributes["POSITION"] = pos;
        if (!m.normals.empty()) {
            const std::vector<std::int8_t> oct = octahedralNormals(m.normals);
            attributes["NORMAL"] =
                doc.accessor(kNormals, doc.append(kNormals, oct.data(), n), n, kByte, "VEC3", true);
        }
        if (!m.uvs.empty()) {
            const std::vector<std::uint32_t> exp = exponentialUvs(m.uvs);
            attributes["TEXCOORD_0"] =
                doc.accessor(kUvs, doc.append(kUvs, exp.data(), n), n, kFloat, "VEC2");
        }
    } else {
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (const glm::vec3& p : m.positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        const int pos = doc.accessor(kPositions, doc.append(kPositions, m.positions.data(), n), n,
                                     kFloat, "VEC3");
        // Exact floats (the validator compares them with the data): only ".0" is left out.
        doc.gltf["accessors"][pos]["min"] = {shortDouble(lo.x), shortDouble(lo.y),
                                             shortDouble(lo.z)};
        doc.gltf["accessors"][pos]["max"] = {shortDouble(hi.x), shortDouble(hi.y),
                                             shortDouble(hi.z)};
        attributes["POSITION"] = pos;
        if (!m.normals.empty())
            attributes["NORMAL"] = doc.accessor(kNormals, doc.append(kNormals, m.normals.data(), n),
                                                n, kFloat, "VEC3");
        if (!m.uvs.empty())
            attributes["TEXCOORD_0"] =
                doc.accessor(kUvs, doc.append(kUvs, m.uvs.data(), n), n, kFloat, "VEC2");
    }
    if (!m.colors.empty())
        attributes["COLOR_0"] = doc.accessor(kColors, doc.append(kColors, m.colors.data(), n), n,
                                             kUnsignedByte, "VEC4", true);
    return attributes;
}

// Triangles over `vertexCount` vertices into the 16- or 32-bit index stream; the accessor.
int addIndices(Doc& doc, std::span<const std::uint32_t> indices, std::size_t vertexCount) {
    const bool shortIndices = vertexCount <= 65535;
    const Stream s = shortIndices ? kIndices16 : kIndices32;
    StreamData& d = doc.streams[s];
    const std::size_t first = d.count;
    d.indices.insert(d.indices.end(), indices.begin(), indices.end());
    d.count += indices.size();
    return doc.accessor(s, first, indices.size(), shortIndices ? kUnsignedShort : kUnsignedInt,
                        "SCALAR");
}

const char* filterOf(Stream s) {
    return s == kNormals ? "OCTAHEDRAL" : s == kUvs ? "EXPONENTIAL" : "NONE";
}

// With compression and no image in buffer 0, the accessor whose data is also stored plain there
// (GlbWriter.h): the one smallest once decoded, as an index into doc.streamAccessors; -1 when
// nothing is needed.
int plainAccessor(const Doc& doc) {
    if (!doc.meshopt || (doc.gltf.contains("bufferViews") && !doc.gltf["bufferViews"].empty()))
        return -1;
    int best = -1;
    std::size_t bestBytes = 0;
    for (std::size_t i = 0; i < doc.streamAccessors.size(); ++i) {
        const auto& [accessor, stream] = doc.streamAccessors[i];
        const std::size_t count = doc.gltf["accessors"][std::size_t(accessor)]["count"];
        const std::size_t bytes = count * strideOf(stream, true);
        if (best < 0 || bytes < bestBytes) {
            best = static_cast<int>(i);
            bestBytes = bytes;
        }
    }
    return best;
}

// A plain view in buffer 0 holding `count` elements of stream `s` from element `first` on, as
// a decoder of the compressed stream would produce them.
int plainCopy(Doc& doc, Stream s, std::size_t first, std::size_t count) {
    const StreamData& d = doc.streams[s];
    if (s == kIndices16) {
        const std::vector<std::uint16_t> narrow(d.indices.begin() + first,
                                                d.indices.begin() + first + count);
        return doc.plainView(narrow.data(), count * 2, kElementArrayBuffer);
    }
    if (s == kIndices32) return doc.plainView(&d.indices[first], count * 4, kElementArrayBuffer);
    const std::size_t stride = strideOf(s, doc.meshopt);
    const std::vector<std::uint8_t> bytes =
        decodedAttributes(d.bytes.data() + first * stride, count, stride, filterOf(s));
    return doc.plainView(bytes.data(), bytes.size(), kArrayBuffer, stride);
}

// Every stream as one buffer view; the accessors pointed at theirs. With compression, the
// plain accessor (plainAccessor) reads its own plain copy instead (the compressed stream keeps
// its data too, so the other accessors' offsets stay; a stream it was alone in is not written
// compressed at all).
void finishStreams(Doc& doc) {
    const int plain = plainAccessor(doc);
    // A stream whose only accessor is the plain one gets no compressed view (it would be unused).
    int onlyPlain = -1;
    if (plain >= 0) {
        const Stream s = doc.streamAccessors[std::size_t(plain)].second;
        int users = 0;
        for (const auto& sa : doc.streamAccessors)
            users += sa.second == s;
        if (users == 1) onlyPlain = s;
    }
    int viewOf[kStreams];
    for (int s = 0; s < kStreams; ++s) {
        const Stream stream = static_cast<Stream>(s);
        StreamData& d = doc.streams[s];
        viewOf[s] = -1;
        if (d.count == 0 || s == onlyPlain) continue;
        const std::size_t stride = strideOf(stream, doc.meshopt);
        const bool indices = stream == kIndices16 || stream == kIndices32;
        if (doc.meshopt && indices) {
            std::uint32_t top = 0;
            for (std::uint32_t i : d.indices)
                top = std::max(top, i);
            viewOf[s] = doc.meshoptView(compressTriangles(d.indices, std::size_t(top) + 1), d.count,
                                        stride, kElementArrayBuffer, "TRIANGLES", "NONE");
        } else if (doc.meshopt) {
            viewOf[s] =
                doc.meshoptView(compressAttributes(d.bytes.data(), d.count, stride), d.count,
                                stride, kArrayBuffer, "ATTRIBUTES", filterOf(stream));
        } else if (stream == kIndices16) {
            const std::vector<std::uint16_t> narrow(d.indices.begin(), d.indices.end());
            viewOf[s] = doc.plainView(narrow.data(), d.count * 2, kElementArrayBuffer);
        } else if (indices) {
            viewOf[s] = doc.plainView(d.indices.data(), d.count * 4, kElementArrayBuffer);
        } else {
            // Several accessors share the view: byteStride is required (glTF 2.0, 3.6.2.3).
            viewOf[s] = doc.plainView(d.bytes.data(), d.bytes.size(), kArrayBuffer, stride);
        }
    }
    for (std::size_t i = 0; i < doc.streamAccessors.size(); ++i) {
        const auto& [accessor, stream] = doc.streamAccessors[i];
        nlohmann::json& a = doc.gltf["accessors"][std::size_t(accessor)];
        if (static_cast<int>(i) != plain) {
            a["bufferView"] = viewOf[stream];
            continue;
        }
        const std::size_t first = a.value("byteOffset", std::size_t(0)) / strideOf(stream, true);
        a.erase("byteOffset");
        a["bufferView"] = plainCopy(doc, stream, first, a["count"].get<std::size_t>());
    }
}

// The node's TRS composed with its mesh's dequantization: frame = T R S (offset + step q).
nlohmann::json nodeJson(const GlbNode& node, int mesh, const PositionGrid& dq) {
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
    const glm::dvec3& s = trs.scale;
    if (t != glm::dvec3(0.0))
        j["translation"] = {shortDouble(t.x), shortDouble(t.y), shortDouble(t.z)};
    if (r != glm::dquat(1.0, 0.0, 0.0, 0.0))
        j["rotation"] = {shortDouble(r.x), shortDouble(r.y), shortDouble(r.z), shortDouble(r.w)};
    if (s != glm::dvec3(1.0)) j["scale"] = {shortDouble(s.x), shortDouble(s.y), shortDouble(s.z)};
    return j;
}

// The glTF mesh of `m` (one primitive), its vertices and indices added to the streams.
nlohmann::json meshJson(Doc& doc, const GlbMesh& m, PositionGrid& grid) {
    nlohmann::json attributes = addVertices(doc, m, grid);
    const int indices = addIndices(doc, m.indices, m.positions.size());
    nlohmann::json mesh = {{"primitives",
                            {{{"attributes", std::move(attributes)},
                              {"indices", indices},
                              {"material", materialIndex(doc, m)}}}}};
    if (!m.name.empty()) mesh["name"] = m.name;
    return mesh;
}

// The JSON and BIN chunk of `scene`.
Doc buildDoc(const GlbScene& scene) {
    Doc doc;
    doc.meshopt = scene.compression == GlbCompression::Meshopt;
    nlohmann::json& gltf = doc.gltf;
    gltf["asset"] = {{"version", "2.0"}, {"generator", "HLOD Studio " HLOD_VERSION}};
    gltf["scene"] = 0;
    const std::size_t count = scene.meshes.size();
    std::vector<int> meshIndex(count, -1);
    std::vector<PositionGrid> grid(count);
    for (std::size_t i = 0; i < count; ++i) {
        const GlbMesh& m = scene.meshes[i];
        check(m);
        if (m.indices.empty()) continue;
        gltf["meshes"].push_back(meshJson(doc, m, grid[i]));
        meshIndex[i] = static_cast<int>(gltf["meshes"].size()) - 1;
    }
    finishStreams(doc);
    nlohmann::json roots = nlohmann::json::array();
    for (const GlbNode& node : scene.nodes) {
        if (node.mesh < -1 || node.mesh >= static_cast<int>(count))
            throw Error(ErrorCode::InvalidArgument,
                        "GLB node '" + node.name + "' names a mesh that does not exist");
        const int mesh = node.mesh < 0 ? -1 : meshIndex[static_cast<std::size_t>(node.mesh)];
        roots.push_back(gltf["nodes"].size());
        gltf["nodes"].push_back(
            nodeJson(node, mesh, mesh < 0 ? PositionGrid{} : grid[std::size_t(node.mesh)]));
    }
    gltf["scenes"] = nlohmann::json::array({{{"nodes", std::move(roots)}}});
    if (!doc.bin.empty()) gltf["buffers"].push_back({{"byteLength", doc.bin.size()}});
    if (doc.fallbackBytes > 0) {
        gltf["buffers"].push_back({{"byteLength", doc.fallbackBytes},
                                   {"extensions", {{kMeshopt, {{"fallback", true}}}}}});
        gltf["extensionsUsed"] = {kMeshopt, kQuantization};
        gltf["extensionsRequired"] = {kMeshopt, kQuantization};
    }
    if (doc.emissiveStrength) gltf["extensionsUsed"].push_back("KHR_materials_emissive_strength");
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
