// Bottom-up parallel proxy baking with a dependency-counting TBB task graph and a Merkle-keyed
// content cache (thesis 5.3's postfix traversal, parallel), see ProxyBaker.h.
#include "pipeline/proxy/ProxyBaker.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <ctime>
#include <deque>
#include <limits>
#include <memory>

#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <future>
#include <mutex>
#include <unordered_map>

#include "pipeline/core/Error.h"
#include "pipeline/proxy/Aggregate.h"
#include "pipeline/proxy/AtlasStep.h"
#include "pipeline/proxy/BakeFrame.h"
#include "pipeline/proxy/ContentHash.h"
#include "pipeline/proxy/CopyParts.h"
#include "pipeline/proxy/ProxyCache.h"
#include "pipeline/proxy/ProxyFinish.h"
#include "pipeline/proxy/ProxyLook.h"
#include "pipeline/proxy/SloppyProxy.h"
#include "pipeline/scene/AppendPlaced.h"

namespace hlod {

namespace {

// Bumped whenever a change of the proxy code changes its output, so stale caches miss.
constexpr std::uint64_t kBakeFormatVersion = 13;

// Input triangles of the bakes in flight together when BakeParams::boundWorkingSets
// (BakeRun::inFlightCap): a share of the triangles the run bakes, so that a farm shard's working
// sets shrink with its slice (engine tiled 100x, shard of 0.98 M triangles alone: 198 -> 185 MB
// peak, same wall time), and at least BakeParams::inFlightFloor, so that a small shard's bakes
// stay parallel.
constexpr std::size_t kInFlightShare = 16;

// CPU time of the calling thread (a node's measured cost, NodeBake::cpuSeconds).
double threadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Children before parents, only nodes in the subtrees of `roots` (the root's: the whole tree),
// without the `skip` ones and what lies below them.
std::vector<Id> postOrder(const ClusterTree& tree, const std::vector<Id>& roots,
                          const std::vector<char>* skip = nullptr) {
    std::vector<Id> order;
    std::vector<std::pair<Id, bool>> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it)
        stack.push_back({*it, false});
    while (!stack.empty()) {
        auto [id, expanded] = stack.back();
        stack.pop_back();
        if (expanded) {
            order.push_back(id);
            continue;
        }
        stack.push_back({id, true});
        const auto& children = tree.nodes[id].children;
        for (auto it = children.rbegin(); it != children.rend(); ++it)
            if (!skip || !(*skip)[*it]) stack.push_back({*it, false});
    }
    return order;
}

// Node boxes as the clusterer stored them; recomputed from the leaves for hand-built trees
// that left them empty.
std::vector<Aabb> nodeBoxes(const Scene& scene, const ClusterTree& tree,
                            const std::vector<Id>& order) {
    std::vector<Aabb> boxes(tree.nodes.size());
    for (Id id : order) {
        const ClusterNode& node = tree.nodes[id];
        if (!node.box.empty()) {
            boxes[id] = node.box;
        } else if (node.isLeaf()) {
            if (node.instance != kNoId) boxes[id] = scene.instanceBounds(node.instance);
        } else {
            for (Id c : node.children)
                boxes[id].expand(boxes[c]);
        }
    }
    return boxes;
}

void hashOptions(ContentHash& h, const BakeParams& params) {
    h.addValue(kBakeFormatVersion);
    h.addValue(static_cast<std::uint32_t>(params.method));
    switch (params.method) {
    case ProxyMethod::Decimate:
        h.addValue(params.decimate.weldFraction);
        break;
    case ProxyMethod::Remesh:
        h.addValue(params.remesh.voxelFraction);
        h.addValue(params.remesh.shellVoxels);
        h.addValue(params.remesh.keepVoxels);
        h.addValue(params.remesh.adaptivity);
        h.addValue(params.remesh.maxVoxelsPerAxis);
        h.addValue(params.remesh.decimateBelowTriangles);
        h.addValue(params.decimate.weldFraction);
        break;
    case ProxyMethod::Sloppy:
        break;
    }
    hashAtlasOptions(h, params.atlas);
}

// The head of a node's key; frameInputs adds its inputs' keys and quantised placements.
void hashNodeHead(ContentHash& h, const BakeParams& params, double errorBudget,
                  std::size_t inputs) {
    hashOptions(h, params);
    h.addValue(errorBudget);
    h.addValue(static_cast<std::uint64_t>(inputs));
}

std::uint64_t hashMesh(const Mesh& mesh) {
    ContentHash h(0x6d657368); // "mesh"
    h.addVector(mesh.positions);
    h.addVector(mesh.colors);
    h.addVector(mesh.indices);
    return h.digest();
}

void fillFrames(const Scene& scene, const ClusterTree& tree, const BakeParams& params,
                const std::vector<Id>& order, std::vector<NodeBake>& nodes) {
    const std::vector<Aabb> boxes = nodeBoxes(scene, tree, order);
    for (Id id : order) {
        NodeBake& nb = nodes[id];
        const ClusterNode& node = tree.nodes[id];
        nb.diameter = nodeDiameter(node);
        if (!(nb.diameter > 0.0)) nb.diameter = boxes[id].diagonal();
        nb.errorBudget = quantizedBudget(proxyErrorBudget(nb.diameter, params.screen));
        nb.switchDistance = switchDistance(nb.diameter, params.screen);
        if (node.isLeaf() && node.instance != kNoId) {
            const glm::dmat4& world = scene.instanceTransform(node.instance);
            nb.frame = {glm::dvec3(world[3]), frameRotation(glm::dmat3(world))};
        } else {
            // Replaced by the first placed input's frame when the node is framed (frameInputs).
            nb.frame = {boxes[id].empty() ? glm::dvec3(0.0) : boxes[id].center(), glm::dmat3(1.0)};
        }
        nb.proxy.origin = nb.frame.origin;
    }
}

// Leaf keys: what a leaf contributes in its own frame (mesh, material colour; its linear part
// and translation enter the parent's key as a quantised placement in the parent's frame, so a
// turned copy of a leaf has the same key).
void leafKeys(const Scene& scene, const ClusterTree& tree, const std::vector<Id>& order,
              const BakeParams& params, std::vector<NodeBake>& nodes) {
    std::vector<std::uint8_t> used(scene.meshes.size(), 0);
    for (Id id : order) {
        const ClusterNode& n = tree.nodes[id];
        if (n.isLeaf() && n.instance != kNoId) used[scene.instances[n.instance].mesh] = 1;
    }
    std::vector<std::uint64_t> meshHash(scene.meshes.size(), 0);
    tbb::parallel_for(std::size_t(0), scene.meshes.size(), [&](std::size_t m) {
        if (used[m]) meshHash[m] = hashMesh(scene.meshes[m]);
    });
    const std::vector<std::uint64_t> texHash =
        params.atlas.enabled ? textureHashes(scene) : std::vector<std::uint64_t>{};
    for (Id id : order) {
        const ClusterNode& node = tree.nodes[id];
        if (!node.isLeaf()) continue;
        ContentHash h(0x6c656166); // "leaf"
        if (node.instance != kNoId) {
            const MeshInstance& inst = scene.instances[node.instance];
            const Mesh& mesh = scene.meshes[inst.mesh];
            const Id mat = mesh.material < scene.materials.size() ? mesh.material : 0;
            h.addValue(meshHash[inst.mesh]);
            h.addValue(scene.materials[mat].effectiveColor());
            if (params.atlas.enabled) h.addValue(leafLookHash(scene, node.instance, texHash));
            // Sides and emission decide the proxy's (ProxyLook.h); hashed only when set, so
            // the keys of scenes without them are unchanged.
            const Material& m = scene.materials[mat];
            if (m.doubleSided || m.emits()) {
                h.addValue(static_cast<std::uint8_t>(m.doubleSided));
                h.addValue(m.effectiveEmissive());
                h.addValue(static_cast<std::uint8_t>(m.emissiveTexture == m.texture));
            }
        }
        nodes[id].key = h.digest();
    }
}

// Frames node `id` (BakeFrame.h): its frame becomes its first placed input's (a leaf with an
// instance, or an inner node, whose frame is already set), `placements[i]` input i's placement
// in it, and the node's key is hashed from the inputs' keys and placements in order. Empty
// leaves are placed at the frame's origin. The one place the bake (BakeRun::partsOf) and
// structuralKeys frame a node, so both give the same keys.
std::uint64_t frameInputs(const Scene& scene, const ClusterTree& tree, const BakeParams& params,
                          Id id, const std::vector<Id>& inputs, std::vector<NodeBake>& nodes,
                          std::vector<PartPlacement>& placements) {
    NodeBake& nb = nodes[id];
    // An input's world linear map and position: an instance's, or an inner node's frame.
    auto pose = [&](Id in, glm::dmat3& linear, glm::dvec3& at) {
        const ClusterNode& node = tree.nodes[in];
        if (node.isLeaf()) {
            if (node.instance == kNoId) return false;
            const glm::dmat4& world = scene.instanceTransform(node.instance);
            linear = glm::dmat3(world);
            at = glm::dvec3(world[3]);
            return true;
        }
        linear = nodes[in].frame.rotation;
        at = nodes[in].frame.origin;
        return true;
    };
    glm::dmat3 linear(1.0);
    glm::dvec3 at(0.0);
    for (Id in : inputs) {
        // The frame's origin and rotation are the first input's, so the placements of the
        // inputs of rigid copies are the same functions of the same relative poses.
        if (!pose(in, linear, at)) continue;
        nb.frame = nodes[in].frame;
        break;
    }
    nb.proxy.origin = nb.frame.origin;
    ContentHash h(0x6e6f6465); // "node"
    hashNodeHead(h, params, nb.errorBudget, inputs.size());
    placements.assign(inputs.size(), PartPlacement{});
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        if (pose(inputs[i], linear, at))
            placements[i] = placeInFrame(nb.frame, linear, at, nb.errorBudget);
        h.addValue(nodes[inputs[i]].key);
        h.addValue(placements[i].linear);
        h.addValue(placements[i].offset);
    }
    return h.digest();
}

} // namespace

