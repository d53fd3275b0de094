#include "pipeline/scene/Scene.h"

#include <functional>

namespace hlod {

Aabb Aabb::transformed(const glm::dmat4& m) const {
    Aabb out;
    if (empty()) return out;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 c((i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y,
                           (i & 4) ? max.z : min.z);
        out.expand(glm::dvec3(m * glm::dvec4(c, 1.0)));
    }
    return out;
}

bool sameLook(const Material& a, const Material& b) {
    const bool mask = a.alphaMode == AlphaMode::Mask;
    return a.baseColor == b.baseColor && a.texture == b.texture &&
           a.baseColorTexture == b.baseColorTexture && a.textureMean == b.textureMean &&
           a.alphaMode == b.alphaMode && (!mask || a.alphaCutoff == b.alphaCutoff) &&
           a.doubleSided == b.doubleSided && a.emissive == b.emissive &&
           a.emissiveTexture == b.emissiveTexture &&
           a.emissiveTextureFile == b.emissiveTextureFile && a.emissiveMean == b.emissiveMean;
}

Aabb Mesh::localBounds() const {
    Aabb b;
    for (const glm::vec3& p : positions)
        b.expand(glm::dvec3(p));
    return b;
}

Scene::Scene() {
    nodes.push_back(Node{"root", kNoId, {}, glm::dmat4(1.0), glm::dmat4(1.0)});
    materials.push_back(Material{"default", glm::vec4(0.8f, 0.8f, 0.8f, 1.0f), {}});
}

Id Scene::addNode(std::string name, Id parent, const glm::dmat4& local) {
    const Id id = static_cast<Id>(nodes.size());
    Node n;
    n.name = std::move(name);
    n.parent = parent;
    n.local = local;
    n.world = parent == kNoId ? local : nodes[parent].world * local;
    nodes.push_back(std::move(n));
    if (parent != kNoId) nodes[parent].children.push_back(id);
    return id;
}

Id Scene::addMesh(Mesh mesh) {
    if (mesh.normals.size() != mesh.positions.size()) computeNormals(mesh);
    meshes.push_back(std::move(mesh));
    return static_cast<Id>(meshes.size() - 1);
}

Id Scene::addMaterial(Material material) {
    materials.push_back(std::move(material));
    return static_cast<Id>(materials.size() - 1);
}

Id Scene::addTexture(Texture texture) {
    textures.push_back(std::move(texture));
    return static_cast<Id>(textures.size() - 1);
}

const RgbaImage* Scene::textureImage(Id material) const {
    if (material >= materials.size()) return nullptr;
    const Id t = materials[material].texture;
    if (t >= textures.size() || !textures[t].image || textures[t].image->empty()) return nullptr;
    return textures[t].image.get();
}

Id Scene::addInstance(Id mesh, Id node) {
    instances.push_back(MeshInstance{mesh, node});
    return static_cast<Id>(instances.size() - 1);
}

void Scene::updateWorldTransforms() {
    // Iterative, root first; importers guarantee the hierarchy is a tree.
    std::vector<Id> stack{0};
    nodes[0].world = nodes[0].local;
    while (!stack.empty()) {
        const Id id = stack.back();
        stack.pop_back();
        for (Id c : nodes[id].children) {
            nodes[c].world = nodes[id].world * nodes[c].local;
            stack.push_back(c);
        }
    }
}

void Scene::append(Scene&& other, const std::string& name) {
    const Id nodeBase = static_cast<Id>(nodes.size());
    const Id meshBase = static_cast<Id>(meshes.size());
    const Id matBase = static_cast<Id>(materials.size());
    const Id texBase = static_cast<Id>(textures.size());
    // other's root becomes a named child of our root.
    for (std::size_t i = 0; i < other.nodes.size(); ++i) {
        Node n = std::move(other.nodes[i]);
        if (i == 0) {
            n.name = name;
            n.parent = 0;
        } else {
            n.parent += nodeBase;
        }
        for (Id& c : n.children)
            c += nodeBase;
        nodes.push_back(std::move(n));
    }
    nodes[0].children.push_back(nodeBase);
    for (Mesh& m : other.meshes) {
        m.material += matBase;
        meshes.push_back(std::move(m));
    }
    for (Material& m : other.materials) {
        if (m.texture != kNoId) m.texture += texBase;
        if (m.emissiveTexture != kNoId) m.emissiveTexture += texBase;
        materials.push_back(std::move(m));
    }
    for (Texture& t : other.textures)
        textures.push_back(std::move(t));
    for (const MeshInstance& inst : other.instances) {
        instances.push_back(MeshInstance{inst.mesh + meshBase, inst.node + nodeBase});
    }
    for (auto& f : other.sourceFiles)
        sourceFiles.push_back(std::move(f));
    for (auto& f : other.referencedFiles)
        referencedFiles.push_back(std::move(f));
    for (auto& n : other.importNotes)
        importNotes.push_back(std::move(n));
    updateWorldTransforms();
}

Aabb Scene::instanceBounds(Id instance) const {
    const MeshInstance& inst = instances[instance];
    const glm::dmat4& m = nodes[inst.node].world;
    Aabb b;
    for (const glm::vec3& p : meshes[inst.mesh].positions) {
        b.expand(glm::dvec3(m * glm::dvec4(glm::dvec3(p), 1.0)));
    }
    return b;
}

Aabb Scene::worldBounds() const {
    Aabb b;
    for (Id i = 0; i < instances.size(); ++i)
        b.expand(instanceBounds(i));
    return b;
}

SceneStats Scene::stats() const {
    SceneStats s;
    s.nodes = nodes.size();
    s.meshes = meshes.size();
    s.instances = instances.size();
    s.drawCalls = instances.size();
    s.materials = materials.size();
    for (const Mesh& m : meshes) {
        s.uniqueTriangles += m.triangleCount();
        s.uniqueVertices += m.vertexCount();
    }
    for (const MeshInstance& inst : instances) {
        s.triangles += meshes[inst.mesh].triangleCount();
        s.vertices += meshes[inst.mesh].vertexCount();
    }
    // Depth, iteratively.
    std::vector<std::pair<Id, std::size_t>> stack{{0, 1}};
    while (!stack.empty()) {
        auto [id, d] = stack.back();
        stack.pop_back();
        s.depth = std::max(s.depth, d);
        for (Id c : nodes[id].children)
            stack.push_back({c, d + 1});
    }
    return s;
}

void computeNormals(Mesh& mesh) {
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        const glm::vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a],
                                       mesh.positions[c] - mesh.positions[a]);
        mesh.normals[a] += n;
        mesh.normals[b] += n;
        mesh.normals[c] += n;
    }
    for (glm::vec3& n : mesh.normals) {
        const float len = glm::length(n);
        n = len > 0.0f ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
    }
}

} // namespace hlod
