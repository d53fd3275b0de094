// Proxy baking throughput (issue #4): input triangles per second of bakeProxies with 1 and 2
// threads, against raw meshopt_simplify on exactly the same per-node inputs (the aggregated
// children of every inner node, at every node's error budget). Issue 26: the certified path
// alone (makeProxy, simplification and the two-way deviation certificate, one thread) on those
// very inputs, next to meshopt_simplify, both with their output triangles, so the price of the
// certificate is measured apart from aggregation, keys and reuse (bakeProxies bakes each of
// the grid's repeated clusters once; these two simplify every node).
//
// Scene: a deterministic grid of spheres, cylinders and boxes under a hand-built quadtree
// (4 children per inner node), so the measurement does not depend on the clusterer.
// Run: build/bench/bench_bake --benchmark_min_time=2 (see docs/benchmarks.md, proxy baking).
#include <benchmark/benchmark.h>

#include <glm/gtc/matrix_transform.hpp>
#include <meshoptimizer.h>

#include "pipeline/proxy/Aggregate.h"
#include "pipeline/proxy/ProxyBaker.h"
#include "pipeline/scene/Primitives.h"

using namespace hlod;

namespace {

struct Workload {
    Scene scene;
    ClusterTree tree;
    std::vector<ProxyMesh> inputs; // aggregated input of every inner node
    std::vector<double> budgets;
    std::size_t inputTriangles = 0;
};

Id addNode(ClusterTree& tree, ClusterNode node) {
    tree.nodes.push_back(std::move(node));
    const Id id = static_cast<Id>(tree.nodes.size() - 1);
    for (Id c : tree.nodes[id].children)
        tree.nodes[c].parent = id;
    return id;
}

// Quadtree over a side x side grid of cells [x0, x0 + size) x [y0, y0 + size).
Id buildQuad(Workload& w, const std::vector<Id>& leafOf, int side, int x0, int y0, int size) {
    if (size == 1) return leafOf[static_cast<std::size_t>(y0 * side + x0)];
    ClusterNode n;
    const int half = size / 2;
    for (int q = 0; q < 4; ++q) {
        n.children.push_back(
            buildQuad(w, leafOf, side, x0 + (q % 2) * half, y0 + (q / 2) * half, half));
    }
    for (Id c : n.children) {
        n.box.expand(w.tree.nodes[c].box);
        n.level = std::max(n.level, w.tree.nodes[c].level + 1);
    }
    n.sphere.center = n.box.center();
    n.sphere.radius = n.box.diagonal() * 0.5;
    return addNode(w.tree, std::move(n));
}

const Workload& workload() {
    static const Workload w = [] {
        Workload out;
        const int side = 16; // 256 objects, 85 inner nodes
        const Id meshes[] = {out.scene.addMesh(makeSphere(0.5f, 64, 32)),
                             out.scene.addMesh(makeCylinder(0.3f, 1.2f, 48)),
                             out.scene.addMesh(makeSphere(0.35f, 40, 20))};
        std::vector<Id> leafOf;
        for (int y = 0; y < side; ++y) {
            for (int x = 0; x < side; ++x) {
                const glm::dvec3 at(x * 1.5, 0.0, y * 1.5);
                const Id node = out.scene.addNode("o", 0, glm::translate(glm::dmat4(1.0), at));
                const Id inst = out.scene.addInstance(meshes[(x + 2 * y) % 3], node);
                ClusterNode leaf;
                leaf.instance = inst;
                leaf.box = out.scene.instanceBounds(inst);
                leaf.sphere.center = leaf.box.center();
                leaf.sphere.radius = leaf.box.diagonal() * 0.5;
                leafOf.push_back(addNode(out.tree, std::move(leaf)));
            }
        }
        out.tree.root = buildQuad(out, leafOf, side, 0, 0, side);
        // The exact inputs bakeProxies feeds each node (children's proxies, leaves' meshes).
        BakeParams params;
        params.threads = 2;
        const BakeResult baked = bakeProxies(out.scene, out.tree, params);
        for (Id id = 0; id < out.tree.nodes.size(); ++id) {
            const ClusterNode& n = out.tree.nodes[id];
            if (n.isLeaf()) continue;
            std::vector<AggregatePart> parts;
            for (Id c : n.children) {
                if (out.tree.nodes[c].isLeaf())
                    parts.push_back({out.tree.nodes[c].instance, nullptr});
                else
                    parts.push_back({kNoId, &baked.nodes[c].proxy});
            }
            out.inputs.push_back(aggregateParts(out.scene, parts, baked.nodes[id].proxy.origin));
            out.budgets.push_back(baked.nodes[id].errorBudget);
            out.inputTriangles += out.inputs.back().triangleCount();
        }
        return out;
    }();
    return w;
}

void BM_BakeDecimate(benchmark::State& state) {
    const Workload& w = workload();
    BakeParams params;
    params.threads = static_cast<int>(state.range(0));
    for (auto _ : state) {
        BakeResult r = bakeProxies(w.scene, w.tree, params);
        benchmark::DoNotOptimize(r.proxyTriangles);
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * w.inputTriangles));
    state.counters["input_tris"] = static_cast<double>(w.inputTriangles);
}

