// Last step of every proxy method: normals and a render-friendly layout.
//
// Normals: area-weighted average of the faces around a vertex that lie within `creaseDegrees`
// of the corner's own face (the classic crease-angle smoothing used by modelling tools), so a
// simplified box keeps hard edges while a simplified cylinder stays smooth. Vertices are split
// where corners end up with different normals.
// Layout: meshoptimizer's vertex cache optimisation (Forsyth-like, Sander et al. 2007 "Tipsify"
// family) and vertex fetch reordering.
// Deterministic; positions, colours and the set of triangles are unchanged.
#pragma once

#include "pipeline/proxy/ProxyMesh.h"

namespace hlod {

void computeCreaseNormals(ProxyMesh& mesh, float creaseDegrees = 60.0f);

void optimizeForRendering(ProxyMesh& mesh);

// Both, in that order.
void finishProxy(ProxyMesh& mesh, float creaseDegrees = 60.0f);

} // namespace hlod
