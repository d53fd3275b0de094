// LOD selection speed on large random trees (see docs/benchmarks.md): Algorithm 5's full
// traversal vs the frame-coherent front cache, along a smooth fly-in camera path.
// Run: build/bench/bench_select --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>

#include "pipeline/select/LodSelection.h"
#include "pipeline/select/RandomTree.h"

using namespace hlod;

namespace {

struct Fixture {
    ClusterTree tree;
    SelectionTree sel;
    std::vector<Camera> path;
    explicit Fixture(std::size_t leaves)
        : tree(hlod::test::randomTree(leaves, 7, 4, 5000.0)),
          sel(tree, std::vector<std::uint64_t>(tree.nodes.size(), 100)) {
        for (int i = 0; i < 600; ++i) { // 10 s at 60 fps: orbit while descending
            const double a = i * 0.004, r = 6000.0 - i * 9.0;
            Camera c;
            c.eye = {r * std::cos(a), 50.0 + r * 0.05, r * std::sin(a)};
            c.target = {0, 0, 0};
            c.viewportHeight = 1080;
            c.farPlane = 1e6;
            path.push_back(c);
        }
    }
};

Fixture& fixture(std::size_t leaves) {
    static std::map<std::size_t, std::unique_ptr<Fixture>> cache;
    auto& f = cache[leaves];
    if (!f) f = std::make_unique<Fixture>(leaves);
    return *f;
}

void BM_SelectFull(benchmark::State& state) {
    Fixture& f = fixture(static_cast<std::size_t>(state.range(0)));
    std::size_t i = 0, drawn = 0;
    for (auto _ : state) {
        const SelectionResult r = selectFull(f.sel, f.path[i++ % f.path.size()], {300.0});
        drawn += r.drawCalls;
        benchmark::DoNotOptimize(r.drawList.data());
    }
    state.counters["nodes"] = static_cast<double>(f.tree.nodes.size());
    state.counters["draws/frame"] = static_cast<double>(drawn) / state.iterations();
}

void BM_SelectFrontCache(benchmark::State& state) {
    Fixture& f = fixture(static_cast<std::size_t>(state.range(0)));
    FrontCache cache(f.sel);
    std::size_t i = 0, drawn = 0;
    for (auto _ : state) {
        const SelectionResult r = cache.select(f.path[i++ % f.path.size()], {300.0});
        drawn += r.drawCalls;
        benchmark::DoNotOptimize(r.drawList.data());
    }
    state.counters["nodes"] = static_cast<double>(f.tree.nodes.size());
    state.counters["draws/frame"] = static_cast<double>(drawn) / state.iterations();
}

} // namespace

BENCHMARK(BM_SelectFull)->Arg(1000)->Arg(10000)->Arg(70000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SelectFrontCache)->Arg(1000)->Arg(10000)->Arg(70000)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
