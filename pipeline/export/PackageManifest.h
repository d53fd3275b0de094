// hlod.json of a package, format 2 (Package.h): what an engine importer needs besides the
// tileset. One JSON object:
//   format, formatVersion (2), generator, source.inputs, contentUpAxis ("Y"), screen (S, t,
//   fov, viewport, maximumScreenSpaceError), volume, k, proxyMethod, compression, parameters,
//   statistics, root (node id), placement (Placement.h, added by the package writer),
//   files:  the package's content files (relative paths),
//   tiles:  per tile {node (or null for a leaf group), parent tile (-1 at the root), file
//           (index into files, -1 = no content), frame: "translation" [x, y, z] or "matrix"
//           [16, column-major]: the content's frame in the package frame (Y up, metres),
//           positionError: the most a decoded position of its content is off per axis (m)},
//   meshes: per scene mesh {name, material, triangles, vertices},
//   nodes:  per tree node; inner: {parent, children, level, box {min, max}, sphere {center,
//           radius}, diameter, errorBudget, switchDistance, triangles, vertices, tile};
//           leaf: {parent, children [], instance, name, mesh, tile, contentNode (its glTF node
//           in the tile's file), and for a leaf merged with others contentRange [first vertex,
//           vertex count, first index, index count] of that node's primitive}.
// Numbers other than frames are rounded to 7 significant digits (JsonNumbers.h): the manifest
// of a scene with 10,000 leaves stays about a megabyte.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipeline/export/Package.h"
#include "pipeline/export/TileContent.h"
#include "pipeline/proxy/BakeStats.h"

namespace hlod {

struct ManifestInput {
    const Scene& scene;
    const ClusterTree& tree;
    const BakeResult& bake;
    const BakeParams& bakeParams;
    const PackageOptions& options;
    const PackageLayout& layout;
    const std::vector<std::string>& contentUris; // per layout content
    const std::vector<EncodedContent>& encoded;  // per layout content (bytes not needed)
    // When set, mesh and proxy sizes come from here instead of the geometry (a distributed
    // bake's final step holds the sizes, not the meshes: BakePlan.h).
    const SizeTable* sizes = nullptr;
};

nlohmann::json buildManifest(const ManifestInput& in);

} // namespace hlod