ProxyMesh makeProxy(ProxyMesh input, double errorBudget, const BakeParams& params,
                    const Progress& progress) {
    switch (params.method) {
    case ProxyMethod::Decimate:
        return decimateProxy(std::move(input), errorBudget, params.decimate);
    case ProxyMethod::Remesh: {
        // Both meet the budget; the shell is kept only when it is not larger, so remeshing
        // never inflates a proxy (a closed shell of a few low-poly parts can be).
        ProxyMesh decimated = decimateProxy(input, errorBudget, params.decimate);
        const auto small =
            static_cast<std::size_t>(std::max(0, params.remesh.decimateBelowTriangles));
        if (decimated.triangleCount() <= small) return decimated;
        // The shell is measured against its input, which lies within its own bound of the
        // originals: it gets what is left of the budget.
        if (!(input.errorBound < errorBudget)) return decimated;
        ProxyMesh shell =
            remeshProxy(std::move(input), errorBudget - input.errorBound, progress, params.remesh);
        shell.errorBound = static_cast<float>(errorBudget);
        return shell.triangleCount() <= decimated.triangleCount() ? shell : decimated;
    }
    case ProxyMethod::Sloppy: {
        // No bound is promised (SloppyProxy.h); it claims the whole budget.
        ProxyMesh out = sloppyProxy(std::move(input), errorBudget);
        out.errorBound = static_cast<float>(errorBudget);
        return out;
    }
    }
    return input;
}