void BM_BakeMethod(benchmark::State& state, ProxyMethod method) {
    const Workload& w = workload();
    BakeParams params;
    params.method = method;
    params.threads = static_cast<int>(state.range(0));
    for (auto _ : state) {
        BakeResult r = bakeProxies(w.scene, w.tree, params);
        benchmark::DoNotOptimize(r.proxyTriangles);
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * w.inputTriangles));
}

// One meshopt_simplify per node on the same aggregated triangles at the node's budget: what
// a bare "simplify everything once" pass costs, single-threaded (no certificate: its error is
// meshoptimizer's own estimate, not a bound).
void BM_RawMeshoptSimplify(benchmark::State& state) {
    const Workload& w = workload();
    std::vector<unsigned> out;
    std::size_t kept = 0;
    for (auto _ : state) {
        kept = 0;
        for (std::size_t i = 0; i < w.inputs.size(); ++i) {
            const ProxyMesh& m = w.inputs[i];
            const float* pos = &m.positions[0].x;
            const float scale = meshopt_simplifyScale(pos, m.positions.size(), sizeof(glm::vec3));
            out.resize(m.indices.size());
            kept += meshopt_simplify(out.data(), m.indices.data(), m.indices.size(), pos,
                                     m.positions.size(), sizeof(glm::vec3), 0,
                                     static_cast<float>(w.budgets[i] / scale), 0, nullptr) /
                    3;
            benchmark::DoNotOptimize(out.data());
        }
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * w.inputTriangles));
    state.counters["input_tris"] = static_cast<double>(w.inputTriangles);
    state.counters["output_tris"] = static_cast<double>(kept);
}

// The certified path on the same inputs: makeProxy per node at its budget (the default
// decimate method: simplify, then prove every point within the budget both ways), one thread.
void BM_CertifiedSimplify(benchmark::State& state) {
    const Workload& w = workload();
    BakeParams params;
    params.threads = 1;
    std::size_t kept = 0;
    for (auto _ : state) {
        kept = 0;
        for (std::size_t i = 0; i < w.inputs.size(); ++i)
            kept += makeProxy(w.inputs[i], w.budgets[i], params).triangleCount();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * w.inputTriangles));
    state.counters["input_tris"] = static_cast<double>(w.inputTriangles);
    state.counters["output_tris"] = static_cast<double>(kept);
}

} // namespace

BENCHMARK(BM_RawMeshoptSimplify)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CertifiedSimplify)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_BakeDecimate)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_BakeMethod, sloppy, ProxyMethod::Sloppy)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_BakeMethod, remesh, ProxyMethod::Remesh)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

BENCHMARK_MAIN();
