// Tile content encoding on top of the GLB writer. Leaves are pre-transformed (the instance's
// world matrix applied in double precision, positions stored relative to the mesh's world
// centre, carried by the glTF node translation) so that every tile shares the package frame.
#include "pipeline/export/TileContent.h"

#include <fstream>

#include <glm/gtc/matrix_inverse.hpp>

#include "pipeline/core/AtomicFile.h"
#include "pipeline/core/Error.h"
#include "pipeline/io/TextureImage.h"

#include "pipeline/io/GlbWriter.h"

namespace hlod {

namespace {

TileStats stats(const std::filesystem::path& file, std::size_t tris, std::size_t verts) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(file, ec);
    return {tris, verts, ec ? 0 : size};
}

} // namespace

const std::string& TextureCache::uriFor(Id material) {
    if (auto it = byMaterial_.find(material); it != byMaterial_.end()) return it->second;
    std::string& uri = byMaterial_[material];
    const Material& m = scene_.materials[material];
    if (!m.hasTexture || m.baseColorTexture.empty()) return uri;
    if (auto it = byFile_.find(m.baseColorTexture); it != byFile_.end()) {
        uri = it->second;
        return uri;
    }
    std::string& shared = byFile_[m.baseColorTexture];
    const std::optional<EncodedImage> image = loadTextureForGltf(m.baseColorTexture);
    if (!image) return uri; // mean colour fallback, see the header
    const std::string name = "textures/" + std::to_string(byFile_.size() - 1) +
                             (image->mimeType == "image/jpeg" ? ".jpg" : ".png");
    const std::filesystem::path file = tilesDir_ / name;
    std::filesystem::create_directories(file.parent_path());
    writeFileAtomic(file, std::string_view(reinterpret_cast<const char*>(image->bytes.data()),
                                           image->bytes.size()));
    bytes_ += image->bytes.size();
    ++files_;
    shared = name;
    uri = name;
    return uri;
}

TileStats writeLeafContent(const std::filesystem::path& file, const Scene& scene, Id instance,
                           TextureCache& textures) {
    const MeshInstance& inst = scene.instances[instance];
    const Mesh& mesh = scene.meshes[inst.mesh];
    if (mesh.indices.empty()) return {};
    const glm::dmat4& world = scene.nodes[inst.node].world;
    const glm::dmat3 normalMatrix = glm::inverseTranspose(glm::dmat3(world));
    Aabb box;
    std::vector<glm::dvec3> worldPos(mesh.positions.size());
    for (std::size_t i = 0; i < worldPos.size(); ++i) {
        worldPos[i] = glm::dvec3(world * glm::dvec4(glm::dvec3(mesh.positions[i]), 1.0));
        box.expand(worldPos[i]);
    }
    const glm::dvec3 origin = box.center();
    std::vector<glm::vec3> positions(worldPos.size()), normals(mesh.normals.size());
    for (std::size_t i = 0; i < worldPos.size(); ++i)
        positions[i] = glm::vec3(worldPos[i] - origin);
    for (std::size_t i = 0; i < normals.size(); ++i) {
        const glm::dvec3 n = normalMatrix * glm::dvec3(mesh.normals[i]);
        const double len = glm::length(n);
        normals[i] = len > 0.0 ? glm::vec3(n / len) : glm::vec3(0, 1, 0);
    }
    std::vector<std::uint32_t> indices = mesh.indices;
    if (glm::determinant(glm::dmat3(world)) < 0.0) { // a mirroring transform flips the winding
        for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
            std::swap(indices[t + 1], indices[t + 2]);
    }
    std::vector<glm::u8vec4> colors;
    for (const glm::vec4& c : mesh.colors)
        colors.push_back(quantizeColor(c));
    const Material& mat = scene.materials[mesh.material];
    GlbMesh glb;
    glb.name = scene.nodes[inst.node].name;
    glb.translation = origin;
    glb.positions = positions;
    glb.normals = normals;
    glb.colors = colors;
    glb.indices = indices;
    const std::string noTexture;
    const std::string& uri = mesh.uvs.empty() ? noTexture : textures.uriFor(mesh.material);
    if (!uri.empty()) {
        glb.uvs = mesh.uvs;
        glb.imageUri = uri;
        glb.baseColor = mat.baseColor;
    } else {
        glb.baseColor = mat.effectiveColor();
    }
    writeGlbFile(file, glb);
    return stats(file, mesh.triangleCount(), mesh.vertexCount());
}

TileStats writeProxyContent(const std::filesystem::path& file, const ProxyMesh& proxy,
                            const std::string& name) {
    if (proxy.empty()) return {};
    GlbMesh glb;
    glb.name = name;
    glb.translation = proxy.origin;
    glb.positions = proxy.positions;
    glb.normals = proxy.normals;
    glb.indices = proxy.indices;
    if (proxy.hasAtlas()) { // the atlas carries the whole base colour (ProxyMesh.h)
        glb.uvs = proxy.uvs;
        glb.image = proxy.atlas->encoded;
        glb.imageMimeType = proxy.atlas->mimeType;
        glb.alphaMask = proxy.atlas->mask;
    } else {
        glb.colors = proxy.colors;
    }
    writeGlbFile(file, glb);
    return stats(file, proxy.triangleCount(), proxy.vertexCount());
}

} // namespace hlod
