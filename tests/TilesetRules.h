// The 3D Tiles 1.1 rules our packages promise (DESIGN.md, the package), checked tile by tile:
// relative content URIs inside the package that exist, geometricError > 0 on inner tiles and
// 0 on leaves, never growing from parent to child, boxes (Z-up, axis aligned) that contain
// their children's. Shared by the package unit tests and the end-to-end CLI tests.
#pragma once

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>

#include <glm/glm.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace hlod::test {

// Z-up box (center, 3 half axes aligned with x, y, z) as min/max.
inline std::pair<glm::dvec3, glm::dvec3> boxMinMax(const nlohmann::json& b) {
    const glm::dvec3 c(b[0], b[1], b[2]);
    const glm::dvec3 h(b[3].get<double>(), b[7].get<double>(), b[11].get<double>());
    return {c - h, c + h};
}

// Checks `tile` and its subtree; counts tiles and tiles with content.
inline void checkTile(const nlohmann::json& tile, const std::filesystem::path& dir,
                      std::size_t& tiles, std::size_t* contents = nullptr) {
    ++tiles;
    const auto [mn, mx] = boxMinMax(tile["boundingVolume"]["box"]);
    const double err = tile["geometricError"];
    if (tile.contains("content")) {
        if (contents) ++*contents;
        const std::string uri = tile["content"]["uri"];
        EXPECT_FALSE(std::filesystem::path(uri).is_absolute()) << uri;
        EXPECT_EQ(uri.find(".."), std::string::npos) << uri;
        EXPECT_TRUE(std::filesystem::is_regular_file(dir / uri)) << uri;
    }
    if (!tile.contains("children")) {
        EXPECT_EQ(err, 0.0); // leaves hold the original meshes: no error
        return;
    }
    EXPECT_GT(err, 0.0);
    for (const auto& child : tile["children"]) {
        EXPECT_LE(child["geometricError"].get<double>(), err);
        const auto [cmn, cmx] = boxMinMax(child["boundingVolume"]["box"]);
        for (int a = 0; a < 3; ++a) {
            EXPECT_LE(mn[a], cmn[a] + 1e-6 * (1.0 + std::abs(cmn[a])));
            EXPECT_GE(mx[a], cmx[a] - 1e-6 * (1.0 + std::abs(cmx[a])));
        }
        checkTile(child, dir, tiles, contents);
    }
}

} // namespace hlod::test
