// glTF 2.0 binary (GLB) writer for a flat scene of triangle meshes: each mesh one primitive with
// positions, optional normals, texture coordinates and vertex colours (COLOR_0 as normalised
// unsigned bytes, linear) and one PBR material (base colour factor and optional base colour
// texture, metallic 0, roughness 1, the alpha mode and cut-off given, doubleSided, emissive
// factor and texture; an emissive factor above 1 is written as its largest channel in
// KHR_materials_emissive_strength and the factor divided by it); each node
// places one mesh (or none) with a translation / rotation / scale in double precision (so
// content far from the origin stays exact), all nodes roots of the one scene. Identical
// materials are written once; a mesh referenced by several nodes is stored once (glTF
// instancing by reference).
// Follows the Khronos glTF 2.0 specification, section 4.4 (GLB container) and 5 (JSON
// schema): little-endian chunks padded to 4 bytes, POSITION min/max present, index type the
// smallest of unsigned short / unsigned int that fits.
//
// Compact JSON (tile contents are small files, their JSON used to outweigh their geometry):
// one buffer view per kind of stream for the whole file (all positions, all normals, all uvs,
// all colours, all 16-bit and all 32-bit indices; embedded images one view each), accessors
// being ranges of them (byteOffset), as gltfpack writes them. Properties at their default value
// are left out (byteOffset 0, primitive mode 4, roughness 1, a white base colour, alpha cut-off
// 0.5, repeat wrapping); min/max only on POSITION, where the specification requires them;
// material factors as the shortest decimal that reads back as the same float, whole numbers
// without a fraction; a material is named only when it has a name of its own
// (GlbMesh::materialName), a mesh only when it has one; no white space. Identical images (same
// URI) and their textures are written once, the one sampler once.
//
// Compression (GlbCompression::Meshopt): KHR_mesh_quantization + EXT_meshopt_compression, both
// required (GlbMeshopt.h: 16-bit grid positions whose offset and step the referencing nodes'
// transforms carry, octahedral normals, exponential uvs, meshopt vertex and index codecs; each
// buffer view compressed as one stream). The compressed streams live in buffer 0 (the BIN
// chunk); buffer 1 is the extension's fallback buffer without data. Validators that do not
// know the extension (the Khronos glTF validator) see buffer 0 used only through it and report
// it "may be unused"; so when nothing else (an embedded image) is in buffer 0, the accessor
// smallest once decoded (in a leaf group, one small mesh's normals or colours; in a single
// mesh, its normals: 4 bytes a vertex) also gets a plain copy of its data there, its decoded
// bytes, the same a meshopt decoder makes, and reads that. None: plain float attributes,
// nothing required.
//
// Output bytes depend only on the input (deterministic, suitable for content hashing).
// A mesh without triangles is not written (its nodes carry no mesh).
// Failure: Error(InvalidArgument) when stream sizes disagree, an index is out of range or a node
// names a mesh that does not exist; writeGlbFile throws Error(Io) naming the file. writeGlbFile
// writes a temporary file next to the target and renames it, so a reader never sees half a file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "pipeline/io/GltfTrs.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

enum class GlbCompression { None, Meshopt };

const char* toString(GlbCompression compression);
// Parses "none", "meshopt"; throws Error(InvalidArgument) otherwise.
GlbCompression glbCompressionFromString(const std::string& text);

struct GlbMesh {
    std::string name;
    glm::dvec3 translation{0.0}; // single-mesh encodeGlb: its node's translation, metres
    std::span<const glm::vec3> positions;
    std::span<const glm::vec3> normals;  // empty or one per position
    std::span<const glm::vec2> uvs;      // empty or one per position
    std::span<const glm::u8vec4> colors; // empty or one per position (linear RGBA)
    std::span<const std::uint32_t> indices;
    glm::vec4 baseColor{1.0f};
    std::string materialName; // empty: the material has no name
    // Optional base colour texture (PNG or JPEG bytes, see TextureImage.h), embedded in the BIN
    // chunk and sampled with TEXCOORD_0 (repeat wrap, linear filtering). Ignored without uvs.
    std::span<const std::uint8_t> image;
    std::string imageMimeType;
    // Or a texture file shared by several GLBs: a relative URI (no "..", no scheme) resolved
    // against the GLB's folder. Used when `image` is empty; also ignored without uvs.
    std::string imageUri;
    // Meshopt only: the position grid asked for (metres of the mesh's frame; 0 = the finest
    // 16 bits allow). The grid used is positionGrid (GlbMeshopt.h) of it over the mesh's bounds.
    double positionStep = 0.0;
    // glTF alphaMode as written (MASK: textured cut-outs, e.g. a proxy atlas with alpha;
    // BLEND: baseColor.a and the texture's alpha blend); alphaCutoff for MASK only.
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
    // Linear RGB emissive factor (0: none). Its texture, sampled with TEXCOORD_0 and ignored
    // without uvs: the base colour image again (emissiveUsesImage: one texture for both, as a
    // proxy atlas standing for originals whose emission follows their texture), or a shared
    // file like imageUri (emissiveUri); none when neither.
    glm::vec3 emissive{0.0f};
    bool emissiveUsesImage = false;
    std::string emissiveUri;
};

struct GlbNode {
    std::string name;
    int mesh = -1; // index into GlbScene::meshes; -1 = an empty node
    Trs trs;       // the mesh's frame in the scene (see GltfTrs.h)
};

struct GlbScene {
    std::vector<GlbMesh> meshes;
    std::vector<GlbNode> nodes; // roots of the scene, in this order
    GlbCompression compression = GlbCompression::None;
};

std::vector<std::uint8_t> encodeGlb(const GlbScene& scene);

// One mesh under one node translated by mesh.translation.
std::vector<std::uint8_t> encodeGlb(const GlbMesh& mesh,
                                    GlbCompression compression = GlbCompression::None);

void writeGlbFile(const std::filesystem::path& file, const GlbMesh& mesh);

// Bytes of the GLB encodeGlb(mesh) produces (for statistics).
std::size_t glbByteSize(const GlbMesh& mesh);

} // namespace hlod
