// Vertex welding of an aggregated proxy input: a vertex whose colour equals that of an earlier
// vertex and whose position is within `tolerance` of it on every axis becomes that vertex (the
// first one in index order keeps its position). A hash grid of cells 4 * tolerance wide finds
// the candidates, neighbouring cells included, so twins straddling a cell wall still weld.
// Triangles that become degenerate (two equal corners) are removed and unreferenced vertices
// dropped.
//
// Why: children come from different meshes and transforms, so surfaces that touch in the scene
// share positions only up to float rounding; welded, the quadric simplifier sees one connected
// surface and can collapse across the former seams instead of locking them as borders.
// Error: a vertex moves by at most tolerance * sqrt(3).
// tolerance == 0 welds bit-identical positions only. Normals are dropped (recomputed later).
// Deterministic: output order follows first use in the index buffer.
#pragma once

#include "pipeline/proxy/ProxyMesh.h"

namespace hlod {

void weldVertices(ProxyMesh& mesh, float tolerance);

// The general form. `byColour` false welds vertices of any colour (the first one's colour
// stays). `sides` welds triangle corners instead of vertices: a corner joins a representative
// only when its face's normal is within 120 degrees of the normal of the face that made the
// representative, so the front and back faces of a two-sided sheet (a wall modelled as both
// faces over the same corners) stay two open sheets instead of one closed zero-volume pillow,
// whose every edge would look interior to a simplifier (QuadricSimplify.h).
struct WeldOptions {
    float tolerance = 0.0f;
    bool byColour = true;
    bool sides = false;
};
void weldCorners(ProxyMesh& mesh, const WeldOptions& options);

// Drops triangles with two equal corners and vertices no triangle uses (keeps first-use order).
void compactMesh(ProxyMesh& mesh);

} // namespace hlod
