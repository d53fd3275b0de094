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

#include <nlohmann/json.hpp>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/cluster/TreeMetrics.h"

namespace hlod {

nlohmann::json clusterTreeToJson(const ClusterTree& tree);
nlohmann::json treeMetricsToJson(const TreeMetrics& metrics);

} // namespace hlod
