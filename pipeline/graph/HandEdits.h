// Hand edits of a cluster tree, kept as constraints on clustering so they survive a rerun with
// other parameters (issue #7: merge, split, move, lock, exclude).
//
// Identity across reruns: a cluster is identified by its leaf set, the sorted instance ids of
// the scene instances below it (an InstanceSet). Instance ids are stable for a given scene (the
// same source files read with the same import options), node ids of a ClusterTree are not, so
// every edit is keyed by instance sets and never by node ids.
//
// The constraints (all instance sets sorted, without duplicates):
// - locked: disjoint groups; each is clustered on its own and kept whole as one subtree whose
//   root is marked locked (ClusterParams::lockedGroups). Merge, move and lock produce these.
// - excluded: instances that are never merged; each is a leaf directly under the root
//   (ClusterParams::excluded).
// - dissolved: clusters that were split: when clustering produces a node with exactly this leaf
//   set, the node is removed and its children hang from its parent (splitClusters in
//   SplitClusters.h). A rerun that no longer forms that cluster leaves nothing to dissolve.
// An instance is in at most one locked group and never both locked and excluded; a dissolved
// set never equals a locked group. The edit operations (ClusterEdits.h) keep these rules.
#pragma once

#include <filesystem>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "pipeline/cluster/Cluster.h"
#include "pipeline/cluster/ClusterTree.h"

namespace hlod {

using InstanceSet = std::vector<Id>; // sorted, unique

struct HandEdits {
    std::vector<InstanceSet> locked; // sorted by first instance
    InstanceSet excluded;
    std::vector<InstanceSet> dissolved; // sorted lexicographically

    bool empty() const { return locked.empty() && excluded.empty() && dissolved.empty(); }
    bool operator==(const HandEdits&) const = default;
};

// Sorts and deduplicates a set (callers may pass ids in any order).
InstanceSet normalizedSet(InstanceSet ids);
// Brings every list into its canonical order (so equal edits serialize identically).
void normalize(HandEdits& edits);

// The leaf set of `node` in `tree`; the cluster a set names in `tree` (kNoId when no node has
// exactly that leaf set).
InstanceSet leafSet(const ClusterTree& tree, Id node);
Id findCluster(const ClusterTree& tree, const InstanceSet& set);

// Copies the locked groups and the exclusions into `params` (replacing what it held).
void applyConstraints(const HandEdits& edits, ClusterParams& params);

// Throws InvalidArgument when an instance id is >= instanceCount (a project made for another
// scene) or the rules above are broken.
void validateHandEdits(const HandEdits& edits, std::size_t instanceCount);

// {"locked": [[0, 5], ...], "excluded": [...], "dissolved": [[...]]}. Reading throws Malformed
// naming `file` (InvalidArgument when `file` is empty) for anything but arrays of ids.
nlohmann::json handEditsToJson(const HandEdits& edits);
HandEdits handEditsFromJson(const nlohmann::json& j, const std::filesystem::path& file = {});

} // namespace hlod
