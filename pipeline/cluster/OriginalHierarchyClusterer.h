// Baseline: the scene's own node hierarchy as the HLOD tree, converted so that only leaves
// reference meshes (thesis section 5.1, figure 5.2).
//
// Conversion: every scene node becomes a cluster node whose children are, in this order, a
// leaf for each mesh instance attached to the scene node itself (ascending instance id; in
// figure 5.2 the mesh of inner node A becomes a leaf beside A's children) and the cluster nodes
// of its child scene nodes (scene order). Scene nodes with no instance below them make no node,
// and a node left with a single entry collapses into that entry, so chains of transform-only
// nodes disappear and no node has a single child. The scene's grouping is kept as is: the
// maxChildren cap does not apply.
// Constraints: the units given may be a subset of the leaves (a locked group clustered on its
// own, or the scene without its excluded instances): the hierarchy is restricted to them. Units
// that are not leaves (roots of locked groups) join the root.
#pragma once

#include <vector>

#include "pipeline/cluster/TreeBuilder.h"
#include "pipeline/core/Progress.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

// UnitMerger (ClusterDriver.h) for the original hierarchy of `scene`; leaf units must be the
// builder's leaves of `scene` (node id = instance id).
Id mergeOriginalHierarchy(const Scene& scene, TreeBuilder& builder, std::vector<Id> units,
                          int maxChildren, const Progress& progress = {});

} // namespace hlod
