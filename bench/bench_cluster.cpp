// Clustering benchmarks (issue #3; figures and commands in docs/benchmarks.md, clustering).
//
// BM_Cluster: buildClusterTree (instance bounds + level merging) on generated scenes of 1k to
// 1M instances, uniform and clumped layouts, sphere and AABB (k = 1), on ONE thread (TBB
// limited to 1) so the figures do not depend on the machine's core count.
// BM_Cluster with volume 2: the loose octree baseline on the same scenes.
// BM_ClusterAabbK: the AABB clusterer for k = 0, 1, 2 on the same scenes.
// BM_NaiveReference / BM_FastReference: the all-pairs reference of the tests
// (tests/pipeline/cluster/NaiveClusterer.h) against the fast merger on 2k-5k instances, merge
// stage only (bounds precomputed), for the speed ratio.
// Counters: nodes of the tree, peak RSS of the process in MiB (ru_maxrss: run one size per
// process, with --benchmark_filter, to read the memory of that size).
#include <map>
#include <memory>
#include <string>
#include <tuple>

#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <tbb/global_control.h>

#include "pipeline/bounds/InstanceBounds.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/cluster/ClusterDriver.h"
#include "pipeline/cluster/LevelMerger.h"
#include "pipeline/cluster/NaiveClusterer.h"
#include "pipeline/cluster/RandomScenes.h"

namespace {

using hlod::test::Layout;

const hlod::Scene& scene(std::size_t n, Layout layout) {
    // One scene alive at a time: the 1M scene alone is several hundred MiB.
    static std::unique_ptr<hlod::Scene> cached;
    static std::tuple<std::size_t, Layout> key{0, Layout::Uniform};
    if (!cached || key != std::make_tuple(n, layout)) {
        cached.reset();
        cached = std::make_unique<hlod::Scene>(hlod::test::makeRandomScene({n, layout, 42, 0.02}));
        key = {n, layout};
    }
    return *cached;
}

double peakRssMiB() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_maxrss) / 1024.0; // ru_maxrss is in KiB on Linux
}

// Times buildClusterTree(s, p) and reports the node count and the peak memory.
void timeClustering(benchmark::State& state, const hlod::Scene& s, const hlod::ClusterParams& p) {
    std::size_t nodes = 0;
    for (auto _ : state) {
        const hlod::ClusterTree t = hlod::buildClusterTree(s, p);
        nodes = t.nodes.size();
        benchmark::DoNotOptimize(nodes);
    }
    state.counters["nodes"] = static_cast<double>(nodes);
    state.counters["peakRssMiB"] = peakRssMiB();
}

// range(0): instances, range(1): layout (0 uniform, 1 clumped), range(2): volume (0 sphere,
// 1 aabb k=1, 2 octree).
void BM_Cluster(benchmark::State& state) {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    const auto n = static_cast<std::size_t>(state.range(0));
    const Layout layout = state.range(1) ? Layout::Clumped : Layout::Uniform;
    const hlod::Scene& s = scene(n, layout);
    hlod::ClusterParams p;
    p.volume = state.range(2) == 0   ? hlod::VolumeType::Sphere
               : state.range(2) == 1 ? hlod::VolumeType::Aabb
                                     : hlod::VolumeType::Octree;
    p.k = 1.0;
    timeClustering(state, s, p);
    state.SetLabel(std::string(layout == Layout::Clumped ? "clumped " : "uniform ") +
                   hlod::toString(p.volume));
}

void clusterArgs(benchmark::internal::Benchmark* b) {
    for (long n : {1000L, 10000L, 100000L, 1000000L}) {
        for (long layout : {0L, 1L}) {
            for (long volume : {0L, 1L, 2L})
                b->Args({n, layout, volume});
        }
    }
}
BENCHMARK(BM_Cluster)->Apply(clusterArgs)->Unit(benchmark::kSecond)->Iterations(1);

// BM_ClusterAabbK: the AABB clusterer with k = range(2) (0, 1 or 2, the thesis' values);
// range(0) instances, range(1) layout as BM_Cluster.
void BM_ClusterAabbK(benchmark::State& state) {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    const auto n = static_cast<std::size_t>(state.range(0));
    const Layout layout = state.range(1) ? Layout::Clumped : Layout::Uniform;
    const hlod::Scene& s = scene(n, layout);
    hlod::ClusterParams p;
    p.volume = hlod::VolumeType::Aabb;
    p.k = static_cast<double>(state.range(2));
    timeClustering(state, s, p);
    state.SetLabel(std::string(layout == Layout::Clumped ? "clumped" : "uniform") +
                   " aabb k=" + std::to_string(state.range(2)));
}
BENCHMARK(BM_ClusterAabbK)
    ->ArgsProduct({{1000, 10000, 100000, 1000000}, {0, 1}, {0, 1, 2}})
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

// Leaves of `s` in a fresh builder, ready for a merger.
std::pair<hlod::TreeBuilder, std::vector<hlod::Id>> leaves(const hlod::Scene& s,
                                                           hlod::VolumeType volume) {
    const hlod::CostModel model(volume, volume == hlod::VolumeType::Aabb ? 1.0 : 0.0);
    const auto bounds = hlod::computeInstanceBounds(s);
    std::vector<hlod::Aabb> boxes;
    for (const auto& b : bounds)
        boxes.push_back(b.box);
    const double minExtent = hlod::clusteringMinExtent(boxes);
    hlod::TreeBuilder builder(model);
    std::vector<hlod::Id> units;
    for (hlod::Id i = 0; i < bounds.size(); ++i) {
        units.push_back(builder.addLeaf(i, bounds[i].box,
                                        model.leaf(bounds[i].sphere, bounds[i].box, minExtent)));
    }
    return {std::move(builder), std::move(units)};
}

template <bool Naive> void mergeOnly(benchmark::State& state) {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    const auto n = static_cast<std::size_t>(state.range(0));
    const hlod::VolumeType volume =
        state.range(1) ? hlod::VolumeType::Aabb : hlod::VolumeType::Sphere;
    const hlod::Scene& s = scene(n, Layout::Clumped);
    for (auto _ : state) {
        state.PauseTiming();
        auto [builder, units] = leaves(s, volume);
        state.ResumeTiming();
        const hlod::Id root = Naive ? hlod::test::naiveMergeLevels(builder, units, 8, {})
                                    : hlod::mergeLevels(builder, units, 8);
        benchmark::DoNotOptimize(root);
    }
    state.SetLabel(std::string("clumped ") + hlod::toString(volume));
}

void BM_NaiveReference(benchmark::State& state) { mergeOnly<true>(state); }
void BM_FastReference(benchmark::State& state) { mergeOnly<false>(state); }

BENCHMARK(BM_NaiveReference)
    ->ArgsProduct({{2000, 5000}, {0, 1}})
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK(BM_FastReference)->ArgsProduct({{2000, 5000}, {0, 1}})->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
