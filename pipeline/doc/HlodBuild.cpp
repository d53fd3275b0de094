#include "pipeline/doc/HlodBuild.h"

#include <chrono>

namespace hlod {

HlodBuild buildHlod(const Scene& scene, const HlodSettings& settings, const Progress& progress) {
    using Clock = std::chrono::steady_clock;
    HlodBuild out;
    out.settings = settings;
    auto t = Clock::now();
    out.tree = buildClusterTree(scene, settings.cluster, progress);
    out.clusterSeconds = std::chrono::duration<double>(Clock::now() - t).count();
    t = Clock::now();
    out.bake = bakeProxies(scene, out.tree, settings.bake, progress);
    out.bakeSeconds = std::chrono::duration<double>(Clock::now() - t).count();
    return out;
}

} // namespace hlod
