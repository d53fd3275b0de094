// What a finished build did that the parameters do not lead one to expect, said in one line for
// the places a user looks at (issue 31 #7: max children was 8 yet the track's root had 198
// children, and sloppy proxies collapsed the tree to height 1, with the reason only at the
// bottom of Statistics). Based on the proxy economy (ProxyBaker.h): a cluster whose proxy does
// not pay is dissolved and its children hang from its parent, so clusters can end up wider than
// max children, and a tree whose clusters all dissolve keeps only the root over the meshes.
// Shown by the Statistics dock (at its top), the log and the status bar (MainWindow).
#pragma once

#include <vector>

#include <QString>

#include "pipeline/cluster/ClusterTree.h"

namespace hlod::widgets {

struct BuiltHlod;

// Empty when the build holds nothing surprising. Otherwise, e.g. "The proxy economy dissolved
// 923 clusters: the tree collapsed to height 1 and Cluster 5 has 198 children (max children
// 8). ...". `labels` (StudioModel::clusterLabels) number the clusters as the Clusters tab does.
QString dissolveWarning(const BuiltHlod& built, const std::vector<int>& labels);

// The inner node with the most children (kNoId when the tree has none).
Id widestCluster(const BuiltHlod& built);

} // namespace hlod::widgets
