// COLLADA instancing bound (issue 22). A COLLADA <node> may place another node by reference
// (<instance_node url="#id">), and assimp's loader resolves every reference by copying the
// referenced subtree: a node placed twice at each of N levels becomes 2^N nodes. A 4 KB file
// of 18 levels took assimp 20 s and 1.6 GB; 22 levels runs into the readers' 8 GB limit after
// minutes. This scans the document's tags once (no DOM), counts what the references expand to
// with each node visited once, and refuses the file before assimp sees it.
//
// Counted: nodes after expansion (what assimp allocates) and placed geometries
// (<instance_geometry>/<instance_controller>), both against limits.maxInstances.
// Failure: Error(TooLarge) naming the file, the count and the limit; Error(Malformed) for a
// node that instances itself (assimp recurses until its stack overflows). A file the scan does
// not understand is left to assimp.
#pragma once

#include <filesystem>

#include "pipeline/io/ImportLimits.h"

namespace hlod {

void checkDaeInstancing(const std::filesystem::path& file, const ImportLimits& limits);

} // namespace hlod
