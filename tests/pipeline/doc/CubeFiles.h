// Tiny scenes on disk for the graph and document tests: one GLB file per unit cube, placed by
// its node translation, so a list of files is a scene whose instance i is file i (importScene
// keeps the order of its inputs) and every cluster can be worked out by hand.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "pipeline/io/GlbWriter.h"

namespace hlod::test {

// Writes cube_<i>.glb for each corner into `dir` and returns the paths in order.
inline std::vector<std::filesystem::path> writeCubeFiles(const std::filesystem::path& dir,
                                                         const std::vector<glm::dvec3>& corners) {
    std::vector<glm::vec3> positions;
    for (int i = 0; i < 8; ++i)
        positions.emplace_back((i & 1) ? 1.0f : 0.0f, (i & 2) ? 1.0f : 0.0f, (i & 4) ? 1.0f : 0.0f);
    const std::vector<std::uint32_t> indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6,
                                                0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7,
                                                0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
    std::vector<std::filesystem::path> files;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        GlbMesh m;
        m.name = "cube";
        m.translation = corners[i];
        m.positions = positions;
        m.indices = indices;
        files.push_back(dir / ("cube_" + std::to_string(i) + ".glb"));
        writeGlbFile(files.back(), m);
    }
    return files;
}

// The seven cubes of LevelMergerTest: a touching row A, B, C at x = 0, 1, 2 and two far pairs
// D, E (x = 100, 102) and F, G (x = 200, 202). With AABB and k = 0 they cluster into
// ABC = {0,1,2}, DE = {3,4}, FG = {5,6}, {ABC, DE}, root {.., FG}: five inner nodes.
inline std::vector<std::filesystem::path> writeSevenCubes(const std::filesystem::path& dir) {
    return writeCubeFiles(
        dir, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {100, 0, 0}, {102, 0, 0}, {200, 0, 0}, {202, 0, 0}});
}

} // namespace hlod::test
