// Entry point of clustering: builds a ClusterTree for a scene with one of the clusterers.
//
// Failure: throws Error(InvalidArgument) for parameters out of range, Error(Cancelled) when the
// progress cancel flag is raised. Deterministic: same scene + params -> same tree.
#pragma once

#include <vector>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/core/Progress.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

inline constexpr double kDefaultLevelGrowth = 2.0;

struct ClusterParams {
    VolumeType volume = VolumeType::Sphere;
    double k = 1.0;      // AABB proportion constraint exponent (thesis evaluates 0, 1, 2)
    int maxChildren = 8; // cap on children per merge (>= 2); levelGrowth may widen nodes later
    // Sphere and AABB trees: levels thinner than this are dissolved, so that a parent is at
    // least this many times wider than its inner children (LevelGrowth.h), before the hand
    // edits apply; 1 keeps the thesis' merges (the library default; the declared parameter,
    // which the CLI, editor and projects use, defaults to kDefaultLevelGrowth).
    double levelGrowth = 1.0;
    // Hand-edit constraints: each group is a set of instance ids kept whole as one locked
    // subtree; excluded instances become their own leaf directly under the root. Both change
    // the automatic tree only locally (LocalConstraints.h).
    std::vector<std::vector<Id>> lockedGroups;
    std::vector<Id> excluded;
};

ClusterTree buildClusterTree(const Scene& scene, const ClusterParams& params,
                             const Progress& progress = {});

} // namespace hlod
