// Baseline: loose octree clustering (thesis section 3.2.2; loose cells after T. Ulrich, "Loose
// Octrees", Game Programming Gems, 2000).
//
// The root cell is the cube around all units. A cell holding more than maxChildren units is
// split into eight octants; a unit moves down into the octant that holds its box centre when
// its box fits in that octant's loose bounds (the octant grown by half its size on every side,
// looseness 2), which is the thesis' "allow cells to grow a little" fix for parts on cell
// boundaries: a part moves down as long as it is no larger than the octant. Units that fit no
// octant stay at the cell. Splitting stops when a cell holds at most maxChildren units, when no
// unit moves down, or at depth 32.
// Tree: a cell becomes one node whose children are its non-empty octants' nodes (octant order)
// and its remaining units; a cell with a single entry collapses into that entry (no
// single-child nodes); empty octants make no node. So a node may have more than maxChildren
// children when many parts are larger than the octants (maxChildren is the split threshold,
// not a hard cap here). Units are placed by their padded clustering boxes (CostModel.h).
// Deterministic: no parallelism, fixed octant order.
#pragma once

#include <vector>

#include "pipeline/cluster/TreeBuilder.h"
#include "pipeline/core/Progress.h"

namespace hlod {

// UnitMerger (ClusterDriver.h) for the loose octree. Checks the cancel flag.
Id mergeOctree(TreeBuilder& builder, std::vector<Id> units, int maxChildren,
               const Progress& progress = {});

} // namespace hlod
