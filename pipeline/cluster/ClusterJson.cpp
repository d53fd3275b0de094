// Cluster tree -> JSON (schema in ClusterJson.h).
#include "pipeline/cluster/ClusterJson.h"

namespace hlod {

namespace {

nlohmann::json vec(const glm::dvec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

nlohmann::json idOrNull(Id id) {
    return id == kNoId ? nlohmann::json(nullptr) : nlohmann::json(id);
}

} // namespace

nlohmann::json clusterTreeToJson(const ClusterTree& tree) {
    nlohmann::json nodes = nlohmann::json::array();
    for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
        const ClusterNode& n = tree.nodes[i];
        nodes.push_back({
            {"id", i},
            {"parent", idOrNull(n.parent)},
            {"children", n.children},
            {"instance", idOrNull(n.instance)},
            {"box", {{"min", vec(n.box.min)}, {"max", vec(n.box.max)}}},
            {"sphere", {{"center", vec(n.sphere.center)}, {"radius", n.sphere.radius}}},
            {"fill", n.fill},
            {"cost", n.cost},
            {"level", n.level},
            {"locked", n.locked},
        });
    }
    return {{"volume", toString(tree.volume)},
            {"k", tree.k},
            {"root", idOrNull(tree.root)},
            {"nodes", std::move(nodes)}};
}

nlohmann::json treeMetricsToJson(const TreeMetrics& m) {
    return {{"nodes", m.nodes},
            {"leaves", m.leaves},
            {"innerNodes", m.innerNodes},
            {"depth", m.depth},
            {"meanLeafDepth", m.meanLeafDepth},
            {"minChildren", m.minChildren},
            {"meanChildren", m.meanChildren},
            {"maxChildren", m.maxChildren},
            {"totalSphereVolume", m.totalSphereVolume},
            {"totalBoxVolume", m.totalBoxVolume},
            {"meanFill", m.meanFill},
            {"meanSpread", m.meanSpread},
            {"maxSpread", m.maxSpread}};
}

} // namespace hlod
