// Cluster, dissolve split clusters, bake (contract in HlodBuild.h).
#include "pipeline/doc/HlodBuild.h"

#include <chrono>

#include "pipeline/graph/Parameters.h"
#include "pipeline/graph/SplitClusters.h"
#include "pipeline/proxy/ProxyEconomy.h"

namespace hlod {

bool sameClustering(const HlodSettings& a, const HlodSettings& b) {
    // paramsFrom covers every declared cluster parameter; the constraints are compared as data.
    return paramsFrom(a.cluster) == paramsFrom(b.cluster) &&
           a.cluster.lockedGroups == b.cluster.lockedGroups &&
           a.cluster.excluded == b.cluster.excluded && a.dissolved == b.dissolved;
}

bool sameBaking(const HlodSettings& a, const HlodSettings& b) {
    return paramsFrom(a.bake) == paramsFrom(b.bake);
}

HlodSettings hlodSettingsFrom(const ParamValues& clusterValues, const ParamValues& bakeValues) {
    return HlodSettings{clusterParamsFrom(clusterValues), bakeParamsFrom(bakeValues)};
}

HlodBuild buildHlod(const Scene& scene, const HlodSettings& settings, const Progress& progress,
                    const HlodBuild* previous) {
    using Clock = std::chrono::steady_clock;
    HlodBuild out;
    out.settings = settings;
    auto t = Clock::now();
    if (previous && sameClustering(previous->settings, settings)) {
        out.clustered = previous->clustered;
        out.treeReused = true;
    } else {
        out.clustered =
            splitClusters(buildClusterTree(scene, settings.cluster, progress), settings.dissolved);
    }
    out.clusterSeconds = std::chrono::duration<double>(Clock::now() - t).count();
    progress.throwIfCancelled();
    t = Clock::now();
    out.tree = out.clustered;
    out.bake = bakeEconomised(scene, out.tree, settings.bake, progress);
    out.bakeSeconds = std::chrono::duration<double>(Clock::now() - t).count();
    return out;
}

} // namespace hlod
