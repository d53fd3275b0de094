// Post-import validation: some parsers (tinygltf, assimp) accept broken files silently, so
// every importer checks its result here before handing it out.
#include <cmath>
#include <string>
#include <vector>

#include "pipeline/core/Error.h"
#include "pipeline/io/Import.h"

namespace hlod {

namespace {

void validateMesh(const Mesh& m, std::size_t id, std::size_t materialCount,
                  const std::filesystem::path& file) {
    const std::string what = "mesh " + std::to_string(id) + " ('" + m.name + "')";
    if (m.indices.size() % 3 != 0) {
        throw Error(ErrorCode::Malformed, file, what + ": index count is not a multiple of 3");
    }
    const std::size_t n = m.positions.size();
    for (std::uint32_t i : m.indices) {
        if (i >= n) {
            throw Error(ErrorCode::Malformed, file,
                        what + ": index " + std::to_string(i) + " out of range (" +
                            std::to_string(n) + " vertices)");
        }
    }
    for (const glm::vec3& p : m.positions) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            throw Error(ErrorCode::Malformed, file, what + ": position is NaN or infinite");
        }
    }
    if (m.normals.size() != n || (!m.uvs.empty() && m.uvs.size() != n) ||
        (!m.colors.empty() && m.colors.size() != n)) {
        throw Error(ErrorCode::Malformed, file, what + ": attribute counts differ");
    }
    if (m.material >= materialCount) {
        throw Error(ErrorCode::Malformed, file, what + ": material id out of range");
    }
}

void validateHierarchy(const Scene& scene, const std::filesystem::path& file) {
    std::vector<char> seen(scene.nodes.size(), 0);
    std::vector<Id> stack{0};
    std::size_t visited = 0;
    while (!stack.empty()) {
        const Id id = stack.back();
        stack.pop_back();
        if (id >= scene.nodes.size() || seen[id]) {
            throw Error(ErrorCode::Malformed, file, "node hierarchy has a cycle or shared child");
        }
        seen[id] = 1;
        ++visited;
        for (Id c : scene.nodes[id].children) {
            if (c >= scene.nodes.size() || scene.nodes[c].parent != id) {
                throw Error(ErrorCode::Malformed, file, "node hierarchy is inconsistent");
            }
            stack.push_back(c);
        }
    }
    if (visited != scene.nodes.size()) {
        throw Error(ErrorCode::Malformed, file, "node hierarchy has unreachable nodes");
    }
    for (const Node& n : scene.nodes) {
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r) {
                if (!std::isfinite(n.world[c][r])) {
                    throw Error(ErrorCode::Malformed, file,
                                "node '" + n.name + "' has a NaN or infinite transform");
                }
            }
        }
    }
}

} // namespace

void validateScene(const Scene& scene, const std::filesystem::path& file) {
    validateHierarchy(scene, file);
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        validateMesh(scene.meshes[i], i, scene.materials.size(), file);
    }
    std::size_t triangles = 0;
    for (const MeshInstance& inst : scene.instances) {
        if (inst.mesh >= scene.meshes.size() || inst.node >= scene.nodes.size()) {
            throw Error(ErrorCode::Malformed, file, "mesh instance refers to a missing mesh");
        }
        triangles += scene.meshes[inst.mesh].triangleCount();
    }
    if (triangles == 0) throw Error(ErrorCode::NoGeometry, file, "scene holds no triangles");
}

void checkSceneLimits(const Scene& scene, const std::filesystem::path& file,
                      const ImportLimits& limits) {
    std::uint64_t unique = 0, drawn = 0;
    for (const Mesh& m : scene.meshes)
        unique += m.triangleCount();
    for (const MeshInstance& inst : scene.instances) {
        if (inst.mesh < scene.meshes.size()) drawn += scene.meshes[inst.mesh].triangleCount();
    }
    if (unique > limits.maxUniqueTriangles) {
        throwOverLimit(file, "the meshes hold " + std::to_string(unique) + " triangles",
                       limits.maxUniqueTriangles, "--max-unique-triangles");
    }
    if (scene.instances.size() > limits.maxInstances) {
        throwOverLimit(
            file, "the scene places " + std::to_string(scene.instances.size()) + " mesh instances",
            limits.maxInstances, "--max-instances");
    }
    if (drawn > limits.maxTriangles) {
        throwOverLimit(file, "its placed meshes make " + std::to_string(drawn) + " triangles",
                       limits.maxTriangles, "--max-triangles");
    }
}

} // namespace hlod
