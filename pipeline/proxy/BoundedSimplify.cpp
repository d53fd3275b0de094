// Quadric simplification repaired by locks until a certified deviation check passes, see
// BoundedSimplify.h.
#include "pipeline/proxy/BoundedSimplify.h"

#include <algorithm>

#include "pipeline/proxy/DeviationCheck.h"
#include "pipeline/proxy/QuadricSimplify.h"

namespace hlod {

namespace {

constexpr std::uint32_t kNone = 0xffffffffu;

// Locks what the violations point at; returns how many vertices were newly locked.
std::size_t lockViolations(std::span<const glm::vec3> positions,
                           std::span<const std::uint32_t> indices,
                           const QuadricSimplifyResult& r, const DeviationViolations& v,
                           std::vector<std::uint8_t>& locked) {
    std::size_t added = 0;
    auto lock = [&](std::uint32_t x) {
        if (!locked[x]) locked[x] = 1, ++added;
    };
    for (std::uint32_t t : v.originalTriangles)
        for (int k = 0; k < 3; ++k)
            lock(indices[3 * t + k]);
    if (v.simplifiedTriangles.empty()) return added;
    // Failing simplified triangles by corner: a vertex collapsed into a corner of one of them
    // and near its failing point is locked (it held the surface there).
    std::vector<std::uint32_t> firstFailure(positions.size(), kNone);
    std::vector<std::uint32_t> nextFailure; // chains of (triangle, corner) entries
    std::vector<std::uint32_t> entryTriangle;
    for (std::size_t i = 0; i < v.simplifiedTriangles.size(); ++i) {
        const std::uint32_t t = v.simplifiedTriangles[i];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t corner = r.indices[3 * t + k];
            entryTriangle.push_back(static_cast<std::uint32_t>(i));
            nextFailure.push_back(firstFailure[corner]);
            firstFailure[corner] = static_cast<std::uint32_t>(nextFailure.size() - 1);
        }
    }
    // Per failing triangle, the vertex collapsed into one of its corners nearest to where it
    // failed: the one that held the surface there.
    std::vector<std::uint32_t> nearest(v.simplifiedTriangles.size(), kNone);
    std::vector<float> best(v.simplifiedTriangles.size(), 0.0f);
    for (std::uint32_t x = 0; x < positions.size(); ++x) {
        const std::uint32_t rep = r.representative[x];
        if (rep == x) continue; // survivors are corners already
        for (std::uint32_t e = firstFailure[rep]; e != kNone; e = nextFailure[e]) {
            const std::uint32_t i = entryTriangle[e];
            const glm::vec3 d = positions[x] - v.simplifiedPoints[i];
            const float d2 = glm::dot(d, d);
            if (nearest[i] == kNone || d2 < best[i]) nearest[i] = x, best[i] = d2;
        }
    }
    for (std::uint32_t x : nearest)
        if (x != kNone) lock(x);
    return added;
}

} // namespace

BoundedSimplifyResult simplifyWithinDeviation(std::span<const glm::vec3> positions,
                                              std::span<const std::uint32_t> indices,
                                              double maxError,
                                              const BoundedSimplifyOptions& options,
                                              BoundedSimplifyStats* stats) {
    BoundedSimplifyStats local;
    BoundedSimplifyStats& st = stats ? *stats : local;
    st = BoundedSimplifyStats{};
    const BoundedSimplifyResult input{{indices.begin(), indices.end()},
                                      {positions.begin(), positions.end()}};
    if (indices.empty() || !(maxError > 0.0)) return input;
    std::vector<std::uint8_t> locked(positions.size(), 0);
    DeviationChecker checker(positions, indices, maxError);
    DeviationViolations violations;
    for (int round = 0; round < options.maxRounds; ++round) {
        ++st.rounds;
        QuadricSimplifyResult r = simplifyWithQuadrics(
            positions, indices, locked, options.targetFraction * maxError, maxError);
        if (r.indices.size() == indices.size()) return input; // nothing collapsed: unchanged
        // Every reshaped face was certified when it was made (QuadricSimplify.h): the samples'
        // direction is what is left to prove.
        if (checker.findViolations(r.positions, r.indices, violations, 1u << 16, false))
            return BoundedSimplifyResult{std::move(r.indices), std::move(r.positions)};
        const std::size_t added = lockViolations(positions, indices, r, violations, locked);
        st.locked += added;
        if (added == 0) break;
    }
    st.fellBack = true;
    return input;
}

} // namespace hlod
