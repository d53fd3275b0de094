// Proxy baking for a whole cluster tree (thesis 5.3, "Hierarchical Proxy Mesh Processor"):
// every inner node gets a proxy made from its children's representations (their proxies, or
// the original meshes of leaf children), bottom-up, in parallel.
//
// Proxy economy (docs/architecture.md): a node keeps its proxy only when it pays for itself, proxy
// triangles <= proxyRatio x the triangles of what it replaces. A node whose proxy does not pay
// is dissolved: its parent is baked from the dissolved node's inputs instead (its children
// move up), so the parent is judged with its wider set of children. Locked nodes are never
// dissolved. Summed over the tree, each proxy is at most rho times the representations of its
// children and every representation has one parent, so all proxies together hold at most
// rho / (1 - rho) of the original triangles (rho = 0.5: at most 100 %). The root has nothing to
// hang its children from: when its proxy does not pay it keeps no proxy (hasProxy false) and
// is always refined. bakeProxies records the decisions (NodeBake::dissolved) on the input tree;
// compactDissolved (ProxyEconomy.h) removes the dissolved nodes.
//
// Frames: a node's proxy is baked in the node's own frame (the position and rotation of its
// first input, every input placed by its linear part and offset relative to that frame, both
// quantised, BakeFrame.h) and keyed by that content, so clusters that are rigid copies of each
// other (a plant built from repeated modules, translated and turned) bake to bit-identical
// proxies: the second is a cache hit, also within one run without a disk cache. The proxy is
// placed in the world by NodeBake::frame (proxy.origin is frame.origin). Within one node, the
// decimate method simplifies inputs that are turned copies of each other once, in their own
// frame, and places the result (CopyParts.h; made once per run for every node that has them).
//
// Scheduling: a dependency-counting task graph on TBB (a node's task is spawned by the last of
// its inner children to finish, leaves are ready at once), run in a task_arena of
// `threads` workers; nested OpenVDB kernels share the same arena.
// Determinism: a node's proxy is a pure function of its inputs and parameters, its inputs are
// gathered in child order, so the result is bit-identical for any thread count and any
// cache state (a cached proxy is the exact bytes of a baked one).
// Cache: see ProxyCache.h; a node's key is a Merkle hash of the method, its parameters, the
// node's budget and the keys and offsets of its inputs, computed when the node is ready (its
// inputs depend on the decisions below it). A node whose key is in the cache, or was baked
// earlier in the same run, is reused without being baked.
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
#include "pipeline/proxy/BakeFrame.h"
#include "pipeline/proxy/DecimateProxy.h"
#include "pipeline/proxy/ErrorBudget.h"
#include "pipeline/proxy/ProxyLook.h"
#include "pipeline/proxy/ProxyMesh.h"
#include "pipeline/proxy/RemeshProxy.h"
#include "pipeline/proxy/atlas/BakeAtlas.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

struct BakeParams {
    ProxyMethod method = ProxyMethod::Decimate;
    ScreenParams screen;
    int threads = 0;                // worker threads; 0 = all hardware threads
    std::filesystem::path cacheDir; // empty = no disk cache
    DecimateOptions decimate;       // tuning, part of the cache key
    RemeshOptions remesh;           // tuning, part of the cache key
    // rho of the proxy economy: a proxy is kept when its triangles are at most this fraction of
    // its inputs' triangles; >= 1 keeps every proxy (the tree as clustered). Not part of the
    // cache key (the decision is made on the cached proxy).
    double proxyRatio = 0.35;
    // Base-colour atlases of kept proxies (AtlasStep.h); off: vertex colours only. Part of the
    // cache key when on.
    AtlasOptions atlas;
    // Farm shards (BakePlan.h): the nodes being made at once take at most a sixteenth of the
    // run's triangles together (a larger node is made alone), so that a shard's peak memory
    // follows its slice; other builds make as many at once as there are threads. Never changes
    // a proxy; not part of the cache key.
    bool boundWorkingSets = false;
    std::size_t inFlightFloor = 32768; // the bound never goes below this many input triangles
};

struct NodeBake {
    double diameter = 0.0;       // metres (ErrorBudget.h nodeDiameter)
    double errorBudget = 0.0;    // e = t * diameter / S, metres
    double switchDistance = 0.0; // metres
    std::uint64_t key = 0;       // cache key (leaves: key of their mesh and material)
    // Inner nodes: the frame the proxy lives in (world = frame.matrix() * proxy position);
    // leaves: their instance's translation and frameRotation of its linear part.
    RigidFrame frame;
    bool reused = false;            // inner nodes: taken from the cache (or this run)
    bool dissolved = false;         // inner nodes: the proxy did not pay (see above)
    bool hasProxy = true;           // inner nodes: false for a root whose proxy did not pay
    std::size_t inputTriangles = 0; // inner nodes: the representations it was baked from
    double cpuSeconds = 0.0;        // inner nodes baked here: the baking thread's CPU time
                                    // (the shard plan's measured cost, BakeCosts.h)
    ProxyMesh proxy;                // inner nodes with a proxy only
};