namespace {

struct BakeRun {
    const Scene& scene;
    const ClusterTree& tree;
    const BakeParams& params;
    const Progress& progress;
    ProxyCache cache;
    BakeResult& result;
    std::unique_ptr<std::atomic<int>[]> pending; // inner children not yet baked, per node
    // Per dissolved node: the nodes whose representations stand in for it (its inputs).
    std::vector<std::vector<Id>> standIns;
    std::mutex bakedMutex;
    // This run's proxies by key, finished or in the making: a node whose key another node is
    // baking waits for that proxy instead of baking a second copy.
    std::unordered_map<std::uint64_t, std::shared_future<ProxyMesh>> bakedByKey;
    // Decimated rigid copies by part key and budget (CopyParts.h), made once for every node.
    std::unordered_map<std::uint64_t, std::shared_future<ProxyMesh>> copiesByKey;
    std::atomic<std::size_t> done{0}, baked{0}, reused{0}, dissolved{0}, triangles{0}, damaged{0};
    tbb::task_group group;
    // Bakes in flight: a node is made while the input triangles of the nodes being made stay
    // within inFlightCap, or alone; otherwise it waits in `deferred` until a bake finishes. A
    // bake's working set grows with its input (the certified simplifier's grids and arrays:
    // tens of MB for a node of 100 k input triangles), so large nodes made at once raised a farm
    // shard's peak by a fifth for a few seconds (docs/benchmarks.md); in a shard the cap keeps
    // their sum to a share of its triangles, whatever the thread count (unbounded elsewhere).
    // Same output: the schedule never changes a proxy.
    std::size_t inFlightCap = 0, inFlight = 0, peakInFlight = 0;
    std::deque<std::pair<Id, std::size_t>> deferred; // node, its input triangles
    TextureMips mips;                 // source texture pyramids, shared by every node's atlas
    std::vector<ProxyLookSums> looks; // per node, over its originals (ProxyLook.h)

