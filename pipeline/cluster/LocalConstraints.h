// The hand-edit constraints (ClusterParams::lockedGroups, ::excluded) applied to the automatic
// tree by local surgery, so that an edit changes only the clusters it names and their
// ancestors (issue 20: merging the only two children of a cluster used to recluster the whole
// scene, because the locked group entered the level merging as one unit and moved every
// level's cost budget).
//
// The tree is a pure function of the scene, the parameters and the constraints: the automatic
// tree (no constraints) is built first, then, in this order:
// 1. Excluded instances: each leaf leaves its parent. At the end the root is a new node whose
//    children are the excluded leaves and the rest of the tree (the rest alone, or nothing,
//    when it is empty).
// 2. Locked groups, in the order given (they are disjoint): the group's fragments are the
//    largest subtrees of the current tree that hold only members of the group.
//    - One fragment: the tree already has the group as a cluster; it is marked locked.
//    - Exactly one fragment is a cluster, the others single meshes: the meshes join that
//      cluster as extra children ("move these meshes into that cluster"); it is marked locked.
//    - Otherwise (several clusters, or only meshes): a new locked cluster whose children are the
//      fragments hangs from their lowest common ancestor ("merge these clusters").
//    A group of one instance is that leaf, marked locked.
// 3. Clean-up: a cluster left without children disappears; one left with a single child is
//    replaced by that child (a cluster of one is no cluster). Locked clusters never shrink.
// Changed: the clusters that gained or lost children and their ancestors; their bounds, fill,
// cost and level are recomputed (fill and cost fold CostModel::merge over the children in id
// order, as TreeBuilder::addFoldedNode does). Unchanged: every other cluster, node for node
// (children, bounds, fill, cost, level). Node ids are renumbered so children still come before
// parents; leaves keep their ids. maxChildren is not enforced on changed clusters (a hand edit
// wins, as with splits).
// The constraints must have passed validateConstraints (ClusterDriver.h).
#pragma once

#include "pipeline/cluster/Cluster.h"
#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/cluster/CostModel.h"

namespace hlod {

// `tree` is the automatic tree built with `model` and leaves padded to `minExtent`
// (ClusterDriver.h); returns it with the constraints of `params` applied.
ClusterTree applyLocalConstraints(ClusterTree tree, const ClusterParams& params,
                                  const CostModel& model, double minExtent);

} // namespace hlod
