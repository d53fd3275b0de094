// The engine-ready HLOD package (DESIGN.md "The package"):
//   DIR/tileset.json   OGC 3D Tiles 1.1, one tile per cluster node, refine REPLACE, box
//                      bounding volumes, geometricError = the node's proxy error (0 at leaves)
//   DIR/tiles/N.glb    glTF 2.0 content of node N: its proxy (inner) or original mesh (leaf)
//   DIR/hlod.json      the tree, screen sizes, switch distances, parameters, statistics
//
// Axes: content is glTF (Y up, as our scenes from glTF/AC3D); 3D Tiles is Z up, and runtimes
// rotate glTF content by +90° about X, so bounding boxes are written in that Z-up frame:
// (x, y, z)_content -> (x, -z, y)_tiles.
// Runtime switching: a 3D Tiles runtime refines a tile when geometricError · H /
// (2 d tan(fov/2)) > maximumScreenSpaceError. With geometricError = t · D / S this happens
// exactly when the projected diameter exceeds S if maximumScreenSpaceError = t (recorded in
// hlod.json as "maximumScreenSpaceError").
//
// Atomicity: writePackage builds everything in a temporary sibling folder and renames it into
// place; on any failure or cancellation the temporary folder is removed and an existing package
// at DIR is left untouched.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/core/Progress.h"
#include "pipeline/export/Geo.h"
#include "pipeline/proxy/ProxyBaker.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

struct PackageOptions {
    std::optional<GeoLocation> geo;  // root transform on the globe; local frame otherwise
    std::vector<std::string> inputs; // source scene paths as given
    nlohmann::json parameters;       // the parameters that produced the tree and proxies
    nlohmann::json statistics;       // thesis-style tables, if the caller has them
};

struct PackageSummary {
    std::size_t tiles = 0;
    std::size_t files = 0;
    std::uintmax_t bytes = 0;
};

PackageSummary writePackage(const std::filesystem::path& dir, const Scene& scene,
                            const ClusterTree& tree, const BakeResult& bake,
                            const BakeParams& bakeParams, const PackageOptions& options,
                            const Progress& progress = {});

// tileset.json of a package (exposed for tests).
nlohmann::json buildTileset(const ClusterTree& tree, const BakeResult& bake,
                            const std::vector<bool>& hasContent,
                            const std::optional<GeoLocation>& geo);

// What a package holds, read back from hlod.json (and checked against the folder).
struct PackageInfo {
    std::filesystem::path dir;
    nlohmann::json manifest;
    ClusterTree tree;
    std::vector<std::string> content; // per node: relative GLB path or empty
    std::size_t leafTriangles = 0;    // sum over leaves (the original scene)
    std::size_t proxyTriangles = 0;   // sum over inner nodes
};

bool isPackageFolder(const std::filesystem::path& dir);

// Throws Error(Malformed) naming the file when hlod.json or tileset.json is missing or wrong,
// a content path is unsafe (absolute, "..") or a content file is missing.
PackageInfo readPackage(const std::filesystem::path& dir);

// The original scene back from a package: every leaf GLB, under nodes named as in the source.
Scene readPackageScene(const PackageInfo& info);

} // namespace hlod
