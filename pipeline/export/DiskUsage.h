// What files cost on disk: the blocks the file system allocated for them (POSIX stat st_blocks,
// in 512-byte units), which is what `du` counts, plus how many there are. A small file still
// takes a whole block (4 KiB on ext4), which is why a package of many tiny tiles costs more
// than its bytes (issue 18). Hard links are counted once.
//
// The source of a build is its scene files plus every file they pulled in (Scene::sourceFiles,
// Scene::referencedFiles and the materials' texture files that exist): what a user has to keep
// to have the scene. A folder among them counts with every file below it.
// Failure: none; files that cannot be stat'ed (gone, or names like "sample:plant") count 0.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "pipeline/scene/Scene.h"

namespace hlod {

struct DiskFootprint {
    std::size_t files = 0;
    std::uintmax_t bytes = 0;       // sizes
    std::uintmax_t bytesOnDisk = 0; // allocated blocks
};

DiskFootprint filesFootprint(const std::vector<std::filesystem::path>& paths);

DiskFootprint sourceFootprint(const Scene& scene);

// The file system's block size at `dir` (statvfs f_bsize; 4096 when unknown).
std::uintmax_t blockSizeAt(const std::filesystem::path& dir);

// `size` bytes rounded up to whole blocks.
inline std::uintmax_t blocksFor(std::uintmax_t size, std::uintmax_t blockSize) {
    return (size + blockSize - 1) / blockSize * blockSize;
}

} // namespace hlod
