// One HLOD build of a scene: the parameters that made it and what came out (cluster tree and
// baked proxies). Shared by the CLI (`hlod build`), the editor (preview, statistics) and the
// document (which owns the current build and reruns it when parameters change).
//
// Contract: buildHlod clusters (under the hand-edit constraints of `settings.cluster`), dissolves
// the split clusters (`settings.dissolved`, exactly as the pipeline graph's Cluster node does:
// splitClusters in pipeline/graph/SplitClusters.h), then bakes. It reports progress with stages
// "cluster" and "bake" and throws hlod::Error (Cancelled when the progress' cancel flag is
// raised; nothing is kept).
// Incremental rebuild: given the previous build of the same scene whose clustering settings are
// the same (sameClustering), its tree is reused and only the bake runs (which itself reuses every
// unchanged proxy from the disk cache): a change of a bake parameter reruns only the bake.
#pragma once

#include <vector>

#include "pipeline/cluster/Cluster.h"
#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/core/Progress.h"
#include "pipeline/graph/HandEdits.h"
#include "pipeline/graph/Parameters.h"
#include "pipeline/proxy/ProxyBaker.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

struct HlodSettings {
    ClusterParams cluster; // with the locked groups and exclusions of the hand edits
    BakeParams bake;
    std::vector<InstanceSet> dissolved = {}; // split clusters (HandEdits::dissolved)
};

// Whether two settings give the same cluster tree (cluster parameters and every hand edit) /
// the same proxies for one tree (every bake parameter).
bool sameClustering(const HlodSettings& a, const HlodSettings& b);
bool sameBaking(const HlodSettings& a, const HlodSettings& b);

// The settings of the Cluster and Bake parameter values (pipeline/graph/Parameters.h), without
// hand edits.
HlodSettings hlodSettingsFrom(const ParamValues& clusterValues, const ParamValues& bakeValues);

struct HlodBuild {
    HlodSettings settings;
    ClusterTree clustered; // as clustered (hand edits applied), before the proxy economy
    ClusterTree tree;      // what the proxies belong to: `clustered` without dissolved nodes
    BakeResult bake;       // parallel to `tree`
    double clusterSeconds = 0.0;
    double bakeSeconds = 0.0;
    bool treeReused = false; // the tree came from the previous build (nothing reclustered)
};

// `previous`: the last build of the same `scene` (or null); used only when sameClustering.
HlodBuild buildHlod(const Scene& scene, const HlodSettings& settings, const Progress& progress = {},
                    const HlodBuild* previous = nullptr);

} // namespace hlod
