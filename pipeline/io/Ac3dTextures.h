// The base colour texture of every object of an AC3D file (.ac, and TORCS's multi-texture .acc
// variant), read from the file itself because assimp 5.2's AC3D loader keeps the *last*
// `texture` line of an object. TORCS track objects carry up to four (base, tiled, skids, shad:
// "texture "tr-road1.rgb" base", "texture "raceline.png" tiled", "texture
// empty_texture_no_mapping skids", ...); the first is the base colour, and its texture
// coordinates are the first pair of every `refs` entry, which is the pair assimp reads.
//
// Format: the AC3D file format description (Inivis, "AC3D file format", ac3d.org): OBJECT
// blocks with name, texture, numvert (N vertex lines follow), numsurf (SURF/mat/refs M blocks,
// M reference lines each) and kids N (N child OBJECT blocks follow, depth first). assimp turns
// every object into one aiNode with the same children in the same order, so the tree read here
// pairs up with assimp's node tree child by child.
// Failure: nullopt when the file cannot be read or its structure is not understood (the caller
// then keeps assimp's textures); never throws.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace hlod {

struct Ac3dObject {
    std::string name;
    std::string firstTexture; // empty when the object names no texture
    std::vector<Ac3dObject> kids;
};

// The top-level objects of the file, in file order.
std::optional<std::vector<Ac3dObject>> readAc3dObjects(const std::filesystem::path& file);

// Parses AC3D text (exposed for tests).
std::optional<std::vector<Ac3dObject>> parseAc3dObjects(const std::string& text);

bool isAc3dPath(const std::filesystem::path& file);

} // namespace hlod
