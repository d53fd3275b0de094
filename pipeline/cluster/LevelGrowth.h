// Coarsening a cluster tree so that every level is at least `minGrowth` times wider than the
// level below (issue "every proxy pays for itself": levels whose diameters grow about 2x
// each, as meshoptimizer's clusterlod halves per level).
//
// Why: bottom-up merging (thesis 4.3) pairs clusters, so a parent is only 1.2-1.5x wider than
// its children. Its error budget (one pixel at the switch) grows as much, and a proxy that
// may deviate 1.4x more than its children's can drop little of them; most such levels
// re-store what is below them. With levels about twice as wide, each proxy's budget doubles
// over its children's, which is what lets it pay (ProxyBaker.h).
//
// Rule (top-down, deterministic): an inner node whose nearest kept ancestor is less than
// `minGrowth` times its diameter is dissolved (DissolveNodes.h: its children hang from that
// ancestor, which then judges them the same way). The root, leaves and locked (hand-edited)
// clusters are never dissolved. Diameter: the bounding sphere's, else the box diagonal.
// minGrowth <= 1 returns the tree unchanged.
#pragma once

#include "pipeline/cluster/ClusterTree.h"

namespace hlod {

ClusterTree coarsenLevels(const ClusterTree& tree, double minGrowth);

} // namespace hlod
