// The glTF content of one tile (PackageLayout.h says what goes where): a proxy (its baked atlas
// embedded as the base colour texture, MASK when it has a cut-out; vertex colours when it has
// none; double-sided and emissive as ProxyLook.h decides), or a leaf group: instanced meshes
// under nodes, the other leaves merged per look into one primitive in the group's frame, each
// keeping its material as authored: base colour factor and texture, alpha mode and cut-off,
// double-sidedness, emissive factor and texture. A look is all of those (not the name) plus
// the vertex streams the leaves carry: leaves of different looks never share a primitive.
// Vertex order: every mesh goes through meshoptimizer's vertex cache and vertex fetch
// optimisation (Forsyth-like cache order, then vertices in first-use order; unreferenced
// vertices dropped) before it is encoded, whatever the compression, so compressed and plain
// packages hold the same vertices in the same order.
// Textures: a leaf whose texture is stacked into a page (StackedAtlas.h: PNG textures, uvs
// within one period of v per triangle) references the page, its uvs moved into its band, so
// leaves of looks that differ only in their texture share a primitive: one draw per page.
// Any other leaf with uvs whose material has a readable texture file references it; the
// image is stored once per package under tiles/textures/, named by its content hash (PNG/JPEG
// as is, other formats re-encoded as PNG, TextureImage.h), and shared by every tile that uses
// it. Without uvs, or when the file is missing or undecodable, or the texture was embedded in
// the source (its bytes are not kept by the importers), the leaf uses the material's base
// colour times the texture's mean colour (a MASK material then blends with the mean coverage,
// or is opaque when the mean is); the emissive texture likewise (factor times its mean when
// it cannot be written).
// Textured proxies: makeContent reads the proxy's geometry through proxyGlbMesh, the one place
// that turns a ProxyMesh into a GlbMesh (uvs and an atlas image go there when proxies have
// them).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "pipeline/export/EncodedImageCache.h"
#include "pipeline/export/PackageLayout.h"
#include "pipeline/export/StackedAtlas.h"
#include "pipeline/io/GlbWriter.h"
#include "pipeline/proxy/ProxyMesh.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

// The package's texture files, loaded on first use and named by content, and the pages
// leaves' textures are stacked into (StackedAtlas.h), encoded as PNG on first use. With an
// image cache folder (EncodedImageCache.h), pages and converted source textures are read from
// it when an earlier export encoded the same pixels or source bytes: the same files either way.
class TextureStore {
public:
    explicit TextureStore(const Scene& scene, std::filesystem::path imageCache = {})
        : scene_(scene), atlases_(scene), cache_(std::move(imageCache)) {}
    const StackedAtlases& atlases() const { return atlases_; }
    // URI of a page of atlases() ("textures/<hash>.png").
    const std::string& pageUri(int page);
    // URI relative to tiles/ ("textures/<hash>.png") of the material's base colour texture;
    // empty when the material has no usable texture file.
    const std::string& uriFor(Id material);
    // The same for its emissive texture (empty when it emits nothing).
    const std::string& emissiveUriFor(Id material);
    // Every texture used so far: URI relative to tiles/ -> bytes.
    const std::map<std::string, std::vector<std::uint8_t>>& files() const { return files_; }
    // Images this store took from the image cache instead of encoding them.
    std::size_t cachedImages() const { return cache_.hits(); }

private:
    std::string uriForFile(const std::filesystem::path& file);
    // The file as glTF carries it (loadTextureForGltf), converted ones from the cache.
    std::optional<EncodedImage> loadCached(const std::filesystem::path& file);
    // encode()'s image, taken from the cache when it holds key() (hashed only with a cache).
    template <class Key, class Encode>
    std::optional<EncodedImage> throughCache(Key&& key, Encode&& encode);

    const Scene& scene_;
    StackedAtlases atlases_;
    EncodedImageCache cache_;
    std::map<int, std::string> byPage_;
    std::map<Id, std::string> byMaterial_, emissiveByMaterial_;
    std::map<std::filesystem::path, std::string> byFile_;
    std::map<std::string, std::vector<std::uint8_t>> files_;
};

// Where a leaf ended up inside its content.
struct LeafInContent {
    int node = -1;       // glTF node index (flat scene: the i-th root node)
    bool merged = false; // its geometry is a range of that node's primitive
    std::size_t firstVertex = 0, vertexCount = 0, firstIndex = 0, indexCount = 0;
};

struct EncodedContent {
    std::vector<std::uint8_t> bytes;   // the GLB
    std::vector<LeafInContent> leaves; // parallel to ContentPlan::leaves
    std::size_t triangles = 0, vertices = 0;
    // The most a decoded position is off on any axis, metres in the content's frame: half the
    // coarsest grid step times the node scale (0 without compression).
    double positionError = 0.0;
};

// A hash of everything a content's bytes depend on besides the scene's meshes and materials: a
// proxy's bake key (its mesh, ProxyBaker.h), offset and grid; a group's meshes, placements and
// grids. Plans with equal keys encode to equal bytes (copies are encoded once).
std::uint64_t contentKey(const ContentPlan& plan, const BakeResult& bake, const Scene& scene);

// Encodes contents; meshes prepared once are reused by every content showing them.
class ContentEncoder {
public:
    ContentEncoder(const Scene& scene, const BakeResult& bake, TextureStore& textures,
                   GlbCompression compression);
    ~ContentEncoder();
    EncodedContent encode(const ContentPlan& plan);

private:
    struct Prepared;
    const Prepared& prepared(Id mesh);
    EncodedContent encodeProxy(const ContentPlan& plan);
    EncodedContent encodeGroup(const ContentPlan& plan);

    const Scene& scene_;
    const BakeResult& bake_;
    TextureStore& textures_;
    GlbCompression compression_;
    std::map<Id, std::unique_ptr<Prepared>> prepared_;
};

// The GLB mesh of a proxy (spans into `proxy`, which must outlive it).
GlbMesh proxyGlbMesh(const ProxyMesh& proxy, const std::string& name);

} // namespace hlod
