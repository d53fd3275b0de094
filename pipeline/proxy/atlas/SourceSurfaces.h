// The original surfaces a proxy stands for, as the atlas bake samples them: every triangle of
// the original mesh instances under a cluster node, placed in the node's frame (metres,
// relative to the proxy's origin), with what its base colour is made of (glTF 2.0 base colour:
// factor x texture at the uv x vertex colour) and how its alpha is used.
//
// Ownership: textures are borrowed (the Scene's decoded images must outlive the bake).
// Vertex colours default to white, uvs to (0, 0) for meshes without them.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include <glm/glm.hpp>

#include "pipeline/scene/Scene.h"

namespace hlod {

struct SourceMaterial {
    glm::vec4 factor{1.0f};             // linear RGBA
    const RgbaImage* texture = nullptr; // null: untextured (or the mesh has no uvs)
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
};

struct SourceSurfaces {
    std::vector<glm::vec3> positions; // node frame
    std::vector<glm::vec2> uvs;       // one per position
    std::vector<glm::vec4> colors;    // linear vertex colours, one per position
    std::vector<std::uint32_t> indices;
    std::vector<std::uint32_t> triangleMaterial; // per triangle, into `materials`
    std::vector<SourceMaterial> materials;

    std::size_t triangleCount() const { return indices.size() / 3; }

    // Appends instance `instance` of `scene` with its vertices mapped by p -> linear * p +
    // offset (the node-frame placement the baker uses). Mirroring transforms flip the winding.
    void addInstance(const Scene& scene, Id instance, const glm::dmat3& linear,
                     const glm::dvec3& offset);

private:
    std::map<std::uint64_t, std::uint32_t> materialIds_; // (scene material, has uvs) -> index
    std::uint32_t materialIndex(const Scene& scene, Id material, bool hasUvs);
};

} // namespace hlod
