// One HLOD build of a scene: the parameters that made it and what came out (cluster tree and
// baked proxies). Shared by the CLI (`hlod build`), the editor (preview, statistics) and the
// document (which owns the current build and reruns it when parameters change).
//
// Contract: buildHlod clusters then bakes; it reports progress with stages "cluster" and "bake"
// and throws hlod::Error (Cancelled when the progress' cancel flag is raised; nothing is kept).
#pragma once

#include "pipeline/cluster/Cluster.h"
#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/core/Progress.h"
#include "pipeline/proxy/ProxyBaker.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

struct HlodSettings {
    ClusterParams cluster;
    BakeParams bake;
};

struct HlodBuild {
    HlodSettings settings;
    ClusterTree tree;
    BakeResult bake;
    double clusterSeconds = 0.0;
    double bakeSeconds = 0.0;
};

HlodBuild buildHlod(const Scene& scene, const HlodSettings& settings,
                    const Progress& progress = {});

} // namespace hlod
