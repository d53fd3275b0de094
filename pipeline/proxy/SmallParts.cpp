// Connected components with union-find (path halving, union by index), see SmallParts.h.
#include "pipeline/proxy/SmallParts.h"

#include <limits>
#include <vector>

#include "pipeline/proxy/Weld.h"

namespace hlod {

namespace {

std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t v) {
    while (parent[v] != v) {
        parent[v] = parent[parent[v]];
        v = parent[v];
    }
    return v;
}

} // namespace

std::vector<std::uint32_t> componentRoots(const ProxyMesh& mesh) {
    std::vector<std::uint32_t> parent(mesh.positions.size());
    for (std::uint32_t v = 0; v < parent.size(); ++v)
        parent[v] = v;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        std::uint32_t a = findRoot(parent, mesh.indices[t]);
        for (int k = 1; k < 3; ++k) {
            std::uint32_t b = findRoot(parent, mesh.indices[t + k]);
            if (a == b) continue;
            if (b < a) std::swap(a, b);
            parent[b] = a;
        }
    }
    for (std::uint32_t v = 0; v < parent.size(); ++v)
        parent[v] = findRoot(parent, v);
    return parent;
}

std::size_t countParts(const ProxyMesh& mesh) {
    const std::vector<std::uint32_t> root = componentRoots(mesh);
    std::vector<bool> used(root.size(), false);
    std::size_t parts = 0;
    for (std::uint32_t v : mesh.indices) {
        if (!used[root[v]]) {
            used[root[v]] = true;
            ++parts;
        }
    }
    return parts;
}

std::size_t dropSmallParts(ProxyMesh& mesh, float minDiagonal) {
    if (mesh.indices.empty() || !(minDiagonal > 0.0f)) return 0;
    const std::vector<std::uint32_t> root = componentRoots(mesh);
    constexpr float kMax = std::numeric_limits<float>::max();
    std::vector<glm::vec3> lo(mesh.positions.size(), glm::vec3(kMax));
    std::vector<glm::vec3> hi(mesh.positions.size(), glm::vec3(-kMax));
    for (std::uint32_t v : mesh.indices) {
        const std::uint32_t r = root[v];
        lo[r] = glm::min(lo[r], mesh.positions[v]);
        hi[r] = glm::max(hi[r], mesh.positions[v]);
    }
    std::vector<std::uint32_t> kept;
    kept.reserve(mesh.indices.size());
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t r = root[mesh.indices[t]];
        if (glm::length(hi[r] - lo[r]) < minDiagonal) continue;
        kept.insert(kept.end(), mesh.indices.begin() + static_cast<std::ptrdiff_t>(t),
                    mesh.indices.begin() + static_cast<std::ptrdiff_t>(t + 3));
    }
    const std::size_t removed = (mesh.indices.size() - kept.size()) / 3;
    if (removed == 0) return 0;
    mesh.indices = std::move(kept);
    compactMesh(mesh);
    return removed;
}

} // namespace hlod
