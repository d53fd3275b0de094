// EXT_meshopt_compression decoding for the glTF importer (see GltfMeshopt.h).
#include "pipeline/io/GltfMeshopt.h"

#include <algorithm>
#include <cstring>

#include <meshoptimizer.h>

#include "pipeline/core/Error.h"

namespace hlod {

namespace {

constexpr const char* kMeshopt = "EXT_meshopt_compression";
constexpr std::uint32_t kGlbMagic = 0x46546C67, kChunkJson = 0x4E4F534A, kChunkBin = 0x004E4942;

std::size_t pad4(std::size_t n) { return (n + 3) & ~std::size_t(3); }

std::uint32_t readU32(const std::vector<std::uint8_t>& b, std::size_t at) {
    std::uint32_t v;
    std::memcpy(&v, b.data() + at, 4);
    return v;
}

void putU32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i)
        out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

[[noreturn]] void bad(const std::filesystem::path& file, std::size_t view,
                      const std::string& what) {
    throw Error(ErrorCode::Malformed, file, "buffer view " + std::to_string(view) + ": " + what);
}

std::uint64_t number(const nlohmann::json& j, const char* key, std::uint64_t fallback,
                     const std::filesystem::path& file, std::size_t view) {
    if (!j.contains(key)) return fallback;
    const nlohmann::json& v = j.at(key);
    if (!v.is_number_unsigned()) bad(file, view, std::string("'") + key + "' is not a count");
    return v.get<std::uint64_t>();
}

// The bytes [offset, offset + length) of buffer `index`, checked.
const std::uint8_t* slice(const std::vector<std::vector<std::uint8_t>>& buffers,
                          std::uint64_t index, std::uint64_t offset, std::uint64_t length,
                          const std::filesystem::path& file, std::size_t view) {
    if (index >= buffers.size()) bad(file, view, "refers to a buffer that does not exist");
    const std::vector<std::uint8_t>& b = buffers[index];
    if (b.empty() && length > 0) bad(file, view, "reads a buffer without data");
    if (offset > b.size() || length > b.size() - offset)
        bad(file, view, "reads past the end of its buffer");
    return b.data() + offset;
}

// Decodes one compressed view into `out` (count * stride bytes).
void decodeView(const nlohmann::json& ext, const std::vector<std::vector<std::uint8_t>>& buffers,
                const std::filesystem::path& file, std::size_t view, std::size_t maxElements,
                std::vector<std::uint8_t>& out) {
    const std::uint64_t count = number(ext, "count", 0, file, view);
    const std::uint64_t stride = number(ext, "byteStride", 0, file, view);
    const std::uint64_t length = number(ext, "byteLength", 0, file, view);
    const std::uint8_t* src = slice(buffers, number(ext, "buffer", ~0ull, file, view),
                                    number(ext, "byteOffset", 0, file, view), length, file, view);
    if (count > maxElements)
        throw Error(ErrorCode::TooLarge, file,
                    "buffer view " + std::to_string(view) + " declares " + std::to_string(count) +
                        " elements (limit " + std::to_string(maxElements) + ")");
    const std::string mode = ext.value("mode", "");
    const std::string filter = ext.value("filter", "NONE");
    out.assign(count * stride, 0);
    int rc = 0;
    if (mode == "ATTRIBUTES") {
        if (stride == 0 || stride > 256 || stride % 4 != 0) bad(file, view, "bad byteStride");
        rc = meshopt_decodeVertexBuffer(out.data(), count, stride, src, length);
    } else if (mode == "TRIANGLES" || mode == "INDICES") {
        if (stride != 2 && stride != 4) bad(file, view, "bad index byteStride");
        if (mode == "TRIANGLES" && count % 3 != 0) bad(file, view, "count is not whole triangles");
        rc = mode == "TRIANGLES"
                 ? meshopt_decodeIndexBuffer(out.data(), count, stride, src, length)
                 : meshopt_decodeIndexSequence(out.data(), count, stride, src, length);
    } else {
        bad(file, view, "unknown meshopt mode '" + mode + "'");
    }
    if (rc != 0) bad(file, view, "meshopt data is corrupt");
    if (filter == "OCTAHEDRAL") {
        if (mode != "ATTRIBUTES" || (stride != 4 && stride != 8)) bad(file, view, "bad filter");
        meshopt_decodeFilterOct(out.data(), count, stride);
    } else if (filter == "QUANTIZATION") {
        if (mode != "ATTRIBUTES" || stride != 8) bad(file, view, "bad filter");
        meshopt_decodeFilterQuat(out.data(), count, stride);
    } else if (filter == "EXPONENTIAL") {
        if (mode != "ATTRIBUTES") bad(file, view, "bad filter");
        meshopt_decodeFilterExp(out.data(), count, stride);
    } else if (filter != "NONE") {
        bad(file, view, "unknown meshopt filter '" + filter + "'");
    }
}

void dropExtension(nlohmann::json& gltf, const char* list) {
    if (!gltf.contains(list) || !gltf[list].is_array()) return;
    nlohmann::json kept = nlohmann::json::array();
    for (const auto& e : gltf[list])
        if (e != kMeshopt) kept.push_back(e);
    if (kept.empty())
        gltf.erase(list);
    else
        gltf[list] = std::move(kept);
}

} // namespace

