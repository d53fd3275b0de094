// Rigid copies among a node's inputs, see CopyParts.h.
#include "pipeline/proxy/CopyParts.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace hlod {

bool isRigidPlacement(const glm::dmat3& linear) {
    if (!(glm::determinant(linear) > 0.0)) return false;
    const glm::dmat3 gram = glm::transpose(linear) * linear;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (!(std::abs(gram[i][j] - (i == j ? 1.0 : 0.0)) <= kRigidTolerance)) return false;
    return true;
}

CopyGroups groupRigidCopies(std::span<const std::uint64_t> keys,
                            std::span<const glm::dmat3> linears) {
    CopyGroups out;
    std::unordered_map<std::uint64_t, std::size_t> groupOf; // key -> index into `all`
    std::vector<std::vector<std::size_t>> all;
    std::vector<std::uint8_t> rigid(keys.size(), 0);
    for (std::size_t i = 0; i < keys.size(); ++i) {
        rigid[i] = isRigidPlacement(linears[i]) ? 1 : 0;
        if (!rigid[i]) continue;
        const auto [it, added] = groupOf.try_emplace(keys[i], all.size());
        if (added) all.emplace_back();
        all[it->second].push_back(i);
    }
    std::vector<std::uint8_t> copied(keys.size(), 0);
    for (std::vector<std::size_t>& group : all) {
        if (group.size() < 2) continue;
        for (std::size_t i : group)
            copied[i] = 1;
        out.copies.push_back(std::move(group));
    }
    for (std::size_t i = 0; i < keys.size(); ++i)
        if (!copied[i]) out.rest.push_back(i);
    return out;
}

void appendPlaced(const ProxyMesh& part, const glm::dmat3& linear, const glm::dvec3& offset,
                  ProxyMesh& out) {
    const auto first = static_cast<std::uint32_t>(out.positions.size());
    for (const glm::vec3& p : part.positions)
        out.positions.push_back(glm::vec3(linear * glm::dvec3(p) + offset));
    if (part.normals.size() == part.positions.size()) {
        for (const glm::vec3& n : part.normals)
            out.normals.push_back(glm::vec3(linear * glm::dvec3(n)));
    }
    if (part.colors.size() == part.positions.size())
        out.colors.insert(out.colors.end(), part.colors.begin(), part.colors.end());
    else
        out.colors.insert(out.colors.end(), part.positions.size(), glm::u8vec4(204, 204, 204, 255));
    for (std::uint32_t v : part.indices)
        out.indices.push_back(first + v);
    out.errorBound = std::max(out.errorBound, part.errorBound);
}

} // namespace hlod
