// The scene model every importer produces and every later stage consumes.
//
// Units: metres. Axes are kept as the source defines them (glTF and AC3D are Y up, CAD is
// usually Z up); nothing is rotated on import.
// Ownership: a Scene owns all its data by value; ids are indices into its vectors.
// Instancing: a Mesh is geometry in its own local frame; a MeshInstance places one mesh under
// one node (world transform = that node's world). A mesh may be instanced by several nodes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "pipeline/scene/Aabb.h"
#include "pipeline/scene/RgbaImage.h"

namespace hlod {

using Id = std::uint32_t;
inline constexpr Id kNoId = 0xffffffffu;

// A base colour texture as imported: decoded once, shared by every material that names it.
// `image` is null when the file could not be read or decoded; `error` then says why, naming
// the file ("tr-road1.rgb: RLE row 7 runs past its end"), and materials using it fall back to
// their base colour (their texture mean stays white).
struct Texture {
    std::string name;                       // file name, or "image N" when embedded
    std::filesystem::path file;             // absolute path; empty when embedded in the source
    std::shared_ptr<const RgbaImage> image; // immutable, shared by copies of the scene
    std::string error;                      // why `image` is null; empty otherwise
};

// How a material's alpha is used (glTF 2.0 alphaMode): ignored, cut out at `alphaCutoff`
// (texels below it are not drawn, the rest opaque), or blended.
enum class AlphaMode : std::uint8_t { Opaque, Mask, Blend };

// A material as authored (glTF 2.0 metallic-roughness subset, section 3.9): what every later
// stage keeps (leaf tiles, proxies, the package, the viewport, `hlod bench`). Two materials
// that agree on all of these draw alike (sameLook); names do not matter.
struct Material {
    std::string name;
    glm::vec4 baseColor{1.0f};              // linear RGBA factor
    std::filesystem::path baseColorTexture; // absolute path, empty when none or embedded
    bool hasTexture = false;                // a base colour texture exists (file or embedded)
    glm::vec4 textureMean{1.0f};            // mean RGBA of that texture (decoded on import)
    Id texture = kNoId;                     // index into Scene::textures, kNoId when none
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f; // AlphaMode::Mask only
    // Drawn from both sides (glTF doubleSided); otherwise back faces are culled.
    bool doubleSided = false;
    // Emitted light added after lighting: linear RGB factor (may exceed 1, as glTF's
    // KHR_materials_emissive_strength allows) times the emissive texture when there is one
    // (sampled with the same uvs as the base colour texture; AC3D's `emis` uses the base
    // colour texture itself, as OpenGL's modulate mode does in TORCS).
    glm::vec3 emissive{0.0f};
    std::filesystem::path emissiveTextureFile; // absolute path, empty when none or embedded
    Id emissiveTexture = kNoId;                // index into Scene::textures, kNoId when none
    glm::vec3 emissiveMean{1.0f};              // mean linear RGB of that texture

    // The colour a proxy uses for this material: base colour times the texture's mean.
    glm::vec4 effectiveColor() const { return baseColor * textureMean; }
    // The emitted colour where the emissive texture cannot be drawn: factor times its mean.
    glm::vec3 effectiveEmissive() const { return emissive * emissiveMean; }
    bool emits() const { return emissive != glm::vec3(0.0f); }
};

// True when `a` and `b` draw alike: same base colour factor and texture, alpha mode and
// cut-off, sidedness and emissive factor and texture (the name is not compared).
bool sameLook(const Material& a, const Material& b);

// Triangle mesh, 32-bit indices, one material. Normals are always present (computed on import
// when the source has none); uvs (v = 0 at the image top, as glTF), colors: none or one each.
struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<glm::vec4> colors;
    std::vector<std::uint32_t> indices; // 3 per triangle
    Id material = 0;

    std::size_t triangleCount() const { return indices.size() / 3; }
    std::size_t vertexCount() const { return positions.size(); }
    Aabb localBounds() const;
};

struct Node {
    std::string name;
    Id parent = kNoId;
    std::vector<Id> children;
    glm::dmat4 local{1.0};
    glm::dmat4 world{1.0}; // kept in sync by Scene::updateWorldTransforms()
};

struct MeshInstance {
    Id mesh = 0;
    Id node = 0;
};

struct SceneStats {
    std::size_t nodes = 0;
    std::size_t meshes = 0;    // unique geometry
    std::size_t instances = 0; // placed meshes
    std::size_t drawCalls = 0; // one per instance (one material per mesh)
    std::size_t triangles = 0; // instanced: what a renderer draws
    std::size_t vertices = 0;  // instanced
    std::size_t uniqueTriangles = 0;
    std::size_t uniqueVertices = 0;
    std::size_t materials = 0;
    std::size_t depth = 0; // longest root-to-node path, root = 1
};

class Scene {
public:
    std::vector<Node> nodes; // nodes[0] is the root
    std::vector<Mesh> meshes;
    std::vector<Material> materials; // materials[0] always exists (default grey)
    std::vector<Texture> textures;   // referenced by Material::texture
    std::vector<MeshInstance> instances;
    std::vector<std::filesystem::path> sourceFiles;
    // Files the source files pulled in (glTF buffers and images, material libraries...),
    // absolute, as the importers read them: with sourceFiles, what the scene costs on disk.
    std::vector<std::filesystem::path> referencedFiles;
    // What an importer changed on the way in, one line each naming the file (e.g. a CAD face
    // coarsened by the tessellation budget); shown by `hlod info`.
    std::vector<std::string> importNotes;

    Scene();

    // Adds a node under `parent` and returns its id.
    Id addNode(std::string name, Id parent, const glm::dmat4& local = glm::dmat4(1.0));
    Id addMesh(Mesh mesh);
    Id addMaterial(Material material);
    Id addTexture(Texture texture);
    // The decoded base colour texture of `material`, null when it has none or it is unreadable.
    const RgbaImage* textureImage(Id material) const;
    Id addInstance(Id mesh, Id node);

    // Recomputes Node::world from Node::local, root first.
    void updateWorldTransforms();

    // Merges `other` under a new child node of this scene's root named `name`.
    void append(Scene&& other, const std::string& name);

    const glm::dmat4& instanceTransform(Id instance) const {
        return nodes[instances[instance].node].world;
    }
    Aabb instanceBounds(Id instance) const;
    Aabb worldBounds() const;
    SceneStats stats() const;
};

// Fills normals from faces (area-weighted) for a mesh that has none.
void computeNormals(Mesh& mesh);

} // namespace hlod
