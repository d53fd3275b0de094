// The cluster hand edits of issue #7 as pure functions from one HandEdits to the next (the
// document's commands store both, so undo restores the exact previous constraints).
// Clusters are named by their leaf sets (HandEdits.h); instances by their ids.
//
// What each edit means, as constraints that survive a rerun with other parameters:
// - mergeClusters: the union of the selected clusters becomes one locked group (members leave
//   any other locked group and the exclusions). Locks do not nest: a locked group inside the
//   union is absorbed.
// - splitCluster: the cluster is dissolved (its children hang from its parent); when it was
//   locked, the lock moves to its inner children, so each of them stays whole.
// - moveToCluster: the items (instances or clusters) join the target cluster, which becomes a
//   locked group holding target + items (a move must survive a rerun, and a lock is what keeps
//   a cluster's membership). When the target lies inside a locked group, the items join that
//   group. Items leave their previous locked groups (which shrink) and the exclusions.
// - lockCluster / unlockCluster: add / remove the cluster as a locked group.
// - excludeInstances / includeInstances: hang instances from the root / cluster them again.
// Failure: Error(InvalidArgument) with a sentence for the user when the edit does not apply
// (nothing to merge, unknown cluster, root or leaf split, target inside an item, already
// locked, not excluded, ...); the input is never modified.
#pragma once

#include <vector>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/graph/HandEdits.h"

namespace hlod {

HandEdits mergeClusters(const HandEdits& edits, const std::vector<InstanceSet>& clusters);
// `tree` is the current tree: it gives the cluster's children (and checks that it exists).
HandEdits splitCluster(const HandEdits& edits, const ClusterTree& tree, const InstanceSet& cluster);
HandEdits moveToCluster(const HandEdits& edits, const std::vector<InstanceSet>& items,
                        const InstanceSet& target);
HandEdits lockCluster(const HandEdits& edits, const InstanceSet& cluster);
HandEdits unlockCluster(const HandEdits& edits, const InstanceSet& cluster);
HandEdits excludeInstances(const HandEdits& edits, const InstanceSet& instances);
HandEdits includeInstances(const HandEdits& edits, const InstanceSet& instances);

} // namespace hlod
