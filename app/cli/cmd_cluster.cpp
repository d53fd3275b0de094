// `hlod cluster [SCENE...] [--volume sphere|aabb|octree|original] [--k K] [--max-children N]
// [--json]`: builds the HLOD cluster tree of a scene and prints it with its quality metrics.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "Args.h"
#include "Commands.h"
#include "ProgressBar.h"
#include "SceneInput.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/cluster/ClusterJson.h"
#include "pipeline/cluster/TreeMetrics.h"

namespace hlod::cli {

namespace {

void printMetrics(const TreeMetrics& m) {
    std::printf("nodes:        %zu (%zu leaves, %zu inner)\n", m.nodes, m.leaves, m.innerNodes);
    std::printf("depth:        %d (mean leaf depth %.2f)\n", m.depth, m.meanLeafDepth);
    std::printf("children:     min %zu, mean %.2f, max %zu per inner node\n", m.minChildren,
                m.meanChildren, m.maxChildren);
    std::printf("volume:       %.6g m^3 spheres, %.6g m^3 boxes (inner nodes)\n",
                m.totalSphereVolume, m.totalBoxVolume);
    std::printf("mean fill:    %.4f\n", m.meanFill);
    std::printf("spread:       mean %.4f, max %.4f\n", m.meanSpread, m.maxSpread);
}

void printNode(const ClusterTree& tree, Id id, int depth) {
    const ClusterNode& n = tree.nodes[id];
    std::printf("%*s#%u L%d ", depth * 2, "", id, n.level);
    if (n.isLeaf()) {
        std::printf("instance %u", n.instance);
    } else {
        std::printf("%zu children", n.children.size());
    }
    std::printf(" fill %.4f cost %.6g sphere (%.4f %.4f %.4f) r %.4f box (%.4f %.4f %.4f)-(%.4f "
                "%.4f %.4f)%s\n",
                n.fill, n.cost, n.sphere.center.x, n.sphere.center.y, n.sphere.center.z,
                n.sphere.radius, n.box.min.x, n.box.min.y, n.box.min.z, n.box.max.x, n.box.max.y,
                n.box.max.z, n.locked ? " locked" : "");
}

// Depth-first, children in stored order (iterative: trees can be deep).
void printTree(const ClusterTree& tree) {
    if (tree.root == kNoId) return;
    std::vector<std::pair<Id, int>> stack{{tree.root, 0}};
    while (!stack.empty()) {
        const auto [id, depth] = stack.back();
        stack.pop_back();
        printNode(tree, id, depth);
        const auto& children = tree.nodes[id].children;
        for (auto it = children.rbegin(); it != children.rend(); ++it) {
            stack.push_back({*it, depth + 1});
        }
    }
}

} // namespace

int runCluster(const CommandArgs& argv) {
    const Args args(argv, command("cluster"));
    ParamValues values = defaultValues(NodeKind::Cluster);
    for (const auto& [decl, value] : paramsFromArgs(args, {NodeKind::Cluster}))
        values[decl->key] = value;
    const ClusterParams params = clusterParamsFrom(values);
    const LoadedScene loaded = loadSceneArgs(args.positionals(), importOptionsFromArgs(args));

    const auto start = std::chrono::steady_clock::now();
    ClusterTree tree;
    {
        ProgressBar bar;
        tree = buildClusterTree(loaded.scene, params, bar.progress());
        bar.finish();
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const TreeMetrics metrics = computeTreeMetrics(tree);

    if (args.has("--json")) {
        nlohmann::json j;
        j["inputs"] = loaded.inputs;
        j["params"] = {{"volume", toString(params.volume)},
                       {"k", params.k},
                       {"max_children", params.maxChildren}};
        j["metrics"] = treeMetricsToJson(metrics);
        // "tree" is the last key (std::map order): the rest as nlohmann dumps it, then the tree
        // streamed as text, the very bytes j["tree"] = clusterTreeToJson(tree) would give.
        std::string text = j.dump(2);
        text.resize(text.size() - 2); // the closing "\n}"
        text += ",\n  \"tree\": ";
        appendClusterTreeJson(text, tree, 1);
        text += "\n}\n";
        std::cout.write(text.data(), static_cast<std::streamsize>(text.size()));
        return 0;
    }
    std::printf("scene:        ");
    for (const auto& in : loaded.inputs)
        std::printf("%s ", in.c_str());
    std::printf("\nclusterer:    %s", toString(params.volume));
    if (params.volume == VolumeType::Aabb) std::printf(" (k = %g)", params.k);
    std::printf(", max %d children, %.3f s\n", params.maxChildren, seconds);
    printMetrics(metrics);
    std::printf("\ntree (id, level, content, fill, cost, bounds in m):\n");
    printTree(tree);
    return 0;
}

} // namespace hlod::cli
