// Two-sided sampled surface deviation between a mesh and a simplified version of it that
// indexes the same vertex array (what meshopt_simplify returns), tested against a limit.
//
// Why: meshoptimizer 0.18's error is an area-weighted RMS distance to the planes of the
// collapsed triangles (its quadricError divides by the accumulated area), not a maximum; on
// curved surfaces the real deviation reaches 1.5-3x the requested value. The proxy budget is a
// maximum (one pixel at the switch point), so simplifications are checked with this.
// Measure (Hausdorff distance sampled, as Metro by Cignoni et al. 1998 does): simplified ->
// original from the corners, edge midpoints and centroids of the simplified triangles;
// original -> simplified from every original vertex and triangle centroid. Nearest triangles
// come from a uniform grid of cells at least 2 * limit wide, so each query reads at most
// 2 x 2 x 2 cells and stops at the first triangle within the limit.
// Result: true when every sample is within `limit` (metres, same frame as the positions).
#pragma once

#include <cstdint>
#include <memory>
#include <span>

#include <glm/glm.hpp>

namespace hlod {

bool withinDeviation(std::span<const glm::vec3> positions, std::span<const std::uint32_t> original,
                     std::span<const std::uint32_t> simplified, double limit);

// The same test for several candidate simplifications of one mesh: the grid over the original
// triangles is built once (a part is typically tried at 2-3 targets, see PartwiseSimplify.h).
// Keeps references to `positions` and `original`.
class DeviationChecker {
public:
    DeviationChecker(std::span<const glm::vec3> positions, std::span<const std::uint32_t> original,
                     double limit);
    ~DeviationChecker();
    bool accepts(std::span<const std::uint32_t> simplified) const;

private:
    struct Grid;
    std::span<const glm::vec3> positions_;
    std::span<const std::uint32_t> original_;
    float limit_;
    std::unique_ptr<Grid> grid_;
};

// One direction only, meshes with their own vertices: every sample of `mesh` (corners, edge
// midpoints, centroids) lies within `limit` of `reference`'s surface. Used for remeshed
// shells, whose hidden input parts must not count as missing.
bool withinDistanceOf(std::span<const glm::vec3> meshPositions, std::span<const std::uint32_t> mesh,
                      std::span<const glm::vec3> referencePositions,
                      std::span<const std::uint32_t> reference, double limit);

} // namespace hlod