    // The representations node `id` is baked from: its children, a dissolved child replaced
    // by its own inputs (already expanded when that child was decided).
    std::vector<Id> inputsOf(Id id) const {
        std::vector<Id> inputs;
        for (Id c : tree.nodes[id].children) {
            if (result.nodes[c].dissolved)
                inputs.insert(inputs.end(), standIns[c].begin(), standIns[c].end());
            else
                inputs.push_back(c);
        }
        return inputs;
    }

    // The parts in the node's quantised frame, and the node's key from the same values.
    std::vector<AggregatePart> partsOf(Id id, const std::vector<Id>& inputs) {
        std::vector<PartPlacement> placements;
        result.nodes[id].key =
            frameInputs(scene, tree, params, id, inputs, result.nodes, placements);
        std::vector<AggregatePart> parts(inputs.size());
        for (std::size_t i = 0; i < inputs.size(); ++i) {
            const ClusterNode& node = tree.nodes[inputs[i]];
            if (node.isLeaf())
                parts[i].instance = node.instance;
            else
                parts[i].proxy = &result.nodes[inputs[i]].proxy;
            parts[i].linear = placements[i].linear;
            parts[i].offset = placements[i].offset;
        }
        return parts;
    }

    // The proxy made (or being made: waited for) under `key` in `made`; otherwise nullopt and
    // `owner` is set: the caller makes it and must fulfil it. Rethrows when the maker failed.
    std::optional<ProxyMesh>
    madeOrClaim(std::unordered_map<std::uint64_t, std::shared_future<ProxyMesh>>& made,
                std::uint64_t key, std::shared_ptr<std::promise<ProxyMesh>>& owner) {
        std::shared_future<ProxyMesh> known;
        {
            const std::lock_guard lock(bakedMutex);
            const auto it = made.find(key);
            if (it != made.end()) {
                known = it->second;
            } else {
                owner = std::make_shared<std::promise<ProxyMesh>>();
                made.emplace(key, owner->get_future().share());
            }
        }
        if (known.valid()) return known.get();
        return std::nullopt;
    }

    // This run's proxy with the same key (waiting while another node makes it), or the disk
    // cache's; otherwise `owner` is set and the caller makes it and must fulfil it. A damaged
    // cache file counts as a miss (and is replaced by the store after the bake).
    std::optional<ProxyMesh> reuse(std::uint64_t key,
                                   std::shared_ptr<std::promise<ProxyMesh>>& owner) {
        if (std::optional<ProxyMesh> known = madeOrClaim(bakedByKey, key, owner)) return known;
        bool bad = false;
        std::optional<ProxyMesh> found = cache.load(key, &bad);
        if (bad) ++damaged;
        return found;
    }

