// Tile contents on top of the GLB writer (see TileContent.h).
#include "pipeline/export/TileContent.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include <meshoptimizer.h>

#include "pipeline/io/GlbMeshopt.h"
#include "pipeline/io/TextureImage.h"
#include "pipeline/proxy/ContentHash.h"
#include "pipeline/scene/AppendPlaced.h"

namespace hlod {

namespace {

// Half the grid step the writer uses for `positions` asked at `requested` (GlbMeshopt.h).
double halfStep(std::span<const glm::vec3> positions, double requested) {
    Aabb box;
    for (const glm::vec3& p : positions)
        box.expand(glm::dvec3(p));
    const glm::dvec3 e = box.extent();
    return 0.5 * positionGridStep(std::max({e.x, e.y, e.z}), requested);
}

double maxAbs(const glm::dvec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// Vertex cache then vertex fetch order (meshoptimizer); `streams` are remapped alike.
// Returns the remap (old vertex -> new, ~0u for dropped vertices) applied to the indices.
template <class... Streams>
void optimizeOrder(std::vector<std::uint32_t>& indices, std::size_t vertexCount,
                   Streams&... streams) {
    if (indices.empty()) return;
    meshopt_optimizeVertexCache(indices.data(), indices.data(), indices.size(), vertexCount);
    std::vector<unsigned> remap(vertexCount);
    const std::size_t kept =
        meshopt_optimizeVertexFetchRemap(remap.data(), indices.data(), indices.size(), vertexCount);
    meshopt_remapIndexBuffer(indices.data(), indices.data(), indices.size(), remap.data());
    auto apply = [&](auto& v) {
        if (v.empty()) return;
        auto out = v;
        meshopt_remapVertexBuffer(out.data(), v.data(), vertexCount, sizeof(v[0]), remap.data());
        out.resize(kept);
        v = std::move(out);
    };
    (apply(streams), ...);
}

} // namespace

const std::string& TextureStore::uriFor(Id material) {
    if (auto it = byMaterial_.find(material); it != byMaterial_.end()) return it->second;
    std::string& uri = byMaterial_[material];
    const Material& m = scene_.materials[material];
    if (m.hasTexture) uri = uriForFile(m.baseColorTexture);
    return uri;
}

const std::string& TextureStore::emissiveUriFor(Id material) {
    if (auto it = emissiveByMaterial_.find(material); it != emissiveByMaterial_.end())
        return it->second;
    std::string& uri = emissiveByMaterial_[material];
    const Material& m = scene_.materials[material];
    if (m.emits()) uri = uriForFile(m.emissiveTextureFile);
    return uri;
}

template <class Key, class Encode>
std::optional<EncodedImage> TextureStore::throughCache(Key&& key, Encode&& encode) {
    if (!cache_.enabled()) return encode();
    const std::uint64_t k = key();
    if (std::optional<EncodedImage> cached = cache_.load(k)) return cached;
    std::optional<EncodedImage> image = encode();
    if (image) cache_.store(k, *image);
    return image;
}

const std::string& TextureStore::pageUri(int page) {
    if (auto it = byPage_.find(page); it != byPage_.end()) return it->second;
    const RgbaImage& pixels = atlases_.pages()[static_cast<std::size_t>(page)];
    const auto key = [&] {
        ContentHash h = imageCacheKey("page png");
        h.addValue(pixels.width);
        h.addValue(pixels.height);
        h.addVector(pixels.pixels);
        return h.digest();
    };
    EncodedImage image =
        *throughCache(key, [&] { return std::optional<EncodedImage>(encodePng(pixels)); });
    std::string& uri = byPage_[page];
    uri = "textures/" + toHex(hashBytes(image.bytes.data(), image.bytes.size())) + ".png";
    files_[uri] = std::move(image.bytes);
    return uri;
}

std::optional<EncodedImage> TextureStore::loadCached(const std::filesystem::path& file) {
    const std::optional<std::vector<std::uint8_t>> bytes = readImageFile(file);
    if (!bytes) return std::nullopt;
    // PNG and JPEG pass through (TextureImage.h): cheap; other formats are converted.
    if (passesThroughForGltf(*bytes)) return encodeForGltf(*bytes);
    const auto key = [&] {
        ContentHash h = imageCacheKey("source texture");
        h.addVector(*bytes);
        return h.digest();
    };
    return throughCache(key, [&] { return encodeForGltf(*bytes); });
}

std::string TextureStore::uriForFile(const std::filesystem::path& file) {
    if (file.empty()) return {};
    if (auto it = byFile_.find(file); it != byFile_.end()) return it->second;
    std::string& shared = byFile_[file];
    std::optional<EncodedImage> image = loadCached(file);
    if (!image) return shared; // mean colour fallback, see the header
    shared = "textures/" + toHex(hashBytes(image->bytes.data(), image->bytes.size())) +
             (image->mimeType == "image/jpeg" ? ".jpg" : ".png");
    files_[shared] = std::move(image->bytes);
    return shared;
}

// A scene mesh as leaves store it: optimised order, 8-bit colours, uvs only when textured,
// its material as written (`look`: no geometry spans yet).
struct ContentEncoder::Prepared {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<glm::u8vec4> colors;
    std::vector<std::uint32_t> indices;
    GlbMesh look;
};

namespace {

// A leaf's material as its tile writes it (TileContent.h): as authored where its textures are
// written; where a texture cannot be (no uvs, an embedded or unreadable file) its mean stands
// in, and a cut-out without its texture blends with the mean coverage instead.
void writtenLook(const Material& mat, const std::string& uri, const std::string& emissiveUri,
                 GlbMesh& g) {
    g.materialName = mat.name;
    g.baseColor = uri.empty() ? mat.effectiveColor() : mat.baseColor;
    g.imageUri = uri;
    g.alphaMode = mat.alphaMode;
    g.alphaCutoff = mat.alphaCutoff;
    if (uri.empty() && mat.alphaMode == AlphaMode::Mask)
        g.alphaMode = g.baseColor.a < 1.0f ? AlphaMode::Blend : AlphaMode::Opaque;
    if (g.alphaMode != AlphaMode::Mask) g.alphaCutoff = 0.5f;
    g.doubleSided = mat.doubleSided;
    if (!mat.emits()) return;
    const bool sameImage = !uri.empty() && mat.emissiveTextureFile == mat.baseColorTexture;
    g.emissiveUri = sameImage ? uri : emissiveUri;
    // Without a written texture its mean stands in (the mean is 1 without a texture).
    g.emissive = g.emissiveUri.empty() ? mat.effectiveEmissive() : mat.emissive;
}

} // namespace

ContentEncoder::ContentEncoder(const Scene& scene, const BakeResult& bake, TextureStore& textures,
                               GlbCompression compression)
    : scene_(scene), bake_(bake), textures_(textures), compression_(compression) {}

ContentEncoder::~ContentEncoder() = default;

const ContentEncoder::Prepared& ContentEncoder::prepared(Id meshId) {
    std::unique_ptr<Prepared>& slot = prepared_[meshId];
    if (slot) return *slot;
    slot = std::make_unique<Prepared>();
    Prepared& p = *slot;
    const Id material = scene_.meshes[meshId].material;
    const Material& mat = scene_.materials[material];
    // A leaf whose texture is in a page reads it there (StackedAtlas.h).
    const StackedAtlases& atlases = textures_.atlases();
    const AtlasBand* band = atlases.stacks(meshId) ? atlases.band(material) : nullptr;
    std::optional<Mesh> stacked;
    if (band) {
        const int rows = atlases.pages()[static_cast<std::size_t>(band->page)].height;
        if (std::optional<StackedUvs> s = stackUvs(scene_.meshes[meshId], *band, rows))
            stacked = stackedMesh(scene_.meshes[meshId], *s);
    }
    const Mesh& mesh = stacked ? *stacked : scene_.meshes[meshId];
    p.positions = mesh.positions;
    p.normals = mesh.normals;
    p.indices = mesh.indices;
    for (const glm::vec4& c : mesh.colors)
        p.colors.push_back(quantizeColor(c));
    const std::string uri = stacked            ? textures_.pageUri(band->page)
                            : mesh.uvs.empty() ? std::string()
                                               : textures_.uriFor(mesh.material);
    // A stacked texture's emission is the texture itself (StackedAtlas.h), read from the page.
    const std::string emissiveUri =
        stacked || mesh.uvs.empty() ? std::string() : textures_.emissiveUriFor(mesh.material);
    if (!uri.empty() || !emissiveUri.empty()) p.uvs = mesh.uvs;
    optimizeOrder(p.indices, p.positions.size(), p.positions, p.normals, p.uvs, p.colors);
    writtenLook(mat, uri, emissiveUri, p.look);
    p.look.name = mesh.name;
    return p;
}

std::uint64_t contentKey(const ContentPlan& plan, const BakeResult& bake, const Scene& scene) {
    ContentHash h(plan.proxy ? 1 : 2);
    if (plan.proxy) {
        const ProxyMesh& proxy = bake.nodes[plan.node].proxy;
        h.addValue(bake.nodes[plan.node].key);
        h.addValue(proxy.vertexCount());
        h.addValue(proxy.triangleCount());
        h.addValue(plan.proxyOffset);
        h.addValue(plan.proxyRotation);
        h.addValue(plan.positionStep);
        return h.digest();
    }
    for (const LeafSlot& s : plan.leaves) {
        h.addValue(scene.instances[s.instance].mesh);
        h.addValue(s.merged);
        h.addValue(s.positionStep);
        if (s.merged) {
            h.addValue(s.matrix);
        } else {
            h.addValue(s.trs.translation);
            h.addValue(s.trs.rotation);
            h.addValue(s.trs.scale);
        }
    }
    return h.digest();
}

GlbMesh proxyGlbMesh(const ProxyMesh& proxy, const std::string& name) {
    GlbMesh m;
    m.name = name;
    m.positions = proxy.positions;
    m.normals = proxy.normals;
    m.indices = proxy.indices;
    m.doubleSided = proxy.doubleSided;
    m.emissive = proxy.emissive;
    if (proxy.hasAtlas()) { // the atlas carries the whole base colour (ProxyMesh.h)
        m.uvs = proxy.uvs;
        m.image = proxy.atlas->encoded;
        m.imageMimeType = proxy.atlas->mimeType;
        m.alphaMode = proxy.atlas->mask ? AlphaMode::Mask : AlphaMode::Opaque;
        m.emissiveUsesImage = true; // the factor is relative to the atlas (ProxyLook.h)
    } else {
        m.colors = proxy.colors;
    }
    return m;
}

EncodedContent ContentEncoder::encode(const ContentPlan& plan) {
    return plan.proxy ? encodeProxy(plan) : encodeGroup(plan);
}

EncodedContent ContentEncoder::encodeProxy(const ContentPlan& plan) {
    ProxyMesh proxy = bake_.nodes[plan.node].proxy;
    // Every per-vertex stream of the proxy goes through the same reordering.
    optimizeOrder(proxy.indices, proxy.positions.size(), proxy.positions, proxy.normals,
                  proxy.colors, proxy.uvs);
    GlbScene glb;
    glb.compression = compression_;
    glb.meshes.push_back(proxyGlbMesh(proxy, "proxy"));
    glb.meshes.back().positionStep = plan.positionStep;
    GlbNode node;
    node.mesh = 0;
    node.trs.translation = plan.proxyOffset;
    node.trs.rotation = glm::quat_cast(plan.proxyRotation);
    glb.nodes.push_back(node);
    EncodedContent out;
    out.bytes = encodeGlb(glb);
    out.triangles = proxy.triangleCount();
    out.vertices = proxy.vertexCount();
    if (compression_ == GlbCompression::Meshopt)
        out.positionError = halfStep(proxy.positions, plan.positionStep);
    return out;
}

namespace {

// Leaves merged into one primitive: the same look (material as written) and colour streams.
struct Merged {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<glm::u8vec4> colors;
    std::vector<std::uint32_t> indices;
    double step = 0.0;
    GlbMesh look;                     // material, texture, colour of the first member
    std::vector<std::size_t> members; // slot indices
};

// Appends a prepared mesh placed by `matrix` (AppendPlaced.h) and records where it went.
void append(Merged& m, const auto& p, const glm::dmat4& matrix, LeafInContent& where) {
    where.merged = true;
    where.firstIndex = m.indices.size();
    where.indexCount = p.indices.size();
    where.firstVertex = appendPlaced(m, p, matrix);
    where.vertexCount = p.positions.size();
}

// What may share a merged primitive (TileContent.h): everything the written material holds
// but its name, and which vertex streams the leaves carry.
using LookKey = std::tuple<std::array<float, 4>, std::string, int, float, bool,
                           std::array<float, 3>, std::string, bool, bool>;

LookKey lookKeyOf(const GlbMesh& g, bool colors, bool uvs) {
    const glm::vec4& c = g.baseColor;
    const glm::vec3& e = g.emissive;
    return {{c.r, c.g, c.b, c.a}, g.imageUri,    static_cast<int>(g.alphaMode),
            g.alphaCutoff,        g.doubleSided, {e.r, e.g, e.b},
            g.emissiveUri,        colors,        uvs};
}

} // namespace

EncodedContent ContentEncoder::encodeGroup(const ContentPlan& plan) {
    EncodedContent out;
    out.leaves.resize(plan.leaves.size());
    GlbScene glb;
    glb.compression = compression_;
    std::map<Id, int> meshIndex; // instanced scene mesh -> GLB mesh
    // Merged primitives by look (importers often give every object its own material of the
    // same look).
    std::map<LookKey, Merged> merged;
    for (std::size_t i = 0; i < plan.leaves.size(); ++i) {
        const LeafSlot& s = plan.leaves[i];
        const Id meshId = scene_.instances[s.instance].mesh;
        const Prepared& p = prepared(meshId);
        out.triangles += p.indices.size() / 3;
        out.vertices += p.positions.size();
        if (s.merged) {
            Merged& m = merged[lookKeyOf(p.look, !p.colors.empty(), !p.uvs.empty())];
            if (m.members.empty()) m.look = p.look;
            m.step = m.step > 0.0 ? std::min(m.step, s.positionStep) : s.positionStep;
            m.members.push_back(i);
            append(m, p, s.matrix, out.leaves[i]);
            continue;
        }
        auto [it, added] = meshIndex.try_emplace(meshId, static_cast<int>(glb.meshes.size()));
        if (added) {
            GlbMesh g = p.look;
            g.positions = p.positions;
            g.normals = p.normals;
            g.uvs = p.uvs;
            g.colors = p.colors;
            g.indices = p.indices;
            g.positionStep = s.positionStep;
            glb.meshes.push_back(g);
        }
        if (compression_ == GlbCompression::Meshopt)
            out.positionError = std::max(out.positionError, halfStep(p.positions, s.positionStep) *
                                                                maxAbs(s.trs.scale));
        GlbNode node;
        node.mesh = it->second;
        node.trs = s.trs;
        out.leaves[i].node = static_cast<int>(glb.nodes.size());
        glb.nodes.push_back(node);
    }
    for (auto& [key, m] : merged) {
        GlbMesh g = m.look;
        g.name = "merged";
        g.positions = m.positions;
        g.normals = m.normals;
        g.uvs = m.uvs;
        g.colors = m.colors;
        g.indices = m.indices;
        g.positionStep = m.step;
        if (compression_ == GlbCompression::Meshopt)
            out.positionError = std::max(out.positionError, halfStep(m.positions, m.step));
        GlbNode node;
        node.mesh = static_cast<int>(glb.meshes.size());
        for (std::size_t i : m.members)
            out.leaves[i].node = static_cast<int>(glb.nodes.size());
        glb.meshes.push_back(g);
        glb.nodes.push_back(node);
    }
    out.bytes = encodeGlb(glb);
    return out;
}

} // namespace hlod
