// See SourceSurfaces.h.
#include "pipeline/proxy/atlas/SourceSurfaces.h"

namespace hlod {

std::uint32_t SourceSurfaces::materialIndex(const Scene& scene, Id material, bool hasUvs) {
    if (material >= scene.materials.size()) material = 0;
    // A textured material drawn without uvs samples nothing: keyed apart.
    const std::uint64_t key = (std::uint64_t(material) << 1) | (hasUvs ? 1u : 0u);
    if (auto it = materialIds_.find(key); it != materialIds_.end()) return it->second;
    const Material& m = scene.materials[material];
    SourceMaterial out;
    out.texture = hasUvs ? scene.textureImage(material) : nullptr;
    // Without its texture, the material's colour is what vertex colours use (factor x mean).
    out.factor = out.texture ? m.baseColor : m.effectiveColor();
    out.alphaMode = m.alphaMode;
    out.alphaCutoff = m.alphaCutoff;
    materials.push_back(out);
    const auto index = static_cast<std::uint32_t>(materials.size() - 1);
    materialIds_.emplace(key, index);
    return index;
}

void SourceSurfaces::addInstance(const Scene& scene, Id instance, const glm::dmat3& linear,
                                 const glm::dvec3& offset) {
    const Mesh& mesh = scene.meshes[scene.instances[instance].mesh];
    const bool hasUvs = mesh.uvs.size() == mesh.positions.size();
    const bool hasColors = mesh.colors.size() == mesh.positions.size();
    const std::uint32_t material = materialIndex(scene, mesh.material, hasUvs);
    const auto base = static_cast<std::uint32_t>(positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        positions.push_back(glm::vec3(linear * glm::dvec3(mesh.positions[i]) + offset));
        uvs.push_back(hasUvs ? mesh.uvs[i] : glm::vec2(0.0f));
        colors.push_back(hasColors ? mesh.colors[i] : glm::vec4(1.0f));
    }
    const bool flip = glm::determinant(linear) < 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        indices.push_back(base + mesh.indices[t]);
        indices.push_back(base + mesh.indices[flip ? t + 2 : t + 1]);
        indices.push_back(base + mesh.indices[flip ? t + 1 : t + 2]);
        triangleMaterial.push_back(material);
    }
}

} // namespace hlod
