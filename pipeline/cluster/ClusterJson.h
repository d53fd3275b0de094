// A cluster tree and its metrics as JSON, for `hlod cluster --json` and the package's
// hlod.json.
//
// Tree: {"volume": "sphere"|"aabb"|"octree"|"original", "k": number, "root": id|null,
//        "nodes": [{"id", "parent": id|null, "children": [ids], "instance": id|null (leaves),
//                   "box": {"min": [x,y,z], "max": [x,y,z]},
//                   "sphere": {"center": [x,y,z], "radius"}, "fill", "cost", "level",
//                   "locked"}]}
// Node i of the array has "id" i. Units: metres.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/cluster/TreeMetrics.h"

namespace hlod {

nlohmann::json clusterTreeToJson(const ClusterTree& tree);

// Appends to `out` exactly what clusterTreeToJson(tree).dump(2) gives when that value sits at
// nesting depth `depth` of a document dumped with an indent of 2 (the same keys in the same
// sorted order, numbers formatted by nlohmann's own shortest round trip), without building the
// JSON value: about 5x faster and a fraction of the memory on 100k-node trees.
void appendClusterTreeJson(std::string& out, const ClusterTree& tree, int depth = 0);
nlohmann::json treeMetricsToJson(const TreeMetrics& metrics);

} // namespace hlod
