// Removing the nodes whose proxies did not pay, see ProxyEconomy.h.
#include "pipeline/proxy/ProxyEconomy.h"

#include "pipeline/cluster/DissolveNodes.h"
#include "pipeline/core/Error.h"

namespace hlod {

std::vector<Id> compactDissolved(ClusterTree& tree, BakeResult& bake) {
    if (bake.nodes.size() != tree.nodes.size()) {
        throw Error(ErrorCode::InvalidArgument, "proxy economy: the proxies do not match the tree");
    }
    std::vector<char> remove(tree.nodes.size(), 0);
    bool any = false;
    for (Id i = 0; i < tree.nodes.size(); ++i) {
        remove[i] = bake.nodes[i].dissolved ? 1 : 0;
        any = any || remove[i];
    }
    if (!any) return {};
    DissolvedTree d = dissolveNodes(tree, remove);
    std::vector<NodeBake> nodes(d.tree.nodes.size());
    for (Id i = 0; i < tree.nodes.size(); ++i) {
        if (d.newId[i] != kNoId) nodes[d.newId[i]] = std::move(bake.nodes[i]);
    }
    bake.nodes = std::move(nodes);
    bake.innerNodes = 0;
    for (const ClusterNode& n : d.tree.nodes)
        bake.innerNodes += n.isLeaf() ? 0 : 1;
    tree = std::move(d.tree);
    return std::move(d.newId);
}

BakeResult bakeEconomised(const Scene& scene, ClusterTree& tree, const BakeParams& params,
                          const Progress& progress) {
    BakeResult bake = bakeProxies(scene, tree, params, progress);
    compactDissolved(tree, bake);
    return bake;
}

bool rootHasNoProxy(const ClusterTree& tree, const BakeResult& bake) {
    return tree.root != kNoId && tree.root < bake.nodes.size() && !tree.nodes[tree.root].isLeaf() &&
           !bake.nodes[tree.root].hasProxy;
}

} // namespace hlod
