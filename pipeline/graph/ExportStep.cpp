// The Export stage: build statistics and the package (see ExportStep.h). The steps are the ones
// `hlod build` always ran; they moved here so the editor and the CLI share them.
#include "pipeline/graph/ExportStep.h"

#include <chrono>

#include <nlohmann/json.hpp>

#include "pipeline/core/Error.h"
#include "pipeline/proxy/BakeStats.h"
#include "pipeline/proxy/DlodChain.h"

namespace hlod {

BuildInfo makeBuildInfo(const BuildInputs& in, bool dlod, double* dlodSeconds) {
    BuildInfo info;
    info.inputs = in.inputs;
    info.bake = in.bakeParams;
    info.clusterParameters = {{"volume", toString(in.cluster.volume)},
                              {"k", in.cluster.k},
                              {"max_children", in.cluster.maxChildren},
                              {"level_growth", in.cluster.levelGrowth}};
    if (!in.edits.empty()) info.clusterParameters["hand_edits"] = handEditsToJson(in.edits);
    const SizeTable sizes = in.sizes ? *in.sizes : sizeTable(in.scene, in.bake);
    info.statistics.push_back(originalStats(in.scene, sizes));
    if (dlod) {
        const DlodSummary chain =
            summarizeDlodChains(in.scene, DlodParams{}, in.bakeParams.threads);
        if (dlodSeconds) *dlodSeconds = chain.seconds;
        info.statistics.push_back(dlodStats(chain));
    }
    info.statistics.push_back(hlodStats(in.scene, in.tree, sizes, hlodVersionName(in.tree)));
    info.share = proxyShare(in.scene, in.tree, in.bake, sizes);
    info.levels = levelTable(in.scene, in.tree, in.bake, sizes);
    return info;
}

ExportResult exportPackage(const BuildInputs& in, const ExportOptions& options,
                           const Progress& progress) {
    if (options.output.empty())
        throw Error(ErrorCode::InvalidArgument, "missing -o DIR (output folder)");
    ExportResult out;
    out.output = options.output;
    out.info = makeBuildInfo(in, options.dlod, &out.dlodSeconds);
    progress.throwIfCancelled();
    const auto t = std::chrono::steady_clock::now();
    out.written = writePackage(options.output, in.scene, in.tree, in.bake, in.bakeParams,
                               packageOptionsFor(in, out.info, options), progress);
    out.writeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    out.source = sourceFootprint(in.scene);
    return out;
}

PackageOptions packageOptionsFor(const BuildInputs& in, const BuildInfo& info,
                                 const ExportOptions& options) {
    PackageOptions package;
    package.inputs = in.inputs;
    package.geo = options.geo;
    package.compression = options.compression;
    // Without "nodes": the package manifest has its own node list.
    nlohmann::json summary = buildTreeJson(in.scene, in.tree, in.bake, info, false);
    // What this run did (proxies baked or found in the cache, its time) is not part of the
    // package: the same inputs make the same bytes whatever the cache held, which is what lets
    // a distributed bake's final step write a single machine's package (BakePlan.h).
    if (auto bake = summary.find("bake"); bake != summary.end() && bake->is_object()) {
        for (const char* key : {"baked", "reused", "seconds"})
            bake->erase(key);
    }
    package.parameters = summary.value("parameters", nlohmann::json::object());
    package.statistics = summary;
    return package;
}

} // namespace hlod
