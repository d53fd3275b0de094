// Certified two-sided Hausdorff test (the surface queries of SurfaceQuery.h), see
// DeviationCheck.h.
#include "pipeline/proxy/DeviationCheck.h"

#include <memory>
#include <vector>

#include "pipeline/proxy/SurfaceQuery.h"

namespace hlod {

using namespace surface;

bool withinDistanceOf(std::span<const glm::vec3> meshPositions, std::span<const std::uint32_t> mesh,
                      std::span<const glm::vec3> referencePositions,
                      std::span<const std::uint32_t> reference, double limitMetres) {
    if (mesh.empty()) return true;
    if (reference.empty()) return false;
    const auto limit = static_cast<float>(limitMetres);
    NearSurface surface;
    surface.reset(referencePositions, reference, limit * (1.0f - kSlackFraction));
    Coverage coverage(surface, limit * kSlackFraction);
    glm::vec3 failAt;
    for (std::size_t t = 0; t + 2 < mesh.size(); t += 3) {
        if (!coverage.covers(meshPositions[mesh[t]], meshPositions[mesh[t + 1]],
                             meshPositions[mesh[t + 2]], {}, failAt))
            return false;
    }
    return true;
}

struct DeviationChecker::Surfaces {
    NearSurface original, simplified;
    bool originalReady = false;         // `original` matches the current mesh
    std::vector<std::uint32_t> nearest; // per vertex, scratch of findViolations()
};

DeviationChecker::DeviationChecker() : surfaces_(std::make_unique<Surfaces>()) {}

DeviationChecker::DeviationChecker(std::span<const glm::vec3> positions,
                                   std::span<const std::uint32_t> original, double limitMetres)
    : DeviationChecker() {
    reset(positions, original, limitMetres);
}

DeviationChecker::~DeviationChecker() = default;

void DeviationChecker::reset(std::span<const glm::vec3> positions,
                             std::span<const std::uint32_t> original, double limitMetres) {
    positions_ = positions;
    original_ = original;
    limit_ = static_cast<float>(limitMetres);
    surfaces_->originalReady = false; // set up by the first check: unchanged parts need none
}

bool DeviationChecker::accepts(std::span<const std::uint32_t> simplified) {
    DeviationViolations none;
    return findViolations(simplified, none, 0);
}

bool DeviationChecker::findViolations(std::span<const std::uint32_t> simplified,
                                      DeviationViolations& out, std::size_t maxReports) {
    return findViolations(positions_, simplified, out, maxReports);
}

bool DeviationChecker::findViolations(std::span<const glm::vec3> moved,
                                      std::span<const std::uint32_t> simplified,
                                      DeviationViolations& out, std::size_t maxReports,
                                      bool bothWays) {
    out = DeviationViolations{};
    if (original_.empty()) return true;
    if (simplified.empty()) {
        for (std::size_t t = 0; t < original_.size() / 3 && t < maxReports; ++t)
            out.originalTriangles.push_back(static_cast<std::uint32_t>(t));
        return false;
    }
    Surfaces& s = *surfaces_;
    // Queries run at the limit less the slack of Coverage, so certified pieces are within it.
    const float query = limit_ * (1.0f - kSlackFraction), slack = limit_ * kSlackFraction;
    if (bothWays && !s.originalReady) {
        s.original.reset(positions_, original_, query);
        s.originalReady = true;
    }
    bool ok = true;
    glm::vec3 failAt;
    // Simplified -> original.
    Coverage toOriginal(s.original, slack);
    for (std::size_t t = 0; bothWays && t + 2 < simplified.size(); t += 3) {
        if (toOriginal.covers(moved[simplified[t]], moved[simplified[t + 1]],
                              moved[simplified[t + 2]], {}, failAt))
            continue;
        ok = false;
        if (out.simplifiedTriangles.size() >= maxReports) break;
        out.simplifiedTriangles.push_back(static_cast<std::uint32_t>(t / 3));
        out.simplifiedPoints.push_back(failAt);
    }
    if (!ok && maxReports == 0) return false;
    // Original -> simplified. A surviving vertex is a corner of a simplified triangle (at
    // distance 0 when it did not move): that triangle is tried first for every original triangle
    // the vertex is a corner of.
    constexpr std::uint32_t kUnknown = 0xffffffffu;
    s.nearest.assign(positions_.size(), kUnknown);
    for (std::size_t i = 0; i < simplified.size(); ++i) {
        std::uint32_t& t = s.nearest[simplified[i]];
        if (t == kUnknown) t = static_cast<std::uint32_t>(i / 3);
    }
    s.simplified.reset(moved, simplified, query);
    Coverage toSimplified(s.simplified, slack);
    for (std::size_t t = 0; t + 2 < original_.size(); t += 3) {
        const std::uint32_t a = original_[t], b = original_[t + 1], c = original_[t + 2];
        const std::uint32_t hints[3] = {s.nearest[a], s.nearest[b], s.nearest[c]};
        if (toSimplified.covers(positions_[a], positions_[b], positions_[c], hints, failAt))
            continue;
        ok = false;
        if (out.originalTriangles.size() >= maxReports) break;
        out.originalTriangles.push_back(static_cast<std::uint32_t>(t / 3));
    }
    return ok;
}

bool withinDeviation(std::span<const glm::vec3> positions, std::span<const std::uint32_t> original,
                     std::span<const std::uint32_t> simplified, double limitMetres) {
    return DeviationChecker(positions, original, limitMetres).accepts(simplified);
}

} // namespace hlod
