// The base colour texture and surface sides of every object of an AC3D file (.ac, and TORCS's
// multi-texture .acc variant), read from the file itself because assimp 5.2's AC3D loader keeps the
// *last* `texture` line of an object. TORCS track objects carry up to four (base, tiled, skids,
// shad: "texture "tr-road1.rgb" base", "texture "raceline.png" tiled", "texture
// empty_texture_no_mapping skids", ...); the first is the base colour, and its texture
// coordinates are the first pair of every `refs` entry, which is the pair assimp reads.
//
// Format: the AC3D file format description (Inivis, "AC3D file format", ac3d.org): OBJECT
// blocks with name, texture, numvert (N vertex lines follow), numsurf (SURF/mat/refs M blocks,
// M reference lines each) and kids N (N child OBJECT blocks follow, depth first). assimp turns
// every object into one aiNode with the same children in the same order, so the tree read here
// pairs up with assimp's node tree child by child.
// Surfaces: the SURF flags (low nibble the type: 0 polygon, 1 closed line, 2 line, 4 TORCS's
// triangle strip; bit 0x20 two-sided) and material index of every surface, which assimp 5.2
// reads but does not pass on. ac3dTwoSidedMaterials maps them onto assimp's materials.
// Failure: nullopt when the file cannot be read or its structure is not understood (the caller
// then keeps assimp's textures and sides); never throws.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace hlod {

struct Ac3dSurface {
    unsigned flags = 0;
    unsigned material = 0; // index into the file's MATERIAL lines, as written
    std::size_t refs = 0;
};

struct Ac3dObject {
    std::string name;
    std::string firstTexture; // empty when the object names no texture
    std::size_t vertices = 0;
    std::vector<Ac3dSurface> surfaces; // in file order
    std::vector<Ac3dObject> kids;
};

struct Ac3dFile {
    std::size_t materials = 0;       // MATERIAL lines
    std::vector<Ac3dObject> objects; // top level, in file order
};

// The file's structure.
std::optional<Ac3dFile> readAc3dFile(const std::filesystem::path& file);

// Parses AC3D text (exposed for tests).
std::optional<Ac3dFile> parseAc3dFile(const std::string& text);

// Per aiMaterial assimp 5.2's AC3D loader makes for `file` (one per object and material its
// surfaces use, objects depth first, materials in index order: AC3DImporter::
// ConvertObjectSection), whether a polygon or strip of that object and material is two-sided
// (SURF flag 0x20). assimp puts all surfaces of one object and material in one mesh, so a mesh
// is two-sided when any of its surfaces is (a one-sided face drawn from behind too costs
// overdraw; a two-sided face culled is a hole). nullopt when the count differs from
// `assimpMaterials` (the trees do not pair up).
std::optional<std::vector<bool>> ac3dTwoSidedMaterials(const Ac3dFile& file,
                                                       std::size_t assimpMaterials);

bool isAc3dPath(const std::filesystem::path& file);

} // namespace hlod
