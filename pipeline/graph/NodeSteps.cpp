// What each node kind of the pipeline graph computes (PipelineGraph.h): Import reads the source
// scene (or the embedded sample, or a package folder), Cluster builds the tree under the hand
// edits (HandEdits.h, SplitClusters.h), Bake bakes the proxies (disk cache) and applies the proxy
// economy (ProxyEconomy.h: bakeEconomised), Export writes the package (ExportStep.h). These are
// the only places the stages are called from a graph: the CLI and the editor both come here.
#include <chrono>
#include <optional>

#include "pipeline/core/Error.h"
#include "pipeline/export/Package.h"
#include "pipeline/graph/PipelineGraph.h"
#include "pipeline/graph/SplitClusters.h"
#include "pipeline/io/SampleScene.h"
#include "pipeline/proxy/ProxyEconomy.h"

namespace hlod {

namespace {

double secondsSince(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

NodeOutput runImport(const GraphNode& node, const Progress& progress) {
    NodeOutput out;
    if (node.sources.empty()) {
        out.scene = std::make_shared<const Scene>(makeSampleScene());
        out.inputs = {"sample:plant"};
        return out;
    }
    for (const auto& p : node.sources)
        out.inputs.push_back(p.string());
    if (node.sources.size() == 1 && isPackageFolder(node.sources[0])) {
        out.scene = std::make_shared<const Scene>(readPackageScene(readPackage(node.sources[0])));
        return out;
    }
    out.scene = std::make_shared<const Scene>(
        importScene(node.sources, importOptionsFrom(node.params), progress));
    return out;
}

NodeOutput runCluster(const GraphNode& node, const NodeOutput& in, const Progress& progress) {
    NodeOutput out = in;
    out.cluster = clusterParamsFrom(node.params);
    validateHandEdits(node.edits, in.scene->instances.size());
    applyConstraints(node.edits, out.cluster);
    out.edits = node.edits;
    const auto t = std::chrono::steady_clock::now();
    ClusterTree tree = buildClusterTree(*in.scene, out.cluster, progress);
    out.tree =
        std::make_shared<const ClusterTree>(splitClusters(std::move(tree), node.edits.dissolved));
    out.clusterSeconds = secondsSince(t);
    out.bake.reset();
    out.exported.reset();
    return out;
}

NodeOutput runBake(const GraphNode& node, const NodeOutput& in, const Progress& progress) {
    NodeOutput out = in;
    out.bakeParams = bakeParamsFrom(node.params);
    validate(out.bakeParams.screen);
    // The proxy economy dissolves nodes: the tree downstream is the one the proxies belong to.
    auto tree = std::make_shared<ClusterTree>(*in.tree);
    out.bake = std::make_shared<const BakeResult>(
        bakeEconomised(*in.scene, *tree, out.bakeParams, progress));
    out.tree = std::move(tree);
    out.exported.reset();
    return out;
}

NodeOutput runExport(const GraphNode& node, const NodeOutput& in, const Progress& progress) {
    NodeOutput out = in;
    ExportOptions options;
    options.output = paramText(node.params, "output");
    options.dlod = paramBool(node.params, "dlod");
    options.compression = glbCompressionFromString(paramText(node.params, "compression"));
    if (const std::string geo = paramText(node.params, "geo"); !geo.empty())
        options.geo = parseGeoLocation(geo);
    const BuildInputs inputs{*in.scene, *in.tree,      *in.bake, in.cluster,
                             in.edits,  in.bakeParams, in.inputs};
    out.exported = std::make_shared<const ExportResult>(exportPackage(inputs, options, progress));
    return out;
}

} // namespace

NodeOutput runNodeStep(const GraphNode& node, const NodeOutput* input, const Progress& progress) {
    progress.throwIfCancelled();
    if (node.kind == NodeKind::Import) return runImport(node, progress);
    auto need = [&](bool ok, const char* what) {
        if (!ok) {
            throw Error(ErrorCode::InvalidArgument,
                        nodeLabel(node) + ": no " + what + " from its input");
        }
    };
    need(input && input->scene, "scene");
    switch (node.kind) {
    case NodeKind::Cluster:
        return runCluster(node, *input, progress);
    case NodeKind::Bake:
        need(input->tree != nullptr, "cluster tree");
        return runBake(node, *input, progress);
    case NodeKind::Export:
        need(input->tree && input->bake, "baked proxies");
        return runExport(node, *input, progress);
    case NodeKind::Import:
        break;
    }
    return {};
}

} // namespace hlod
