// Checks the invariants stated in ClusterTree.h, for tests and for trees read back from disk
// or changed by hand edits.
//
// Returns an empty string when the tree is valid, else a one-line description of the first
// violation found. Containment is checked with a tolerance of 1e-9 relative to the node's size
// (plus 1e-9 m), because enclosing spheres are computed in floating point.
#pragma once

#include <cstddef>
#include <string>

#include "pipeline/cluster/ClusterTree.h"

namespace hlod {

std::string validateClusterTree(const ClusterTree& tree, std::size_t instanceCount);

} // namespace hlod
