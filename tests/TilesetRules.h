// The 3D Tiles 1.1 rules our packages promise (README.md, the package), checked tile by tile as
// the official 3D Tiles validator checks them: relative content URIs inside the package that
// exist; geometricError > 0 on tiles with children and 0 on tiles without, never growing from
// parent to child, and the tileset's at least the root's; tile transforms affine; bounding
// boxes (in their tile's frame, which the transforms of the tile and its ancestors place) that
// contain their children's boxes and every vertex of their content (decoded from the GLB,
// turned Z up as runtimes turn glTF content); every extension named in the tileset declared in
// extensionsUsed, and extensionsRequired within extensionsUsed. Shared by the package unit
// tests and the end-to-end CLI tests.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <utility>

#include <glm/glm.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "pipeline/io/Import.h"

namespace hlod::test {

// A box's centre and half axes (columns), in its tile's frame.
struct Obb {
    glm::dvec3 c;
    glm::dmat3 h;
};

inline Obb obbOf(const nlohmann::json& b) {
    Obb o;
    o.c = glm::dvec3(b[0], b[1], b[2]);
    for (int a = 0; a < 3; ++a)
        o.h[a] = glm::dvec3(b[3 + 3 * a], b[4 + 3 * a], b[5 + 3 * a]);
    return o;
}

// Z-up box (center, 3 half axes aligned with x, y, z) as min/max, in its tile's frame.
inline std::pair<glm::dvec3, glm::dvec3> boxMinMax(const nlohmann::json& b) {
    const glm::dvec3 c(b[0], b[1], b[2]);
    const glm::dvec3 h(b[3].get<double>(), b[7].get<double>(), b[11].get<double>());
    return {c - h, c + h};
}

inline glm::dmat4 transformOf(const nlohmann::json& tile) {
    glm::dmat4 m(1.0);
    if (!tile.contains("transform")) return m;
    const auto& t = tile["transform"];
    EXPECT_EQ(t.size(), 16u);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            m[c][r] = t[static_cast<std::size_t>(c * 4 + r)].get<double>();
    EXPECT_EQ(m[0][3], 0.0); // affine: last row 0 0 0 1
    EXPECT_EQ(m[1][3], 0.0);
    EXPECT_EQ(m[2][3], 0.0);
    EXPECT_EQ(m[3][3], 1.0);
    EXPECT_NE(glm::determinant(glm::dmat3(m)), 0.0);
    return m;
}

// A box placed by its tile's world transform, ready for point tests.
class PlacedBox {
public:
    PlacedBox(const Obb& o, const glm::dmat4& world)
        : c_(o.c), toBox_(glm::inverse(o.h)), toLocal_(glm::inverse(world)),
          tol_(1e-6 * (1.0 + glm::length(o.c) / glm::length(o.h[0] + o.h[1] + o.h[2]))) {}
    // Whether world point p lies in the box (tolerance relative to its size and offset).
    bool holds(const glm::dvec3& p) const {
        const glm::dvec3 u = toBox_ * (glm::dvec3(toLocal_ * glm::dvec4(p, 1.0)) - c_);
        return std::abs(u.x) <= 1.0 + tol_ && std::abs(u.y) <= 1.0 + tol_ &&
               std::abs(u.z) <= 1.0 + tol_;
    }

private:
    glm::dvec3 c_;
    glm::dmat3 toBox_; // box coordinates in [-1, 1]
    glm::dmat4 toLocal_;
    double tol_;
};

inline std::array<glm::dvec3, 8> corners(const Obb& o, const glm::dmat4& world) {
    std::array<glm::dvec3, 8> out;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 s(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
        out[i] = glm::dvec3(world * glm::dvec4(o.c + o.h * s, 1.0));
    }
    return out;
}

// Every vertex of a tile's glTF content, in the tile's frame (Z up), decoded by our importer.
class ContentVertices {
public:
    const std::vector<glm::dvec3>& of(const std::filesystem::path& glb) {
        auto it = cache_.find(glb);
        if (it != cache_.end()) return it->second;
        std::vector<glm::dvec3>& out = cache_[glb];
        const Scene s = importGltf(glb, ImportOptions{});
        for (const MeshInstance& inst : s.instances) {
            const glm::dmat4& w = s.nodes[inst.node].world;
            for (const glm::vec3& v : s.meshes[inst.mesh].positions) {
                const glm::dvec3 y(w * glm::dvec4(glm::dvec3(v), 1.0));
                out.push_back({y.x, -y.z, y.y}); // glTF Y up -> tiles Z up
            }
        }
        return out;
    }

private:
    std::map<std::filesystem::path, std::vector<glm::dvec3>> cache_;
};

// The names under every "extensions" object of a JSON tree.
inline void extensionsNamed(const nlohmann::json& j, std::set<std::string>& out) {
    if (j.is_object()) {
        for (auto it = j.begin(); it != j.end(); ++it) {
            if (it.key() == "extensions" && it.value().is_object()) {
                for (auto e = it.value().begin(); e != it.value().end(); ++e)
                    out.insert(e.key());
            }
            extensionsNamed(it.value(), out);
        }
    } else if (j.is_array()) {
        for (const auto& e : j)
            extensionsNamed(e, out);
    }
}

struct TileCheck {
    std::filesystem::path dir;
    std::size_t tiles = 0;
    std::size_t contents = 0;
    bool checkContent = true; // decode every content and check its vertices against the box
    ContentVertices vertices;
};

// Checks `tile` (placed by `parentWorld`) and its subtree.
inline void checkTile(const nlohmann::json& tile, TileCheck& tc,
                      const glm::dmat4& parentWorld = glm::dmat4(1.0)) {
    ++tc.tiles;
    const glm::dmat4 world = parentWorld * transformOf(tile);
    const PlacedBox box(obbOf(tile["boundingVolume"]["box"]), world);
    const double err = tile["geometricError"];
    if (tile.contains("content")) {
        ++tc.contents;
        const std::string uri = tile["content"]["uri"];
        EXPECT_FALSE(std::filesystem::path(uri).is_absolute()) << uri;
        EXPECT_EQ(uri.find(".."), std::string::npos) << uri;
        EXPECT_TRUE(std::filesystem::is_regular_file(tc.dir / uri)) << uri;
        if (tc.checkContent && std::filesystem::is_regular_file(tc.dir / uri)) {
            std::size_t outside = 0;
            for (const glm::dvec3& v : tc.vertices.of(tc.dir / uri))
                outside += box.holds(glm::dvec3(world * glm::dvec4(v, 1.0))) ? 0 : 1;
            EXPECT_EQ(outside, 0u) << uri << ": vertices outside the tile's box";
        }
    }
    if (!tile.contains("children")) {
        EXPECT_EQ(err, 0.0); // leaves hold the original meshes: no error
        return;
    }
    EXPECT_GT(err, 0.0);
    for (const auto& child : tile["children"]) {
        EXPECT_LE(child["geometricError"].get<double>(), err);
        const glm::dmat4 childWorld = world * transformOf(child);
        for (const glm::dvec3& p : corners(obbOf(child["boundingVolume"]["box"]), childWorld))
            EXPECT_TRUE(box.holds(p)) << "a child's box leaves its parent's";
        checkTile(child, tc, world);
    }
}

// The whole tileset: version, refinement, the top geometric error, extensions, every tile.
inline void checkTileset(const nlohmann::json& ts, TileCheck& tc) {
    EXPECT_EQ(ts["asset"]["version"], "1.1");
    EXPECT_EQ(ts["root"]["refine"], "REPLACE");
    EXPECT_GE(ts["geometricError"].get<double>(), ts["root"]["geometricError"].get<double>());
    std::set<std::string> named, used, required;
    extensionsNamed(ts, named);
    for (const auto& e : ts.value("extensionsUsed", nlohmann::json::array()))
        used.insert(e.get<std::string>());
    for (const auto& e : ts.value("extensionsRequired", nlohmann::json::array()))
        required.insert(e.get<std::string>());
    for (const std::string& e : named)
        EXPECT_TRUE(used.count(e)) << e << " is used but not declared";
    for (const std::string& e : required)
        EXPECT_TRUE(used.count(e)) << e << " is required but not used";
    checkTile(ts["root"], tc);
}

} // namespace hlod::test
