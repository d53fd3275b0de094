// Two-sided sampled surface deviation between a mesh and a simplified version of it that
// indexes the same vertex array (what meshopt_simplify returns), tested against a limit.
//
// Why: meshoptimizer 0.18's error is an area-weighted RMS distance to the planes of the
// collapsed triangles (its quadricError divides by the accumulated area), not a maximum; on
// curved surfaces the real deviation reaches 1.5-3x the requested value. The proxy budget is a
// maximum (one pixel at the switch point), so simplifications are checked with this.
// Measure: the two-sided Hausdorff distance, certified rather than sampled. Every triangle of
// one mesh is shown to lie within the limit of the other mesh's surface: the distance to one
// triangle is a convex function, so a triangle whose three corners lie within the limit of
// the same triangle T lies within it entirely. A triangle whose corners have no such common T
// has an edge bisected (SurfaceQuery.h) and both halves are certified the same way, down to
// pieces whose longest edge is 1/32 of the limit (queries run at 31/32 of the limit, so such a
// piece is within the limit wherever its corners are). Metro (Cignoni et al. 1998) samples points;
// corners, midpoints and centroids alone missed the middle of long triangles (a 50 m strip of
// track spanning a bend). A triangle that needs more than 2^14 pieces counts as a violation
// (conservative).
// Result: true when both directions hold within `limit` (metres, same frame as the positions).
//
// How it stays cheap (linear in the triangles, one grid per mesh):
// - Corners of simplified triangles and surviving vertices are original vertices (distance 0);
//   an original triangle first tries the simplified triangles its surviving corners belong to.
// - Nearest triangles come from a uniform grid of cells at least 2 * limit wide, so a query
//   reads at most 2 x 2 x 2 cells and stops at the first triangle within the limit; the
//   triangle that answered the previous query is tried first (consecutive samples are usually
//   on the same triangle). Candidates are first tested against their plane and edge planes
//   (lower bounds of the distance), the exact point-triangle distance only when those pass.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace hlod {

// Where a simplification leaves the limit: original triangles some point of which is far from
// the simplified surface, and simplified triangles with a point far from the original (that
// point, in simplifiedPoints, one per triangle).
struct DeviationViolations {
    std::vector<std::uint32_t> originalTriangles;   // triangle numbers in `original`
    std::vector<std::uint32_t> simplifiedTriangles; // triangle numbers in `simplified`
    std::vector<glm::vec3> simplifiedPoints;
};

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
    // The same test, reporting up to `maxReports` violations of each direction (0: stop at the
    // first); true when there are none.
    bool findViolations(std::span<const std::uint32_t> simplified, DeviationViolations& out,
                        std::size_t maxReports);
    // The same for a simplified mesh whose vertices moved: `simplifiedPositions` holds them,
    // indexed like the original's (a vertex that did not move keeps its position).
    // `bothWays` false checks only original -> simplified (for a simplification whose every
    // new face was certified against the original when it was made, QuadricSimplify.h).
    bool findViolations(std::span<const glm::vec3> simplifiedPositions,
                        std::span<const std::uint32_t> simplified, DeviationViolations& out,
                        std::size_t maxReports, bool bothWays = true);

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
