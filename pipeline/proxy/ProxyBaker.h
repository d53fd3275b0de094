// Proxy baking for a whole cluster tree (thesis 5.3, "Hierarchical Proxy Mesh Processor"):
// every inner node gets a proxy made from its children's proxies (original meshes for leaf
// children), bottom-up, in parallel.
//
// Scheduling: a dependency-counting task graph on TBB (a node's task is spawned by the last of
// its inner children to finish, leaves are ready at once), run in a task_arena of
// `threads` workers; nested OpenVDB kernels share the same arena.
// Determinism: a node's proxy is a pure function of its inputs and parameters, its inputs are
// gathered in child order, so the result is bit-identical for any thread count and any
// cache state (a cached proxy is the exact bytes of a baked one).
// Cache: see ProxyCache.h; keys are computed up front (Merkle hash over the tree), a node whose
// key is in the cache is reused without being baked.
// Progress: stage "bake", done/total = inner nodes finished/all, detail
// "baked N, reused M, T proxy triangles"; called from worker threads.
// Cancellation: each node checks the flag before it starts and the remesher checks it while
// voxelising, so the call returns within the time of one decimation (well under a second for
// the scenes we bake); it throws Error(Cancelled). Proxies finished before that are in the
// cache (complete files only), nothing else is written.
// Failure: Error(InvalidArgument) for bad parameters, Error(Io) when the cache folder cannot
// be written.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/core/Progress.h"
#include "pipeline/proxy/DecimateProxy.h"
#include "pipeline/proxy/ErrorBudget.h"
#include "pipeline/proxy/ProxyMesh.h"
#include "pipeline/proxy/RemeshProxy.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

struct BakeParams {
    ProxyMethod method = ProxyMethod::Decimate;
    ScreenParams screen;
    int threads = 0;                // worker threads; 0 = all hardware threads
    std::filesystem::path cacheDir; // empty = no disk cache
    DecimateOptions decimate;       // tuning, part of the cache key
    RemeshOptions remesh;           // tuning, part of the cache key
};

struct NodeBake {
    double diameter = 0.0;          // metres (ErrorBudget.h nodeDiameter)
    double errorBudget = 0.0;       // e = t * diameter / S, metres
    double switchDistance = 0.0;    // metres
    std::uint64_t key = 0;          // cache key (leaves: key of their instance)
    bool reused = false;            // inner nodes: taken from the cache
    std::size_t inputTriangles = 0; // inner nodes: aggregated children
    ProxyMesh proxy;                // inner nodes only
};

struct BakeResult {
    std::vector<NodeBake> nodes; // parallel to ClusterTree::nodes
    std::size_t innerNodes = 0;
    std::size_t baked = 0;
    std::size_t reused = 0;
    std::size_t inputTriangles = 0; // sum over inner nodes
    std::size_t proxyTriangles = 0; // sum over inner nodes
    std::size_t proxyVertices = 0;
    double seconds = 0.0;
};

BakeResult bakeProxies(const Scene& scene, const ClusterTree& tree, const BakeParams& params,
                       const Progress& progress = {});

// The cache key of every node (what bakeProxies uses), without baking.
std::vector<std::uint64_t> computeBakeKeys(const Scene& scene, const ClusterTree& tree,
                                           const BakeParams& params);

// One node's proxy from its already aggregated input (the per-node step of bakeProxies).
// For `remesh` this is the smaller of the shell and the `decimate` proxy (both within the
// budget), and just the latter when it is tiny (RemeshOptions::decimateBelowTriangles).
ProxyMesh makeProxy(ProxyMesh input, double errorBudget, const BakeParams& params,
                    const Progress& progress = {});

} // namespace hlod
