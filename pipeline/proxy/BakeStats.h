// Statistics in the shape of the thesis' tables 6.2-6.6 (Triangles, Vertices, Meshes, Space)
// for the original scene, the DLOD chain baseline and an HLOD configuration.
//
// Conventions (so rows are comparable):
// - counts are per mesh instance (a mesh placed twice counts twice), as SceneStats::triangles;
// - an HLOD configuration holds the original meshes (its leaves) plus one proxy per inner node,
//   so its rows are original + proxies, like the thesis' tables;
// - space is geometry bytes as the GLB writer stores them (float positions and normals, float
//   uvs when present, 8-bit colours when present, 16- or 32-bit indices), without JSON or
//   textures, so it measures geometry, not file-format overhead.
// Proxy share, three ways to say "how big are the proxies": all proxies together relative to
// the original triangle count (the thesis' measure: HLOD minus Original over Original, 21-90%
// in its tables 6.2-6.6), the root proxy alone relative to the original, and what a proxy
// costs relative to the originals it replaces when drawn (sum over inner nodes of proxy
// triangles over the sum of their subtrees' original triangles).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/proxy/DlodChain.h"
#include "pipeline/proxy/ProxyBaker.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

struct GeometryStats {
    std::string version; // "Original", "DLOD chain", "HLOD, sphere", ...
    std::size_t triangles = 0;
    std::size_t vertices = 0;
    std::size_t meshes = 0;
    std::size_t bytes = 0;
};

struct ProxyShare {
    double allProxies = 0.0; // sum of proxy triangles / original triangles
    double rootProxy = 0.0;  // root proxy triangles / original triangles
    double replaced = 0.0;   // sum proxy triangles / sum of the subtrees' original triangles
};

std::size_t meshBytes(std::size_t vertices, std::size_t indices, bool uvs, bool colors);
std::size_t meshBytes(const Mesh& mesh);
std::size_t meshBytes(const ProxyMesh& mesh);

// Triangles, vertices and geometry bytes (meshBytes) of one mesh or proxy.
struct MeshSize {
    std::size_t triangles = 0;
    std::size_t vertices = 0;
    std::size_t bytes = 0;
};

// What the statistics read of the geometry, without the geometry: per scene mesh, and per tree
// node its proxy (zero for leaves and nodes without one). A distributed bake's final step
// (BakePlan.h) has the sizes, not the meshes.
struct SizeTable {
    std::vector<MeshSize> meshes;  // parallel to Scene::meshes
    std::vector<MeshSize> proxies; // parallel to BakeResult::nodes
};
std::vector<MeshSize> meshSizes(const Scene& scene);
SizeTable sizeTable(const Scene& scene, const BakeResult& bake);

GeometryStats originalStats(const Scene& scene);
GeometryStats dlodStats(const DlodSummary& summary);
GeometryStats hlodStats(const Scene& scene, const ClusterTree& tree, const BakeResult& bake,
                        const std::string& version);
ProxyShare proxyShare(const Scene& scene, const ClusterTree& tree, const BakeResult& bake);
// The same from sizes (the scene's instances and the bake's totals are read, not its meshes).
GeometryStats originalStats(const Scene& scene, const SizeTable& sizes);
GeometryStats hlodStats(const Scene& scene, const ClusterTree& tree, const SizeTable& sizes,
                        const std::string& version);
ProxyShare proxyShare(const Scene& scene, const ClusterTree& tree, const BakeResult& bake,
                      const SizeTable& sizes);

// One row of the per-level table of a built HLOD (levels as ClusterNode::level: leaves 0, a
// parent one above its highest child). Level 0 holds the leaves: the original meshes, whose
// share is 1. Inner levels: the proxies of that level, their error budgets (metres), and their
// triangles as a share of the original scene's triangles.
struct LevelRow {
    int level = 0;
    std::size_t nodes = 0;
    double meanChildren = 0.0;
    double budgetMin = 0.0, budgetMax = 0.0;
    std::size_t triangles = 0; // proxy triangles (level 0: original triangles)
    double share = 0.0;        // triangles / original triangles
};

std::vector<LevelRow> levelTable(const Scene& scene, const ClusterTree& tree,
                                 const BakeResult& bake);
std::vector<LevelRow> levelTable(const Scene& scene, const ClusterTree& tree,
                                 const BakeResult& bake, const SizeTable& sizes);

// "HLOD, sphere", "HLOD, AABB k=1", ... as in the thesis' tables.
std::string hlodVersionName(const ClusterTree& tree);

} // namespace hlod