    // The decimated proxy of one input in its own frame within `budget` (CopyParts.h), made by
    // the first node that needs it; the others wait for it.
    ProxyMesh copyProxy(std::uint64_t partKey, const AggregatePart& part, double budget) {
        ContentHash h(0x636f7079); // "copy"
        hashOptions(h, params);
        h.addValue(budget);
        h.addValue(partKey);
        std::shared_ptr<std::promise<ProxyMesh>> owner;
        if (std::optional<ProxyMesh> known = madeOrClaim(copiesByKey, h.digest(), owner))
            return std::move(*known);
        try {
            AggregatePart own = part;
            own.offset = glm::dvec3(0.0);
            own.linear = glm::dmat3(1.0);
            ProxyMesh made =
                decimateProxy(aggregateParts(scene, std::span(&own, 1), glm::dvec3(0.0)),
                              budget * kPartBudgetScale, params.decimate);
            owner->set_value(made);
            return made;
        } catch (...) {
            owner->set_exception(std::current_exception());
            throw;
        }
    }

    // The node's new proxy (makeProxy over its aggregated inputs); decimated, inputs that are
    // rigid copies of each other are simplified once each and placed (CopyParts.h).
    ProxyMesh makeNodeProxy(const NodeBake& nb, const std::vector<Id>& inputs,
                            const std::vector<AggregatePart>& parts, const glm::dvec3& origin) {
        auto joint = [&](std::span<const AggregatePart> some) {
            return makeProxy(aggregateParts(scene, some, origin), nb.errorBudget, params, progress);
        };
        if (params.method != ProxyMethod::Decimate) return joint(parts);
        std::vector<std::uint64_t> keys(inputs.size());
        std::vector<glm::dmat3> linears(inputs.size());
        for (std::size_t i = 0; i < inputs.size(); ++i) {
            keys[i] = result.nodes[inputs[i]].key;
            linears[i] = parts[i].linear.value_or(glm::dmat3(0.0)); // unset: not rigid
        }
        const CopyGroups groups = groupRigidCopies(keys, linears);
        if (groups.copies.empty()) return joint(parts);
        ProxyMesh out;
        out.origin = origin;
        if (!groups.rest.empty()) {
            std::vector<AggregatePart> rest;
            for (std::size_t i : groups.rest)
                rest.push_back(parts[i]);
            appendPlaced(out, joint(rest), glm::dmat4(1.0));
        }
        for (const std::vector<std::size_t>& group : groups.copies) {
            progress.throwIfCancelled();
            const ProxyMesh copy =
                copyProxy(keys[group.front()], parts[group.front()], nb.errorBudget);
            for (std::size_t i : group) {
                glm::dmat4 placed(*parts[i].linear);
                placed[3] = glm::dvec4(*parts[i].offset, 1.0);
                appendPlaced(out, copy, placed);
            }
        }
        if (out.normals.size() != out.positions.size()) { // a part without: all recomputed
            out.normals.clear();
            finishProxy(out);
        }
        out.errorBound = static_cast<float>(nb.errorBudget);
        return out;
    }

    // The economy's decision (ProxyBaker.h), once the proxy is known.
    void decide(Id id, std::vector<Id>&& inputs) {
        NodeBake& nb = result.nodes[id];
        const ClusterNode& node = tree.nodes[id];
        const double limit = params.proxyRatio * static_cast<double>(nb.inputTriangles);
        if (node.locked || static_cast<double>(nb.proxy.triangleCount()) <= limit) {
            triangles += nb.proxy.triangleCount();
            return;
        }
        ++dissolved;
        if (id == tree.root) {
            nb.hasProxy = false; // nothing to hang the children from: refined always
        } else {
            nb.dissolved = true;
            standIns[id] = std::move(inputs);
        }
    }

