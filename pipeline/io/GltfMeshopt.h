// Reading glTF files whose geometry is compressed with EXT_meshopt_compression (Khronos
// extension specification; the bitstreams are meshoptimizer's vertex codec version 0, index
// codec version 1 and index sequence codec, the filters OCTAHEDRAL, QUANTIZATION and
// EXPONENTIAL). tinygltf 2.7 cannot: the extension's fallback buffers have no data (or no
// URI). So before tinygltf sees the file, decodeMeshoptGltf rewrites it into a plain GLB in
// memory: every buffer view becomes a plain view of one new buffer (compressed views decoded
// with meshoptimizer and their filters undone, plain views copied), the extension is dropped
// from extensionsUsed / extensionsRequired, everything else (images by URI, accessors, nodes,
// other extensions such as KHR_mesh_quantization) stays as it was.
//
// Contract: `buffers` holds the bytes of every buffer of `gltf` in order, empty for the
// extension's fallback buffers (which are never read). Untrusted input: every offset, length,
// count and stride is checked before use, counts above `maxElements` are refused before
// allocating, and decoder failures are errors. Failure: Error(Malformed) naming `file` and what
// is wrong (for instance "buffer view 3: meshopt data is corrupt"), Error(TooLarge) for counts
// above the cap.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

namespace hlod {

bool usesMeshopt(const nlohmann::json& gltf);

// Whether buffer `index` of `gltf` is an EXT_meshopt_compression fallback buffer.
bool isMeshoptFallback(const nlohmann::json& gltf, std::size_t index);

// The GLB bytes of the decoded document (see above).
std::vector<std::uint8_t> decodeMeshoptGltf(nlohmann::json gltf,
                                            const std::vector<std::vector<std::uint8_t>>& buffers,
                                            const std::filesystem::path& file,
                                            std::size_t maxElements);

// A GLB's JSON text and BIN chunk (empty when absent). Error(Malformed) naming `file` when the
// container is broken (bad magic or version, chunk lengths past the end).
struct GlbChunks {
    std::string json;
    std::vector<std::uint8_t> bin;
};
GlbChunks splitGlb(const std::vector<std::uint8_t>& bytes, const std::filesystem::path& file);

// Writes a GLB container around a JSON document and one BIN chunk.
std::vector<std::uint8_t> makeGlb(const std::string& json, const std::vector<std::uint8_t>& bin);

} // namespace hlod
