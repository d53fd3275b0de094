// Two-sided sampled surface deviation between a mesh and a simplified version of it that
// indexes the same vertex array (what meshopt_simplify returns), tested against a limit.
//
// Why: meshoptimizer 0.18's error is an area-weighted RMS distance to the planes of the
// collapsed triangles (its quadricError divides by the accumulated area), not a maximum; on
// curved surfaces the real deviation reaches 1.5-3x the requested value. The proxy budget is a
// maximum (one pixel at the switch point), so simplifications are checked with this.
// Measure (Hausdorff distance sampled, as Metro by Cignoni et al. 1998 does): simplified ->
// original from the corners, edge midpoints and centroids of the simplified triangles;
// original -> simplified from every original vertex and triangle centroid.
// Result: true when every sample is within `limit` (metres, same frame as the positions).
//
// How it stays cheap (linear in the triangles, one grid per mesh):
// - Corners of simplified triangles and surviving vertices are original vertices (distance 0).
// - Nearest triangles come from a uniform grid of cells at least 2 * limit wide, so a query
//   reads at most 2 x 2 x 2 cells and stops at the first triangle within the limit; the
//   triangle that answered the previous query is tried first (consecutive samples are usually
//   on the same triangle). Candidates are first tested against their plane and edge planes
//   (lower bounds of the distance), the exact point-triangle distance only when those pass.
// - The distance to a triangle is a convex function, so a sample that is a mean of points
//   within the limit of one triangle is within the limit of it too: a centroid is not
//   queried when one triangle answered all three corners (original triangles) or all three
//   edge midpoints (simplified triangles). This is exact, not a thinner sampling.
#pragma once

#include <cstdint>
#include <memory>
#include <span>

#include <glm/glm.hpp>

namespace hlod {

bool withinDeviation(std::span<const glm::vec3> positions, std::span<const std::uint32_t> original,
                     std::span<const std::uint32_t> simplified, double limit);

// The same test for several candidate simplifications of one mesh: the grid over the original
// triangles is built once (a part may be tried at several targets, see PartwiseSimplify.h).
// reset() starts on another mesh and reuses the grids' memory, so one checker serves all the
// parts of a node without allocating per part. Keeps references to `positions` and `original`.
class DeviationChecker {
public:
    DeviationChecker();
    DeviationChecker(std::span<const glm::vec3> positions, std::span<const std::uint32_t> original,
                     double limit);
    ~DeviationChecker();
    DeviationChecker(const DeviationChecker&) = delete;
    DeviationChecker& operator=(const DeviationChecker&) = delete;

    void reset(std::span<const glm::vec3> positions, std::span<const std::uint32_t> original,
               double limit);
    bool accepts(std::span<const std::uint32_t> simplified);

private:
    struct Surfaces;
    std::span<const glm::vec3> positions_;
    std::span<const std::uint32_t> original_;
    float limit_ = 0.0f;
    std::unique_ptr<Surfaces> surfaces_;
};

// One direction only, meshes with their own vertices: every sample of `mesh` (corners, edge
// midpoints, centroids) lies within `limit` of `reference`'s surface. Used for remeshed
// shells, whose hidden input parts must not count as missing.
bool withinDistanceOf(std::span<const glm::vec3> meshPositions, std::span<const std::uint32_t> mesh,
                      std::span<const glm::vec3> referencePositions,
                      std::span<const std::uint32_t> reference, double limit);

} // namespace hlod
