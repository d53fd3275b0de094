// Exact binary form of a ClusterTree (every field bit for bit, host little-endian layout), for
// handing a tree to other processes: the shards of a distributed bake read the tree the plan
// clustered (pipeline/graph/BakePlan.h), so their proxy keys are the ones a single-machine
// build computes. Not an interchange format.
// Failure: readClusterTreeBinary throws Error(Malformed) naming `origin` on truncated or
// inconsistent bytes (bad magic or version, ids out of range, a child that does not name its
// parent, no root); it never reads past the buffer and caps counts by its size.
#pragma once

#include <filesystem>
#include <string>

#include "pipeline/cluster/ClusterTree.h"

namespace hlod {

std::string writeClusterTreeBinary(const ClusterTree& tree);
ClusterTree readClusterTreeBinary(const std::string& bytes, const std::filesystem::path& origin);

} // namespace hlod
