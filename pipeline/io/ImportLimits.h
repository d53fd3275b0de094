// The import budget (issue 22): how much work and memory one scene file may make the importers
// spend, so a small file cannot expand into minutes and gigabytes. All limits live here; the
// importers enforce them and `hlod info` prints them. A file over a limit is refused with
// Error(TooLarge) naming the file, what was counted and the limit (and the flag that raises
// it), before the expansion is allocated where the format allows it. Textures are the
// exception: an image over its budget is not decoded and its materials keep their colour (the
// documented fallback for any unreadable texture, with a warning that names the limit).
//
// Expansions this guards against, each from a file of a few hundred bytes:
//  - instancing DAGs: a COLLADA <node> or STEP sub-assembly placed twice at each of 30 levels
//    is 2^30 placements (assimp and XCAF expand them into a tree of nodes);
//  - declared counts: a PLY/OFF/STL header or a glTF accessor declaring billions of elements;
//  - shared data: thousands of glTF primitives reading the same accessors;
//  - images: a PNG of 60000 x 60000 texels (deflate packs ~1000 zero texels a byte), or many
//    distinct large images in one file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace hlod {

struct ImportLimits {
    // Elements one declared array may hold (a glTF accessor, a PLY/OFF element list, a binary
    // STL's triangles), checked before allocating. 50 M vertices of position + normal + uv is
    // ~1.6 GB in memory: beyond any single mesh the pipeline bakes in reasonable time.
    std::size_t maxElements = 50'000'000;
    // Triangles stored in the file's meshes (each counted once however often it is placed).
    // Held as 12 bytes of indices plus their vertices (positions, normals, uvs: 32+ bytes
    // each): ~30 bytes a triangle for indexed meshes, ~85 for triangle soups (measured: 100 M
    // non-indexed glTF triangles peaked at 8.3 GB), so 50 M is 1.5-4 GB. `--max-unique-triangles`.
    std::uint64_t maxUniqueTriangles = 50'000'000;
    // Placed meshes (and scene nodes) after expanding every level of instancing. Measured on
    // a COLLADA file expanded by assimp: ~1.6 KB of peak memory per node (assimp's aiNode
    // carries a fixed 1 KB name buffer; ours holds two double matrices and is sent back from
    // the isolated reader), so 2 M is ~3.2 GB, within the readers' 8 GB limit with room for
    // the geometry. `--max-instances`.
    std::uint64_t maxInstances = 2'000'000;
    // Triangles of all placed meshes, as `hlod info` counts them ("triangles"). Importing
    // them is cheap (instances are references), baking is not: the bake reads every placed
    // triangle at the leaves, ~16 k per CPU second with atlases (docs/benchmarks.md: 180 k
    // triangles of cg57-cruiser in 10.9 s), so 1 G is ~17 hours of CPU: a file over it is an
    // expansion, not a scene to build. `--max-triangles`.
    std::uint64_t maxTriangles = 1'000'000'000;
    // Texels of one decoded image: 8192 x 8192 (256 MB as RGBA; stb_image holds about twice
    // that while decoding). Larger images are not decoded.
    std::uint64_t maxImageTexels = 64ull << 20;
    // Texels of all images decoded for one file: 512 Mi texels is 2 GB of RGBA (32 textures of
    // 4096 x 4096, 128 of 2048 x 2048; measured: ten 8192 x 8192 PNGs, 2.6 MB of files, took
    // 3 GB and 9 s to decode). Images beyond it are not decoded. `--max-texels`.
    std::uint64_t maxTexels = 512ull << 20;
};

// Throws Error(TooLarge) naming `file`: "<what>, over the import limit of <limit> (<flag> raises
// it)"; `what` says what was counted ("the assembly places 1073741824 parts"), `flag` may be
// null for a limit without one.
[[noreturn]] void throwOverLimit(const std::filesystem::path& file, const std::string& what,
                                 std::uint64_t limit, const char* flag);

} // namespace hlod