    // Whether node `id` with `weight` input triangles may be made now (counted in flight);
    // otherwise it is deferred and started by release().
    bool admit(Id id, std::size_t weight) {
        const std::lock_guard lock(bakedMutex);
        if (inFlight != 0 && inFlight + weight > inFlightCap) {
            deferred.emplace_back(id, weight);
            return false;
        }
        inFlight += weight;
        peakInFlight = std::max(peakInFlight, inFlight);
        return true;
    }

    // A bake of `weight` input triangles finished: starts the deferred nodes that now fit.
    void release(std::size_t weight) {
        const std::lock_guard lock(bakedMutex);
        inFlight -= weight;
        while (!deferred.empty() &&
               (inFlight == 0 || inFlight + deferred.front().second <= inFlightCap)) {
            const auto [id, w] = deferred.front();
            deferred.pop_front();
            inFlight += w;
            peakInFlight = std::max(peakInFlight, inFlight);
            group.run([this, id = id] { bakeNode(id, true); });
        }
    }

    struct InFlight {
        BakeRun& run;
        std::size_t weight;
        ~InFlight() { run.release(weight); }
    };

    void bakeNode(Id id, bool admitted = false) {
        progress.throwIfCancelled();
        const double cpuStart = threadCpuSeconds();
        NodeBake& nb = result.nodes[id];
        std::vector<Id> inputs = inputsOf(id);
        const std::vector<AggregatePart> parts = partsOf(id, inputs);
        nb.inputTriangles = aggregateTriangleCount(scene, parts);
        if (!admitted && !admit(id, nb.inputTriangles)) return;
        const InFlight slot{*this, nb.inputTriangles};
        const glm::dvec3 origin = nb.proxy.origin;
        std::shared_ptr<std::promise<ProxyMesh>> owner;
        try {
            bool store = false;
            std::optional<ProxyMesh> known = reuse(nb.key, owner);
            ProxyCache::Claim claim; // held until the proxy is stored (ProxyCache.h)
            if (!known && cache.enabled()) {
                claim = cache.claim(nb.key, progress); // waits while another process bakes this key
                known = cache.load(nb.key);
            }
            if (known) {
                nb.proxy = std::move(*known);
                nb.reused = true;
                ++reused;
            } else {
                nb.proxy = makeNodeProxy(nb, inputs, parts, origin);
                store = true;
                ++baked;
            }
            nb.proxy.origin = origin;
            decide(id, std::move(inputs));
            // The atlas once the geometry is final and kept (AtlasStep.h); a reused proxy may
            // lack it when it was dissolved the time it was baked (a lock changes the decision).
            if (params.atlas.enabled && !nb.dissolved && nb.hasProxy && !nb.proxy.hasAtlas()) {
                progress.throwIfCancelled();
                nb.proxy = bakeNodeAtlas(nb.proxy, scene, tree, id, result.nodes, params, mips);
                store = store || nb.proxy.hasAtlas(); // unchanged: the file holds it already
            }
            if (store) cache.store(nb.key, nb.proxy);
            if (!nb.reused) nb.cpuSeconds = threadCpuSeconds() - cpuStart;
            applyProxyLook(nb.proxy, looks[id]); // not cached: derived from the originals
            if (owner) owner->set_value(nb.proxy);
            // With the disk cache on, this run's copy of the proxy goes once stored: a later
            // node with the same key (a rigid copy of this one) reads it from the cache, as a
            // second run would (a farm shard: 6 MB less at its peak). Nodes already waiting
            // hold their own copy of the future.
            if (owner && cache.enabled()) {
                const std::lock_guard lock(bakedMutex);
                bakedByKey.erase(nb.key);
            }
            // A proxy that did not pay is not drawn nor baked from (its parent reads its
            // inputs): stored above, it need not stay in memory.
            if (nb.dissolved || !nb.hasProxy) nb.proxy = ProxyMesh{origin, {}, {}, {}, {}};
        } catch (...) {
            if (owner) owner->set_exception(std::current_exception());
            throw;
        }
        const std::size_t finished = ++done;
        progress.emit(ProgressInfo{"bake", finished, result.innerNodes,
                                   "baked " + std::to_string(baked.load()) + ", reused " +
                                       std::to_string(reused.load()) + ", dissolved " +
                                       std::to_string(dissolved.load()) + ", " +
                                       std::to_string(triangles.load()) + " proxy triangles"});
        const Id parent = tree.nodes[id].parent;
        if (parent != kNoId && pending[parent].fetch_sub(1, std::memory_order_acq_rel) == 1) {
            group.run([this, parent] { bakeNode(parent); });
        }
    }
};

void validateParams(const BakeParams& params) {
    // Only what the bake cannot do without; the ranges a user may choose are declared in
    // pipeline/graph/Parameters.cpp and checked where a value enters.
    validate(params.screen);
    if (params.threads < 0) {
        throw Error(ErrorCode::InvalidArgument,
                    "threads must not be negative, got " + std::to_string(params.threads));
    }
    if (!(params.proxyRatio > 0.0 && std::isfinite(params.proxyRatio))) {
        throw Error(ErrorCode::InvalidArgument, "proxy ratio must be a positive number, got " +
                                                    std::to_string(params.proxyRatio));
    }
}

} // namespace

