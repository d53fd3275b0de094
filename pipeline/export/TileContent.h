// The glTF content of one tile: a leaf's original mesh instance (baked into world space
// relative to its own centre, material base colour kept) or an inner node's proxy.
// Files are written only for non-empty meshes. Failure: Error(Io) naming the file.
#pragma once

#include <cstdint>
#include <filesystem>

#include "pipeline/proxy/ProxyMesh.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

struct TileStats {
    std::size_t triangles = 0;
    std::size_t vertices = 0;
    std::uintmax_t bytes = 0;
};

TileStats writeLeafContent(const std::filesystem::path& file, const Scene& scene, Id instance);
TileStats writeProxyContent(const std::filesystem::path& file, const ProxyMesh& proxy,
                            const std::string& name);

} // namespace hlod
