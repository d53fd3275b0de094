// Original hierarchy baseline, leaf-only conversion of thesis figure 5.2 (see header).
#include "pipeline/cluster/OriginalHierarchyClusterer.h"

#include <algorithm>

#include "pipeline/core/Error.h"

namespace hlod {

Id mergeOriginalHierarchy(const Scene& scene, TreeBuilder& builder, std::vector<Id> units,
                          int /*maxChildren*/, const Progress& progress) {
    if (units.empty()) return kNoId;
    std::sort(units.begin(), units.end());
    // Leaf units grouped by the scene node they hang from; other units go to the root.
    std::vector<std::vector<Id>> leavesAt(scene.nodes.size());
    std::vector<Id> topUnits;
    for (Id u : units) {
        const ClusterNode& n = builder.node(u);
        if (n.isLeaf() && n.instance < scene.instances.size()) {
            leavesAt[scene.instances[n.instance].node].push_back(u);
        } else {
            topUnits.push_back(u);
        }
    }
    // Iterative post-order over the scene graph (CAD assemblies can be deep).
    std::vector<Id> result(scene.nodes.size(), kNoId);
    std::vector<std::pair<Id, bool>> stack{{0, false}};
    while (!stack.empty()) {
        auto [id, expanded] = stack.back();
        stack.pop_back();
        const Node& node = scene.nodes[id];
        if (!expanded) {
            stack.push_back({id, true});
            for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) {
                stack.push_back({*it, false});
            }
            continue;
        }
        std::vector<Id> entries = leavesAt[id];
        for (Id c : node.children) {
            if (result[c] != kNoId) entries.push_back(result[c]);
        }
        if (entries.size() == 1) {
            result[id] = entries[0];
        } else if (entries.size() > 1) {
            result[id] = builder.addFoldedNode(std::move(entries));
        }
    }
    progress.throwIfCancelled();
    if (result[0] != kNoId) topUnits.push_back(result[0]);
    if (topUnits.size() == 1) return topUnits[0];
    return builder.addFoldedNode(std::move(topUnits));
}

} // namespace hlod
