// The proxy economy's tree (docs/architecture.md): after bakeProxies has decided which
// proxies pay for themselves, the dissolved nodes are removed and their children hang from
// their nearest kept ancestor (DissolveNodes.h), so every inner node of the result is drawn
// through its own proxy (or, for a root without a proxy, always refined).
//
// Contract: `tree` and `bake` must belong together (bake.nodes parallel to tree.nodes); both
// are rewritten in place, bake.nodes staying parallel to the new tree. Without dissolved nodes
// nothing changes.
#pragma once

#include <vector>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/proxy/ProxyBaker.h"

namespace hlod {

// Returns per old node its new id (kNoId when removed); empty when nothing was dissolved (ids
// unchanged).
std::vector<Id> compactDissolved(ClusterTree& tree, BakeResult& bake);

// bakeProxies followed by compactDissolved: `tree` becomes the tree the proxies belong to.
BakeResult bakeEconomised(const Scene& scene, ClusterTree& tree, const BakeParams& params,
                          const Progress& progress = {});

// Whether the root keeps no proxy (SelectionTree's refineRootAlways, no tile content).
bool rootHasNoProxy(const ClusterTree& tree, const BakeResult& bake);

} // namespace hlod