namespace {

// `below` (bakeAbove): the given nodes are left out of the bake and `nodes` holds them.
BakeResult bakeFrom(const Scene& scene, const ClusterTree& tree, const std::vector<Id>& roots,
                    const BakeParams& params, const Progress& progress,
                    const BakeBelow* below = nullptr, std::vector<NodeBake> nodes = {}) {
    validateParams(params);
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock(); // process CPU time, every thread
    const int threads = params.threads > 0 ? params.threads : tbb::info::default_concurrency();
    tbb::task_arena arena(threads);

    BakeResult result;
    result.nodes = std::move(nodes);
    result.nodes.resize(tree.nodes.size());
    const std::vector<Id> order = postOrder(tree, roots, below ? &below->given : nullptr);
    fillFrames(scene, tree, params, order, result.nodes);
    arena.execute([&] { leafKeys(scene, tree, order, params, result.nodes); });
    for (Id id : order) {
        if (!tree.nodes[id].isLeaf()) ++result.innerNodes;
    }

    BakeRun run{scene, tree, params, progress, ProxyCache(params.cacheDir), result, {}, {}};
    run.pending = std::make_unique<std::atomic<int>[]>(tree.nodes.size());
    run.looks =
        subtreeLookSums(scene, tree, order, below ? below->looks : std::vector<ProxyLookSums>{});
    if (below) run.standIns = below->standIns;
    run.inFlightCap = std::numeric_limits<std::size_t>::max();
    if (params.boundWorkingSets) {
        // A sixteenth of the triangles below the roots, at least the floor.
        const std::vector<std::uint64_t> below = subtreeTriangles(tree, scene);
        std::size_t belowRoots = 0;
        for (Id r : roots)
            belowRoots += below[r];
        run.inFlightCap = std::max(belowRoots / kInFlightShare, params.inFlightFloor);
    }
    run.standIns.resize(tree.nodes.size());
    std::vector<Id> ready;
    for (Id id : order) {
        const ClusterNode& node = tree.nodes[id];
        if (node.isLeaf()) continue;
        int inner = 0;
        for (Id c : node.children)
            inner += tree.nodes[c].isLeaf() || (below && below->given[c]) ? 0 : 1;
        run.pending[id].store(inner);
        if (inner == 0) ready.push_back(id);
    }
    // A subtree root's parent is outside `order`: its counter starts at 0 and only goes
    // negative, so it is never spawned.
    progress.emit(ProgressInfo{"bake", 0, result.innerNodes, ""});
    arena.execute([&] {
        for (Id id : ready)
            run.group.run([&run, id] { run.bakeNode(id); });
        run.group.wait();
    });

    result.baked = run.baked.load();
    result.reused = run.reused.load();
    result.dissolved = run.dissolved.load();
    result.damaged = run.damaged.load();
    result.peakInFlightTriangles = run.peakInFlight;
    for (Id id : order) {
        NodeBake& nb = result.nodes[id];
        if (tree.nodes[id].isLeaf()) continue;
        result.inputTriangles += nb.inputTriangles;
        if (nb.dissolved || !nb.hasProxy) {
            nb.proxy = ProxyMesh{nb.proxy.origin, {}, {}, {}, {}};
            continue;
        }
        result.proxyTriangles += nb.proxy.triangleCount();
        result.proxyVertices += nb.proxy.vertexCount();
    }
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.cpuSeconds = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    return result;
}

} // namespace

