// What every clusterer shares: leaves from the instance bounds, the hand-edit constraints, and
// one merging strategy that joins units into a root: level merging for the sphere and AABB
// clusterers of thesis sections 3.2.3 and 4.1-4.2 (LevelMerger.h), the loose octree
// (OctreeClusterer.h) and the original hierarchy (OriginalHierarchyClusterer.h).
//
// Steps and the choices the thesis leaves open:
// - Leaves: node i is the leaf of scene instance i; its clustering volume is the instance's
//   Welzl sphere or world AABB (InstanceBounds.h), padded to the minimum extent
//   minExtent = 1e-4 x the scene's world-box diagonal (1e-6 m for a scene of one point), so a
//   flat part has a thin but non-zero box and a finite proportion ratio (CostModel.h).
// - Hand edits (ClusterParams::lockedGroups, ::excluded): the automatic tree over every
//   instance is built first, then the edits change it locally (LocalConstraints.h): a locked
//   group becomes (or already is) one locked subtree, an excluded instance hangs from a new root
//   beside the rest (the maxChildren cap does not apply to a changed node); every cluster the
//   edits do not touch stays as the automatic tree has it.
// - Node fields: sphere = clustering sphere (Sappa's pairwise EncapsulateSpheres, tracked for
//   every volume type), box = exact hull of the leaves' world boxes, fill and cost from the
//   cost model passed in.
// Failure: Error(InvalidArgument) for an instance id out of range, an instance in two locked
// groups, locked and excluded at once, an empty group, maxChildren < 2, or k < 0; Error
// (Cancelled) on cancel. Deterministic whatever the thread count.
#pragma once

#include <functional>
#include <vector>

#include "pipeline/cluster/Cluster.h"
#include "pipeline/cluster/TreeBuilder.h"

namespace hlod {

// A merging strategy: joins `units` of `builder` into one root and returns it (the unit itself
// when there is one), appending inner nodes (contract as mergeLevels in LevelMerger.h). Tests
// substitute the naive reference for mergeLevels.
using UnitMerger =
    std::function<Id(TreeBuilder&, std::vector<Id> units, int maxChildren, const Progress&)>;

// The tree of `scene` with leaves costed by `model` and joined by `merger`; the tree records
// params.volume and params.k.
ClusterTree buildConstrainedTree(const Scene& scene, const ClusterParams& params,
                                 const CostModel& model, const UnitMerger& merger,
                                 const Progress& progress = {});

// minExtent as described above, from the instance boxes.
double clusteringMinExtent(const std::vector<Aabb>& boxes);

// Throws Error(InvalidArgument) when the constraints of `params` do not fit a scene with
// `instanceCount` instances (shared by every clusterer).
void validateConstraints(const ClusterParams& params, std::size_t instanceCount);

} // namespace hlod
