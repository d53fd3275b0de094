// Edge-collapse simplification whose every collapse is certified by successive mapping: each
// vertex carries a bound of the surface's two-sided distance to the original around it, and a
// collapse is made only when the new vertex's bound stays within the limit (MappingBound.h).
//
// Based on: Garland & Heckbert 1997 (plane quadrics, area-weighted, and constraint planes along
// feature edges, to choose and place collapses), Cohen, Manocha & Olano 1997 (successive
// mapping: the certificate), the link condition of Dey, Edelsbrunner, Guha & Nekhayev 1999, and
// a priority queue with local updates (each collapse re-scores only the vertices around it).
//
// Why: the certificate this replaces tested every reshaped face against the input surface with
// spatial queries (grid lookups and bisection, 35 pieces per face on the tiled engine), which was
// 78 % of a bake. The mapping bound reads only the faces around the edge (about a dozen). It is
// looser than a distance test where many collapses pile up on a curved surface (it adds up
// their moves), so the simplification continues with that test where this one stops
// (DecimateProxy.h).
// Rules: a vertex whose faces do not form one fan (a disc or a half-disc) never moves nor takes
// another in; a border vertex moves only along its border (it is first moved onto the line to
// its neighbours, which raises its faces' bounds by that distance) and an edge joining two
// borders that is not itself a border edge never collapses; a collapse that would turn a face
// by more than 78 degrees or break the link condition is refused. Placement: the point of least
// quadric error among the optimum (when it lies near the edge), the midpoint and both ends
// (interior edges), or the end on the border.
// Output: the surviving faces in input order with the final positions (the input's, moved) and
// the bound of every vertex, never more than `limit` where a collapse made it (vertices the
// collapses did not touch keep their input bound). Deterministic, single-threaded.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace hlod {

struct CertifiedSimplifyResult {
    std::vector<glm::vec3> positions;   // per input vertex (moved where collapses moved them)
    std::vector<std::uint32_t> indices; // surviving faces, input order
    std::vector<float> vertexBounds;    // per input vertex (metres)
    std::vector<std::uint32_t> representative; // per input vertex: the vertex it became
    std::size_t collapses = 0;
};

// `vertexBounds`: per input vertex its bound against the original surface (empty: all 0).
// `limit` in the units of the positions.
CertifiedSimplifyResult simplifyCertified(std::span<const glm::vec3> positions,
                                          std::span<const std::uint32_t> indices,
                                          std::span<const float> vertexBounds, double limit);

} // namespace hlod
