// Rigid copies among a node's inputs, see CopyParts.h.
#include "pipeline/proxy/CopyParts.h"

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
    for (std::size_t i = 0; i < keys.size(); ++i) {
        if (!isRigidPlacement(linears[i])) continue;
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

} // namespace hlod
