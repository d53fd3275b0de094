// The glTF content of one tile: a leaf's original mesh instance (baked into world space
// relative to its own centre, material base colour and base colour texture kept) or an inner
// node's proxy (its baked atlas embedded as the base colour texture, MASK when it has a
// cut-out; vertex colours when it has none).
// Textures: a leaf with uvs whose material has a readable texture file references it; the
// image is written once per package under tiles/textures/ (PNG/JPEG as is, other formats
// re-encoded as PNG, TextureImage.h) and shared by every tile that uses it. Without uvs, or
// when the file is missing or undecodable, or the texture was embedded in the source (its
// bytes are not kept by the importers), the leaf uses the material's base colour times the
// texture's mean colour.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

#include "pipeline/proxy/ProxyMesh.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

struct TileStats {
    std::size_t triangles = 0;
    std::size_t vertices = 0;
    std::uintmax_t bytes = 0;
};

// The package's shared texture files, written on first use into `tilesDir`/textures/ and
// named by order of first use (deterministic for a deterministic export order).
class TextureCache {
public:
    TextureCache(const Scene& scene, std::filesystem::path tilesDir)
        : scene_(scene), tilesDir_(std::move(tilesDir)) {}
    // URI relative to tilesDir; empty when the material has no usable texture file.
    // Failure to write: Error(Io) naming the file.
    const std::string& uriFor(Id material);
    std::uintmax_t bytesWritten() const { return bytes_; }
    std::size_t filesWritten() const { return files_; }

private:
    const Scene& scene_;
    std::filesystem::path tilesDir_;
    std::map<Id, std::string> byMaterial_;
    std::map<std::filesystem::path, std::string> byFile_;
    std::uintmax_t bytes_ = 0;
    std::size_t files_ = 0;
};

TileStats writeLeafContent(const std::filesystem::path& file, const Scene& scene, Id instance,
                           TextureCache& textures);
TileStats writeProxyContent(const std::filesystem::path& file, const ProxyMesh& proxy,
                            const std::string& name);

} // namespace hlod
