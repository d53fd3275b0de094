// Minimal glTF 2.0 binary (GLB) writer for one triangle mesh: positions, optional normals,
// texture coordinates and vertex colours (COLOR_0 as normalised unsigned bytes, linear), one
// PBR material (base colour factor and optional embedded base colour texture, metallic 0,
// roughness 1; alpha below 1 makes it BLEND, alphaMask MASK), one node carrying the mesh's
// translation in double precision (so world-space proxies far from the origin stay exact).
// Follows the Khronos glTF 2.0 specification, section 4.4 (GLB container) and 5 (JSON
// schema): little-endian chunks padded to 4 bytes, POSITION min/max present, index type the
// smallest of unsigned short / unsigned int that fits.
//
// Output bytes depend only on the input (deterministic, suitable for content hashing).
// An empty mesh (no triangles) produces a valid file whose node has no mesh.
// Failure: Error(InvalidArgument) when stream sizes disagree or an index is out of range;
// writeGlbFile throws Error(Io) naming the file. writeGlbFile writes a temporary file next to
// the target and renames it, so a reader never sees half a file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace hlod {

struct GlbMesh {
    std::string name;
    glm::dvec3 translation{0.0}; // node translation, metres
    std::span<const glm::vec3> positions;
    std::span<const glm::vec3> normals;  // empty or one per position
    std::span<const glm::vec2> uvs;      // empty or one per position
    std::span<const glm::u8vec4> colors; // empty or one per position (linear RGBA)
    std::span<const std::uint32_t> indices;
    glm::vec4 baseColor{1.0f};
    // Optional base colour texture (PNG or JPEG bytes, see TextureImage.h), embedded in the BIN
    // chunk and sampled with TEXCOORD_0 (repeat wrap, linear filtering). Ignored without uvs.
    std::span<const std::uint8_t> image;
    std::string imageMimeType;
    // Or a texture file shared by several GLBs: a relative URI (no "..", no scheme) resolved
    // against the GLB's folder. Used when `image` is empty; also ignored without uvs.
    std::string imageUri;
    // glTF alphaMode MASK with this cut-off (textured cut-outs, e.g. a proxy atlas with
    // alpha); otherwise OPAQUE, or BLEND when baseColor.a < 1.
    bool alphaMask = false;
    float alphaCutoff = 0.5f;
};

std::vector<std::uint8_t> encodeGlb(const GlbMesh& mesh);

void writeGlbFile(const std::filesystem::path& file, const GlbMesh& mesh);

// Bytes of the GLB encodeGlb would produce, without building it (for statistics).
std::size_t glbByteSize(const GlbMesh& mesh);

} // namespace hlod