bool usesMeshopt(const nlohmann::json& gltf) {
    if (!gltf.is_object() || !gltf.contains("extensionsUsed")) return false;
    const auto& used = gltf["extensionsUsed"];
    return used.is_array() && std::find(used.begin(), used.end(), kMeshopt) != used.end();
}

bool isMeshoptFallback(const nlohmann::json& gltf, std::size_t index) {
    const auto* buffers = gltf.contains("buffers") ? &gltf["buffers"] : nullptr;
    if (!buffers || !buffers->is_array() || index >= buffers->size()) return false;
    const auto& b = (*buffers)[index];
    if (!b.is_object() || !b.contains("extensions") || !b["extensions"].is_object()) return false;
    const auto& e = b["extensions"];
    return e.contains(kMeshopt) && e[kMeshopt].is_object() && e[kMeshopt].value("fallback", false);
}

std::vector<std::uint8_t> decodeMeshoptGltf(nlohmann::json gltf,
                                            const std::vector<std::vector<std::uint8_t>>& buffers,
                                            const std::filesystem::path& file,
                                            std::size_t maxElements) {
    std::vector<std::uint8_t> bin, decoded;
    if (gltf.contains("bufferViews")) {
        nlohmann::json& views = gltf["bufferViews"];
        if (!views.is_array()) throw Error(ErrorCode::Malformed, file, "bufferViews is not a list");
        for (std::size_t i = 0; i < views.size(); ++i) {
            nlohmann::json& v = views[i];
            if (!v.is_object()) bad(file, i, "is not an object");
            const nlohmann::json* ext = nullptr;
            if (v.contains("extensions") && v["extensions"].is_object() &&
                v["extensions"].contains(kMeshopt))
                ext = &v["extensions"][kMeshopt];
            const std::uint64_t length = number(v, "byteLength", 0, file, i);
            if (ext) {
                if (!ext->is_object()) bad(file, i, "bad meshopt extension");
                decodeView(*ext, buffers, file, i, maxElements, decoded);
                if (decoded.size() != length)
                    bad(file, i, "byteLength differs from count x stride");
            } else {
                const std::uint8_t* src =
                    slice(buffers, number(v, "buffer", ~0ull, file, i),
                          number(v, "byteOffset", 0, file, i), length, file, i);
                decoded.assign(src, src + length);
            }
            const std::size_t offset = bin.size();
            bin.insert(bin.end(), decoded.begin(), decoded.end());
            bin.resize(pad4(bin.size()), 0);
            v["buffer"] = 0;
            v["byteOffset"] = offset;
            if (ext) v["extensions"].erase(kMeshopt);
            if (v.contains("extensions") && v["extensions"].empty()) v.erase("extensions");
        }
    }
    gltf["buffers"] = nlohmann::json::array({{{"byteLength", bin.size()}}});
    if (bin.empty()) gltf.erase("buffers");
    dropExtension(gltf, "extensionsUsed");
    dropExtension(gltf, "extensionsRequired");
    return makeGlb(gltf.dump(), bin);
}

GlbChunks splitGlb(const std::vector<std::uint8_t>& bytes, const std::filesystem::path& file) {
    auto broken = [&](const char* what) {
        throw Error(ErrorCode::Malformed, file, std::string("not a valid GLB: ") + what);
    };
    if (bytes.size() < 20 || readU32(bytes, 0) != kGlbMagic) broken("bad magic");
    if (readU32(bytes, 4) != 2) broken("not glTF 2.0");
    const std::size_t total = std::min<std::size_t>(readU32(bytes, 8), bytes.size());
    GlbChunks out;
    std::size_t at = 12;
    bool first = true;
    while (at + 8 <= total) {
        const std::size_t len = readU32(bytes, at), type = readU32(bytes, at + 4);
        if (len > total - at - 8) broken("a chunk runs past the end of the file");
        const auto* data = bytes.data() + at + 8;
        if (first && type != kChunkJson) broken("the first chunk is not JSON");
        if (type == kChunkJson && first) out.json.assign(reinterpret_cast<const char*>(data), len);
        if (type == kChunkBin && !first && out.bin.empty()) out.bin.assign(data, data + len);
        first = false;
        at += 8 + len;
    }
    if (first) broken("no JSON chunk");
    return out;
}

std::vector<std::uint8_t> makeGlb(const std::string& json, const std::vector<std::uint8_t>& bin) {
    const std::size_t jsonBytes = pad4(json.size()), binBytes = pad4(bin.size());
    const std::size_t total = 12 + 8 + jsonBytes + (bin.empty() ? 0 : 8 + binBytes);
    std::vector<std::uint8_t> out;
    out.reserve(total);
    putU32(out, kGlbMagic);
    putU32(out, 2);
    putU32(out, static_cast<std::uint32_t>(total));
    putU32(out, static_cast<std::uint32_t>(jsonBytes));
    putU32(out, kChunkJson);
    out.insert(out.end(), json.begin(), json.end());
    out.resize(20 + jsonBytes, ' ');
    if (bin.empty()) return out;
    putU32(out, static_cast<std::uint32_t>(binBytes));
    putU32(out, kChunkBin);
    out.insert(out.end(), bin.begin(), bin.end());
    out.resize(total, 0);
    return out;
}

} // namespace hlod
