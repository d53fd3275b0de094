// `sloppy` proxies: the aggregated children clustered on a uniform grid (vertex clustering,
// Rossignac & Borrel 1993; Lindstrom 2000's quadric representative per cell), as implemented
// by meshoptimizer's meshopt_simplifySloppy. Topology is not kept: thin parts, gaps and small
// holes closer than a cell merge, which makes it the fastest and most aggressive method.
//
// Error: cells of size maxError / sqrt(3) so a vertex moves at most maxError (one cell
// diagonal). meshoptimizer 0.18 caps the grid at 1000 cells per axis; when the budget asks for
// finer cells (pixel error below ~0.5 px at the default screen size) the method falls back to
// `decimate`, which keeps the budget.
// Output: finished proxy, never more triangles than the input. Deterministic.
#pragma once

#include "pipeline/proxy/ProxyMesh.h"

namespace hlod {

ProxyMesh sloppyProxy(ProxyMesh input, double maxError);

} // namespace hlod
