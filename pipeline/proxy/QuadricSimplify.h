// Quadric-error simplification by edge collapses, with feature edges and vertex locks.
//
// Based on: Garland & Heckbert 1997 (plane quadrics, area weighted), their boundary
// constraint planes (a plane through a boundary edge, perpendicular to its face), half-edge
// collapses onto existing vertices in passes of independent collapses sorted by cost (as
// meshoptimizer's simplifier does, Kapoulkine), and the link condition of Dey, Edelsbrunner,
// Guha & Nekhayev 1999 so that collapses never make a manifold neighbourhood non-manifold.
//
// Why our own (meshoptimizer 0.18 is faster): its collapses may slide a vertex freely within
// a plane whose quadric holds no other constraint. Game and CAD scenes are full of two-sided
// sheets (a barrier modelled as front and back faces over the same four corners, welded into
// a closed zero-volume pillow): every edge has two faces, so no boundary quadric holds the
// sheet's outline and a whole barrier collapses into its neighbour 10 m away at zero quadric
// cost (measured on torcs-spring: deviations of 4-8x the budget at any meshoptimizer target,
// so the deviation check kept nearly every input). Here such edges are features:
// - feature edges: boundary edges (one face), non-manifold edges (three or more faces), and
//   folds (two faces facing away from each other, normals more than ~140 degrees apart, or
//   inconsistently oriented). Each gets a constraint plane per face, weighted by its length
//   squared, so moving its vertices off the edge line costs as much as leaving the surface;
// - a vertex on exactly two feature edges may only collapse along one of them; a vertex on one
//   or more than two (a corner) never moves; an interior vertex collapses along any edge;
// - locked vertices (`locked[v] != 0`, e.g. where a deviation check failed) never move, so
//   triangles whose corners are all locked survive unchanged. Other vertices may collapse
//   onto a locked one.
// A collapse is refused when it would flip or fold a remaining face (its normal turning by
// more than ~78 degrees) or break the link condition.
//
// Bounded mode (deviationLimit > 0): the vertex kinds above become costs only (every vertex
// but a locked one may collapse along any edge, a feature's constraint planes make it
// expensive), and each collapse is made only when the mesh stays within deviationLimit of
// the input both ways: the reshaped faces are certified to lie within it of the input surface
// (SurfaceQuery.h Coverage), and sample points of the input (every vertex, and the centroids
// of a subdivision of each triangle at about the limit's spacing, at most 6 x 6) each stay
// within it of a face; each face owns samples within the limit of it, a collapse re-homes the
// samples of the faces it changes onto the faces around the kept vertex, a face's new shape
// first (Hausdorff tracking as in OpenMesh's ModHausdorffT). Only the sampling of the second
// direction is not a proof: callers certify the result (BoundedSimplify.h).
// Cost: the certificates dominate. Each vertex keeps an input triangle found within the limit
// of it until it moves, so a ring's corners are located once, not once per face; a collapse
// that failed any test is not tried again until a face around either end changes.
//
// Error: a collapse u -> v costs the accumulated quadric of u at v, divided by its weight (an
// area-weighted mean squared distance to u's planes, as meshoptimizer measures); collapses
// above maxError^2 are not made. This is not a bound on the true (Hausdorff) deviation: callers
// check the result (BoundedSimplify.h).
// Placement: in plain mode half-edge collapses (the kept vertex stays where it is). In bounded
// mode the kept vertex moves to the point of least error of both quadrics (the optimum when
// the planes pin one down near the edge, else the midpoint or an end): with half-edge
// collapses a chain of proxies of proxies (each level re-simplifying the level below) can only
// keep vertices the level below kept for its smaller budget, and stalls (torcs-spring, 17
// levels: a root of 3,725 triangles where one step from the originals gives 1,617).
// Output: indices into result.positions, triangles of the input that survived or were
// reshaped, in input order. Deterministic, single-threaded.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace hlod {

struct QuadricSimplifyResult {
    std::vector<std::uint32_t> indices;
    // Per input vertex: the vertex it was finally collapsed into (itself when it survived or
    // was not used).
    std::vector<std::uint32_t> representative;
    // Positions of all vertices afterwards: the input's, except kept vertices that moved to the
    // point of least error of an edge they took in (bounded mode only).
    std::vector<glm::vec3> positions;
};

// Where a continued simplification starts (see simplifyWithQuadricsFrom).
struct QuadricStart {
    std::span<const glm::vec3> positions;          // per input vertex, as moved
    std::span<const std::uint32_t> indices;        // over the input's vertex numbering
    std::span<const std::uint32_t> representative; // per input vertex: the vertex it became
};

// `locked` is empty or has one entry per position. maxError in the units of the positions.
// deviationLimit > 0 turns on the bounded mode (see above).
QuadricSimplifyResult simplifyWithQuadrics(std::span<const glm::vec3> positions,
                                           std::span<const std::uint32_t> indices,
                                           std::span<const std::uint8_t> locked, double maxError,
                                           double deviationLimit = 0.0);

// Bounded mode, continued from `start` (a simplification of the input that lies within
// deviationLimit of it both ways), certified against the input as above.
QuadricSimplifyResult simplifyWithQuadricsFrom(std::span<const glm::vec3> positions,
                                               std::span<const std::uint32_t> indices,
                                               const QuadricStart& start, double maxError,
                                               double deviationLimit);

} // namespace hlod
