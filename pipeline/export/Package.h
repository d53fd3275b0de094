// The engine-ready HLOD package (README "The package", docs/architecture.md; issue 18, a
// compact package):
//   DIR/tileset.json          OGC 3D Tiles 1.1, refine REPLACE, box bounding volumes,
//                             geometricError = the node's proxy error (0 for leaf groups),
//                             extras.hlod: placement and a view that frames it (Placement.h)
//   DIR/tiles/HASH.glb        glTF 2.0 content, named by its bytes' hash: a proxy, or the leaves
//                             under one node (PackageLayout.h); equal contents are one file
//   DIR/tiles/textures/HASH.* the leaves' base colour textures, once each
//   DIR/hlod.json             the tree, screen sizes, switch distances, parameters, statistics,
//                             and where every node's geometry is (PackageManifest.cpp)
//
// Axes: content is glTF (Y up, as our scenes from glTF/AC3D); 3D Tiles is Z up, and runtimes
// rotate glTF content by +90° about X, so bounding boxes and transforms are written in that
// Z-up frame: (x, y, z)_content -> (x, -z, y)_tiles.
// Runtime switching: a 3D Tiles runtime refines a tile when geometricError · H /
// (2 d tan(fov/2)) > maximumScreenSpaceError. With geometricError = t · D / S this happens
// exactly when the projected diameter exceeds S if maximumScreenSpaceError = t (recorded in
// hlod.json as "maximumScreenSpaceError").
// Compression: PackageOptions::compression (default meshopt: KHR_mesh_quantization +
// EXT_meshopt_compression, GlbWriter.h); none writes plain glTF with the same layout.
//
// Atomicity: writePackage builds everything in a temporary sibling folder and renames it into
// place; on any failure or cancellation the temporary folder is removed and an existing package
// at DIR is left untouched. Caching: a file whose bytes the package being replaced already has
// (same name, same bytes) is hard-linked from it instead of written again, so a rebuild after a
// parameter change writes only what changed (PackageSummary::written / reused).
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/core/Progress.h"
#include "pipeline/export/Geo.h"
#include "pipeline/export/PackageLayout.h"
#include "pipeline/export/Placement.h"
#include "pipeline/export/TileContent.h"
#include "pipeline/io/GlbWriter.h"
#include "pipeline/proxy/BakeStats.h"
#include "pipeline/proxy/ProxyBaker.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

struct PackageOptions {
    std::optional<GeoLocation> geo;  // root transform on the globe; local frame otherwise
    std::vector<std::string> inputs; // source scene paths as given
    nlohmann::json parameters;       // the parameters that produced the tree and proxies
    nlohmann::json statistics;       // thesis-style tables, if the caller has them
    GlbCompression compression = GlbCompression::Meshopt;
};

struct PackageSummary {
    std::size_t tiles = 0;
    std::size_t files = 0;          // files in the package
    std::uintmax_t bytes = 0;       // their sizes
    std::uintmax_t bytesOnDisk = 0; // their allocated blocks (st_blocks x 512)
    std::size_t written = 0;        // files this export wrote
    std::size_t reused = 0;         // files taken unchanged from the package it replaced
};

PackageSummary writePackage(const std::filesystem::path& dir, const Scene& scene,
                            const ClusterTree& tree, const BakeResult& bake,
                            const BakeParams& bakeParams, const PackageOptions& options,
                            const Progress& progress = {});

// A content encoded elsewhere (a shard of a distributed bake, BakePlan.h): its URI
// ("tiles/HASH.glb"), what the encoder reported (bytes empty) and the file holding the bytes.
struct GivenContent {
    std::string uri;
    EncodedContent encoded;
    std::filesystem::path file;
};

// What a distributed bake's final step writes a package from without the scene's meshes: the
// layout with its blocks (planPackage with LayoutBlocks), the block contents already encoded,
// the sizes the manifest reports, and the placement (packagePlacement of the whole scene).
// The files of given contents are hard-linked (copied across file systems) into the package.
struct PackageParts {
    const PackageLayout& layout;
    std::function<const GivenContent&(const ContentSource&)> given;
    const SizeTable& sizes;
    Placement placement;
};
PackageSummary writePackage(const std::filesystem::path& dir, const Scene& scene,
                            const ClusterTree& tree, const BakeResult& bake,
                            const BakeParams& bakeParams, const PackageOptions& options,
                            const PackageParts& parts, const Progress& progress = {});

// The package writePackage would write, assembled in memory and measured without writing:
// files, bytes, and bytes on disk on a file system of `blockSize`-byte blocks (every file
// takes whole blocks; st_blocks of what writePackage writes on such a file system).
PackageSummary measurePackage(const Scene& scene, const ClusterTree& tree, const BakeResult& bake,
                              const BakeParams& bakeParams, const PackageOptions& options,
                              std::uintmax_t blockSize, const Progress& progress = {});

// tileset.json of a layout whose contents are the files `contentUris` (exposed for tests).
nlohmann::json buildTileset(const PackageLayout& layout,
                            const std::vector<std::string>& contentUris,
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
// a content path is unsafe (absolute, "..") or a content file is missing. Reads packages of
// format 1 (one GLB per node) and 2 (this layout).
PackageInfo readPackage(const std::filesystem::path& dir);

// The original scene back from a package: every leaf's geometry (decoded, placed by its tile's
// frame), under nodes named as in the source.
Scene readPackageScene(const PackageInfo& info);

} // namespace hlod
