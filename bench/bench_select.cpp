// LOD selection speed on a large clustered scene (see docs/benchmarks.md): Algorithm 5's full
// traversal vs the frame-coherent front cache, along a deterministic 600-frame camera path
// (an orbit that closes in from 1.5 scene diagonals to a fly-over at 2% of the diagonal).
// The tree is what the real clusterer builds (AABB, k = 1) over a generated clumped scene.
// Run: build/bench/bench_select --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>

#include "pipeline/cluster/Cluster.h"
#include "pipeline/cluster/RandomScenes.h"
#include "pipeline/select/LodSelection.h"

using namespace hlod;

namespace {

struct Fixture {
    Scene scene;
    ClusterTree tree;
    std::unique_ptr<SelectionTree> sel;
    std::vector<Camera> path;
    explicit Fixture(std::size_t instances) {
        scene = hlod::test::makeRandomScene({instances, hlod::test::Layout::Clumped, 7, 0.0});
        ClusterParams p;
        p.volume = VolumeType::Aabb;
        p.k = 1.0;
        tree = buildClusterTree(scene, p);
        sel = std::make_unique<SelectionTree>(tree,
                                              std::vector<std::uint64_t>(tree.nodes.size(), 100));
        const Aabb b = scene.worldBounds();
        const glm::dvec3 c = b.center();
        const double diag = b.diagonal();
        for (int i = 0; i < 600; ++i) {
            const double t = i / 599.0, a = t * 4.0;
            const double r = diag * (1.5 * (1.0 - t) + 0.02 * t);
            Camera cam;
            cam.eye = c + glm::dvec3(r * std::cos(a), r * 0.4, r * std::sin(a));
            cam.target = c;
            cam.viewportHeight = 1080;
            cam.nearPlane = diag * 1e-4;
            cam.farPlane = diag * 10.0;
            path.push_back(cam);
        }
    }
};

Fixture& fixture(std::size_t n) {
    static std::map<std::size_t, std::unique_ptr<Fixture>> cache;
    auto& f = cache[n];
    if (!f) f = std::make_unique<Fixture>(n);
    return *f;
}

template <typename Select> void run(benchmark::State& state, Fixture& f, Select&& select) {
    std::size_t i = 0, drawn = 0, visited = 0;
    for (auto _ : state) {
        const SelectionResult r = select(f.path[i++ % f.path.size()]);
        drawn += r.drawCalls;
        visited += r.nodesVisited;
        benchmark::DoNotOptimize(r.drawList.data());
    }
    const double n = static_cast<double>(state.iterations());
    state.counters["nodes"] = static_cast<double>(f.tree.nodes.size());
    state.counters["draws/frame"] = static_cast<double>(drawn) / n;
    state.counters["visited/frame"] = static_cast<double>(visited) / n;
}

void BM_SelectFull(benchmark::State& state) {
    Fixture& f = fixture(static_cast<std::size_t>(state.range(0)));
    run(state, f, [&](const Camera& c) { return selectFull(*f.sel, c, {300.0}); });
}

void BM_SelectFrontCache(benchmark::State& state) {
    Fixture& f = fixture(static_cast<std::size_t>(state.range(0)));
    FrontCache cache(*f.sel);
    run(state, f, [&](const Camera& c) { return cache.select(c, {300.0}); });
}

} // namespace

BENCHMARK(BM_SelectFull)->Arg(1000)->Arg(10000)->Arg(60000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SelectFrontCache)->Arg(1000)->Arg(10000)->Arg(60000)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