BakeResult bakeProxies(const Scene& scene, const ClusterTree& tree, const BakeParams& params,
                       const Progress& progress) {
    std::vector<Id> roots;
    if (tree.root != kNoId) roots.push_back(tree.root);
    return bakeFrom(scene, tree, roots, params, progress);
}

BakeResult bakeSubtrees(const Scene& scene, const ClusterTree& tree, const std::vector<Id>& roots,
                        const BakeParams& params, const Progress& progress) {
    std::vector<char> seen(tree.nodes.size(), 0);
    for (Id r : roots) {
        if (r >= tree.nodes.size() || tree.nodes[r].isLeaf() || seen[r]) {
            throw Error(ErrorCode::InvalidArgument,
                        "subtree root " + std::to_string(r) +
                            " is not a distinct inner node of the tree");
        }
        seen[r] = 1;
    }
    for (Id r : roots) {
        for (Id a = tree.nodes[r].parent; a != kNoId; a = tree.nodes[a].parent) {
            if (seen[a]) {
                throw Error(ErrorCode::InvalidArgument, "subtree root " + std::to_string(r) +
                                                            " lies below subtree root " +
                                                            std::to_string(a));
            }
        }
    }
    return bakeFrom(scene, tree, roots, params, progress);
}

BakeResult bakeAbove(const Scene& scene, const ClusterTree& tree, std::vector<NodeBake> nodes,
                     const BakeBelow& below, const BakeParams& params, const Progress& progress) {
    if (nodes.size() != tree.nodes.size() || below.given.size() != tree.nodes.size() ||
        tree.root == kNoId || below.given[tree.root]) {
        throw Error(ErrorCode::InvalidArgument, "bake above the cut: the given nodes do not match "
                                                "the tree");
    }
    // A proxy's look is not cached (ProxyLook.h): the given inputs get theirs as bakeNode gave
    // it to them.
    for (Id id = 0; id < nodes.size(); ++id) {
        if (below.given[id] && !tree.nodes[id].isLeaf() && !nodes[id].proxy.empty() &&
            id < below.looks.size())
            applyProxyLook(nodes[id].proxy, below.looks[id]);
    }
    return bakeFrom(scene, tree, {tree.root}, params, progress, &below, std::move(nodes));
}

std::vector<std::uint64_t> structuralKeys(const Scene& scene, const ClusterTree& tree,
                                          const BakeParams& params) {
    std::vector<Id> roots;
    if (tree.root != kNoId) roots.push_back(tree.root);
    const std::vector<Id> order = postOrder(tree, roots);
    std::vector<NodeBake> nodes(tree.nodes.size());
    fillFrames(scene, tree, params, order, nodes);
    leafKeys(scene, tree, order, params, nodes);
    std::vector<PartPlacement> placements;
    for (Id id : order) {
        const ClusterNode& node = tree.nodes[id];
        if (!node.isLeaf())
            nodes[id].key = frameInputs(scene, tree, params, id, node.children, nodes, placements);
    }
    std::vector<std::uint64_t> keys(tree.nodes.size(), 0);
    for (Id id : order)
        keys[id] = nodes[id].key;
    return keys;
}

std::uint64_t bakeParamsKey(const BakeParams& params) {
    ContentHash h(0x7061726d); // "parm"
    hashOptions(h, params);
    h.addValue(params.screen.screenSize);
    h.addValue(params.screen.pixelError);
    h.addValue(params.screen.fovYDegrees);
    h.addValue(params.screen.viewportHeight);
    h.addValue(params.proxyRatio);
    return h.digest();
}

} // namespace hlod
