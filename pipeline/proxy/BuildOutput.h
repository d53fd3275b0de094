// The output folder of `hlod build` until the package format of the export issue exists:
//   DIR/tree.json            the HLOD tree: per node box, sphere, level, children, leaf
//                            instance, proxy file, geometric error (the proxy budget, metres),
//                            screen size and switching distance; the parameters and the
//                            statistics of the build (BakeStats.h)
//   DIR/proxies/node_<id>.glb  one GLB per inner node with a non-empty proxy (GlbWriter.h),
//                            positions relative to the node translation
// Atomic: everything is written into a sibling temporary folder that then replaces DIR, so a
// failed or cancelled build leaves either the previous output or nothing. An existing DIR is
// only replaced when it is empty or holds a previous build (a tree.json with format
// "hlod-build"); anything else is refused with Error(InvalidArgument).
// Failure: Error(Io) naming the path that could not be written.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/proxy/BakeStats.h"
#include "pipeline/proxy/ProxyBaker.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

struct BuildInfo {
    std::vector<std::string> inputs;
    BakeParams bake;
    std::vector<GeometryStats> statistics; // rows of the thesis-style table
    ProxyShare share;
    std::vector<LevelRow> levels;     // per-level table (BakeStats.h levelTable)
    nlohmann::json clusterParameters; // as the caller names them (volume, k, ...)
};

// The tree.json document (exposed for tests and the GUI).
nlohmann::json buildTreeJson(const Scene& scene, const ClusterTree& tree, const BakeResult& bake,
                             const BuildInfo& info, bool withNodes = true);

// Writes DIR atomically (see above); returns the total bytes written.
std::uintmax_t writeBuildFolder(const std::filesystem::path& dir, const Scene& scene,
                                const ClusterTree& tree, const BakeResult& bake,
                                const BuildInfo& info);

} // namespace hlod
