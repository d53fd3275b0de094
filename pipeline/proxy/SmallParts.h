// Removal of parts too small to matter at a proxy's switch distance: connected components
// (vertices shared through triangles) whose bounding-box diagonal is below `minDiagonal`.
//
// Why: at the switch point one pixel covers e metres (ErrorBudget.h); a part smaller than e
// covers less than a pixel, so dropping it keeps the proxy within its error budget, and the
// quadric simplifier could not remove it anyway (a closed part never collapses below a few
// triangles). Run after welding so touching parts count as one.
// Returns the number of triangles removed. Deterministic (union-find over index order).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "pipeline/proxy/ProxyMesh.h"

namespace hlod {

std::size_t dropSmallParts(ProxyMesh& mesh, float minDiagonal);

// Connected component of every vertex, named by its smallest vertex index (so the result does
// not depend on the order unions happen in); unused vertices are their own component.
std::vector<std::uint32_t> componentRoots(const ProxyMesh& mesh);

// Number of connected components (for tests and statistics).
std::size_t countParts(const ProxyMesh& mesh);

} // namespace hlod
