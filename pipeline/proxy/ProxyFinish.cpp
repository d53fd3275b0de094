// Crease-angle normals and meshoptimizer's render layout, see ProxyFinish.h.
#include "pipeline/proxy/ProxyFinish.h"

#include <cmath>

#include <meshoptimizer.h>

namespace hlod {

namespace {

// Corner normals are only smoothed over this many faces; beyond it (huge fans) a vertex takes
// its face normal, which keeps the cost linear in the worst case.
constexpr std::size_t kMaxSmoothValence = 256;

struct VertexFaces {
    std::vector<std::uint32_t> offsets; // per vertex, into faces
    std::vector<std::uint32_t> faces;
};

VertexFaces buildVertexFaces(const ProxyMesh& m) {
    VertexFaces vf;
    vf.offsets.assign(m.positions.size() + 1, 0);
    for (std::uint32_t v : m.indices)
        ++vf.offsets[v + 1];
    for (std::size_t i = 1; i < vf.offsets.size(); ++i)
        vf.offsets[i] += vf.offsets[i - 1];
    vf.faces.resize(m.indices.size());
    std::vector<std::uint32_t> fill(vf.offsets.begin(), vf.offsets.end() - 1);
    for (std::size_t i = 0; i < m.indices.size(); ++i) {
        vf.faces[fill[m.indices[i]]++] = static_cast<std::uint32_t>(i / 3);
    }
    return vf;
}

glm::vec3 cornerNormal(const VertexFaces& vf, const std::vector<glm::vec3>& areaNormal,
                       const std::vector<glm::vec3>& unitNormal, std::uint32_t v, std::size_t f,
                       float cosCrease) {
    glm::vec3 n = areaNormal[f];
    const std::uint32_t begin = vf.offsets[v], end = vf.offsets[v + 1];
    if (end - begin <= kMaxSmoothValence) {
        n = glm::vec3(0.0f);
        for (std::uint32_t k = begin; k < end; ++k) {
            const std::uint32_t g = vf.faces[k];
            if (glm::dot(unitNormal[f], unitNormal[g]) >= cosCrease) n += areaNormal[g];
        }
    }
    const float len = glm::length(n);
    if (len > 0.0f) return n / len;
    return glm::length(unitNormal[f]) > 0.0f ? unitNormal[f] : glm::vec3(0.0f, 0.0f, 1.0f);
}

} // namespace

void computeCreaseNormals(ProxyMesh& mesh, float creaseDegrees) {
    const std::size_t faceCount = mesh.indices.size() / 3;
    std::vector<glm::vec3> areaNormal(faceCount), unitNormal(faceCount);
    for (std::size_t f = 0; f < faceCount; ++f) {
        const glm::vec3& a = mesh.positions[mesh.indices[3 * f]];
        const glm::vec3& b = mesh.positions[mesh.indices[3 * f + 1]];
        const glm::vec3& c = mesh.positions[mesh.indices[3 * f + 2]];
        areaNormal[f] = glm::cross(b - a, c - a);
        const float len = glm::length(areaNormal[f]);
        unitNormal[f] = len > 0.0f ? areaNormal[f] / len : glm::vec3(0.0f);
    }
    const float cosCrease = std::cos(creaseDegrees * 3.14159265f / 180.0f);
    const VertexFaces vf = buildVertexFaces(mesh);

    if (mesh.colors.size() != mesh.positions.size()) {
        mesh.colors.assign(mesh.positions.size(), glm::u8vec4(255));
    }
    ProxyMesh out;
    out.origin = mesh.origin;
    out.indices.resize(mesh.indices.size());
    // Splits of one input vertex form a chain: firstSplit[v] -> nextSplit[s] -> ...
    constexpr std::uint32_t kNone = 0xffffffffu;
    std::vector<std::uint32_t> firstSplit(mesh.positions.size(), kNone);
    std::vector<std::uint32_t> nextSplit;
    for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
        const std::uint32_t v = mesh.indices[i];
        const glm::vec3 n = cornerNormal(vf, areaNormal, unitNormal, v, i / 3, cosCrease);
        std::uint32_t target = kNone, last = kNone;
        for (std::uint32_t s = firstSplit[v]; s != kNone; s = nextSplit[s]) {
            last = s;
            if (out.normals[s] == n) {
                target = s;
                break;
            }
        }
        if (target == kNone) {
            target = static_cast<std::uint32_t>(out.positions.size());
            if (last == kNone)
                firstSplit[v] = target;
            else
                nextSplit[last] = target;
            nextSplit.push_back(kNone);
            out.positions.push_back(mesh.positions[v]);
            out.normals.push_back(n);
            out.colors.push_back(mesh.colors[v]);
        }
        out.indices[i] = target;
    }
    mesh = std::move(out);
}

void optimizeForRendering(ProxyMesh& mesh) {
    if (mesh.indices.empty()) return;
    const std::size_t n = mesh.positions.size();
    meshopt_optimizeVertexCache(mesh.indices.data(), mesh.indices.data(), mesh.indices.size(), n);
    std::vector<unsigned int> remap(n);
    const std::size_t unique =
        meshopt_optimizeVertexFetchRemap(remap.data(), mesh.indices.data(), mesh.indices.size(), n);
    meshopt_remapIndexBuffer(mesh.indices.data(), mesh.indices.data(), mesh.indices.size(),
                             remap.data());
    auto remapStream = [&](auto& stream) {
        using T = typename std::decay_t<decltype(stream)>::value_type;
        if (stream.size() != n) return;
        std::vector<T> next(unique);
        meshopt_remapVertexBuffer(next.data(), stream.data(), n, sizeof(T), remap.data());
        stream = std::move(next);
    };
    remapStream(mesh.positions);
    remapStream(mesh.normals);
    remapStream(mesh.colors);
}

void finishProxy(ProxyMesh& mesh, float creaseDegrees) {
    computeCreaseNormals(mesh, creaseDegrees);
    optimizeForRendering(mesh);
}

} // namespace hlod
