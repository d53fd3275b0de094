// Aggregation of a node's children into one world-space soup (thesis 5.3), see Aggregate.h.
#include "pipeline/proxy/Aggregate.h"

#include <algorithm>

namespace hlod {

namespace {

void appendInstance(const Scene& scene, const AggregatePart& part, const glm::dvec3& origin,
                    ProxyMesh& out) {
    const MeshInstance& inst = scene.instances[part.instance];
    const Mesh& mesh = scene.meshes[inst.mesh];
    const glm::dmat4& world = scene.nodes[inst.node].world;
    const Material& material =
        scene.materials[mesh.material < scene.materials.size() ? mesh.material : 0];
    const glm::vec4 base = material.effectiveColor();
    const auto first = static_cast<std::uint32_t>(out.positions.size());

    // Double precision transform, then relative to the node origin, so far-away clusters keep
    // sub-millimetre float precision.
    const glm::dmat3 linear = part.linear ? *part.linear : glm::dmat3(world);
    const glm::dvec3 shift = part.offset ? *part.offset : glm::dvec3(world[3]) - origin;
    for (const glm::vec3& p : mesh.positions) {
        out.positions.push_back(glm::vec3(linear * glm::dvec3(p) + shift));
    }
    if (mesh.colors.size() == mesh.positions.size()) {
        for (const glm::vec4& c : mesh.colors)
            out.colors.push_back(quantizeColor(base * c));
    } else {
        out.colors.insert(out.colors.end(), mesh.positions.size(), quantizeColor(base));
    }
    const bool mirrored = glm::determinant(linear) < 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        out.indices.push_back(first + a);
        out.indices.push_back(first + (mirrored ? c : b));
        out.indices.push_back(first + (mirrored ? b : c));
    }
}

void appendProxy(const AggregatePart& part, const glm::dvec3& origin, ProxyMesh& out) {
    const ProxyMesh& proxy = *part.proxy;
    const auto first = static_cast<std::uint32_t>(out.positions.size());
    const glm::dvec3 shift = part.offset ? *part.offset : proxy.origin - origin;
    const glm::dmat3 linear = part.linear ? *part.linear : glm::dmat3(1.0);
    for (const glm::vec3& p : proxy.positions) {
        out.positions.push_back(glm::vec3(linear * glm::dvec3(p) + shift));
    }
    if (proxy.colors.size() == proxy.positions.size()) {
        out.colors.insert(out.colors.end(), proxy.colors.begin(), proxy.colors.end());
    } else {
        out.colors.insert(out.colors.end(), proxy.positions.size(),
                          glm::u8vec4(204, 204, 204, 255));
    }
    const bool mirrored = glm::determinant(linear) < 0.0;
    for (std::size_t t = 0; t + 2 < proxy.indices.size(); t += 3) {
        out.indices.push_back(first + proxy.indices[t]);
        out.indices.push_back(first + proxy.indices[t + (mirrored ? 2 : 1)]);
        out.indices.push_back(first + proxy.indices[t + (mirrored ? 1 : 2)]);
    }
    out.errorBound = std::max(out.errorBound, proxy.errorBound);
}

} // namespace

std::size_t aggregateTriangleCount(const Scene& scene, std::span<const AggregatePart> parts) {
    std::size_t n = 0;
    for (const AggregatePart& part : parts) {
        if (part.proxy)
            n += part.proxy->triangleCount();
        else if (part.instance != kNoId)
            n += scene.meshes[scene.instances[part.instance].mesh].triangleCount();
    }
    return n;
}

ProxyMesh aggregateParts(const Scene& scene, std::span<const AggregatePart> parts,
                         const glm::dvec3& origin) {
    ProxyMesh out;
    out.origin = origin;
    std::size_t vertices = 0, indices = 0;
    for (const AggregatePart& part : parts) {
        if (part.proxy) {
            vertices += part.proxy->positions.size();
            indices += part.proxy->indices.size();
        } else if (part.instance != kNoId) {
            const Mesh& m = scene.meshes[scene.instances[part.instance].mesh];
            vertices += m.positions.size();
            indices += m.indices.size();
        }
    }
    out.positions.reserve(vertices);
    out.colors.reserve(vertices);
    out.indices.reserve(indices);
    for (const AggregatePart& part : parts) {
        if (part.proxy)
            appendProxy(part, origin, out);
        else if (part.instance != kNoId)
            appendInstance(scene, part, origin, out);
    }
    return out;
}

} // namespace hlod