struct BakeResult {
    std::vector<NodeBake> nodes; // parallel to ClusterTree::nodes
    std::size_t innerNodes = 0;
    std::size_t baked = 0;
    std::size_t reused = 0;
    std::size_t dissolved = 0;      // inner nodes dissolved by the proxy economy
    std::size_t damaged = 0;        // cache files found damaged (never trusted: baked again)
    std::size_t inputTriangles = 0; // sum over every baked node (the bake's work)
    std::size_t proxyTriangles = 0; // sum over the kept proxies
    std::size_t proxyVertices = 0;
    double seconds = 0.0;
    double cpuSeconds = 0.0; // CPU time of the whole process during the bake (all threads)
    // The most input triangles of nodes being made at once (BakeParams::boundWorkingSets).
    std::size_t peakInFlightTriangles = 0;
};

// Bakes every inner node of `tree` and makes the economy's decisions; result.nodes is parallel
// to tree.nodes (dissolved nodes keep no proxy). See ProxyEconomy.h for the tree without them.
BakeResult bakeProxies(const Scene& scene, const ClusterTree& tree, const BakeParams& params,
                       const Progress& progress = {});

// Only the subtrees under `roots` (distinct inner nodes, none below another): what one shard
// of a distributed bake does (ShardPlan.h). Every node gets the key, proxy and economy decision
// bakeProxies gives it on the whole tree (a node's bake only reads its own subtree), and the
// proxies go to the cache folder as there. result.nodes is parallel to tree.nodes, filled for
// the subtrees' nodes only (no compaction). The scene needs only the meshes and textures of
// the subtrees' leaves (sliceScene): the others are never read.
// Failure: as bakeProxies; Error(InvalidArgument) for a root that is a leaf, out of range, a
// duplicate or below another root.
BakeResult bakeSubtrees(const Scene& scene, const ClusterTree& tree, const std::vector<Id>& roots,
                        const BakeParams& params, const Progress& progress = {});

// The nodes below the cut of a distributed bake as its shards decided them (BakePlan.h).
struct BakeBelow {
    // Per tree node: decided by a shard; its NodeBake (passed to bakeAbove) holds its key,
    // frame, budget and decision, and a kept one that is an input of a node above, its proxy.
    std::vector<char> given;
    std::vector<std::vector<Id>> standIns; // per node: a given dissolved node's inputs
    // Per node: the sums over its originals (ProxyLook.h), for the given subtree roots and the
    // given kept nodes that are inputs of a node above.
    std::vector<ProxyLookSums> looks;
};

// The final step of a distributed bake: bakes the inner nodes that are not given (the nodes
// above the cut: no given node may have one below it) from `nodes`, whose given entries stand
// for everything below the cut, so no mesh below the cut is read. Each node baked gets the key,
// proxy and decision bakeProxies gives it. result.nodes: `nodes` with the nodes above filled;
// the counts are this call's (the nodes above only).
BakeResult bakeAbove(const Scene& scene, const ClusterTree& tree, std::vector<NodeBake> nodes,
                     const BakeBelow& below, const BakeParams& params,
                     const Progress& progress = {});

// Per node (parallel to tree.nodes, 0 for nodes not under the root), the key bakeProxies gives
// it when no node below it is dissolved. Equal keys mark subtrees that bake to the same proxies
// (rigid copies of a cluster): a shard plan keeps them in one shard, where only the first is
// baked. Reads the meshes of every leaf.
std::vector<std::uint64_t> structuralKeys(const Scene& scene, const ClusterTree& tree,
                                          const BakeParams& params);

// A hash of everything in `params` the proxies and the economy's decisions depend on (method,
// tuning, screen parameters, rho, atlas options); not threads or the cache folder.
std::uint64_t bakeParamsKey(const BakeParams& params);

// One node's proxy from its already aggregated input (the per-node step of bakeProxies).
// For `remesh` this is the smaller of the shell and the `decimate` proxy (both within the
// budget), and just the latter when it is tiny (RemeshOptions::decimateBelowTriangles).
ProxyMesh makeProxy(ProxyMesh input, double errorBudget, const BakeParams& params,
                    const Progress& progress = {});

} // namespace hlod
