// Thesis tables 6.2-6.6 style statistics, see BakeStats.h for the conventions.
#include "pipeline/proxy/BakeStats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace hlod {

std::size_t meshBytes(std::size_t vertices, std::size_t indices, bool uvs, bool colors) {
    const std::size_t perVertex = 12 + 12 + (uvs ? 8 : 0) + (colors ? 4 : 0);
    const std::size_t indexBytes = vertices <= 65535 ? 2 : 4;
    return vertices * perVertex + indices * indexBytes;
}

std::size_t meshBytes(const Mesh& mesh) {
    return meshBytes(mesh.vertexCount(), mesh.indices.size(), !mesh.uvs.empty(),
                     !mesh.colors.empty());
}

std::size_t meshBytes(const ProxyMesh& mesh) {
    return meshBytes(mesh.vertexCount(), mesh.indices.size(), false, true);
}

GeometryStats originalStats(const Scene& scene) {
    GeometryStats s;
    s.version = "Original";
    for (const MeshInstance& inst : scene.instances) {
        const Mesh& m = scene.meshes[inst.mesh];
        s.triangles += m.triangleCount();
        s.vertices += m.vertexCount();
        s.meshes += 1;
        s.bytes += meshBytes(m);
    }
    return s;
}

GeometryStats dlodStats(const DlodSummary& summary) {
    return GeometryStats{"DLOD chain", summary.triangles, summary.vertices, summary.meshes,
                         summary.bytes};
}

GeometryStats hlodStats(const Scene& scene, const ClusterTree& tree, const BakeResult& bake,
                        const std::string& version) {
    GeometryStats s = originalStats(scene);
    s.version = version;
    for (std::size_t id = 0; id < tree.nodes.size() && id < bake.nodes.size(); ++id) {
        if (tree.nodes[id].isLeaf()) continue;
        const ProxyMesh& p = bake.nodes[id].proxy;
        if (p.empty()) continue;
        s.triangles += p.triangleCount();
        s.vertices += p.vertexCount();
        s.meshes += 1;
        s.bytes += meshBytes(p);
    }
    return s;
}

ProxyShare proxyShare(const Scene& scene, const ClusterTree& tree, const BakeResult& bake) {
    ProxyShare share;
    const double original = static_cast<double>(originalStats(scene).triangles);
    if (original <= 0.0) return share;
    share.allProxies = static_cast<double>(bake.proxyTriangles) / original;
    if (tree.root != kNoId && tree.root < bake.nodes.size() && !tree.nodes[tree.root].isLeaf()) {
        share.rootProxy =
            static_cast<double>(bake.nodes[tree.root].proxy.triangleCount()) / original;
    }
    // Original triangles under each node, children before parents (post-order from the root).
    std::vector<double> subtree(tree.nodes.size(), 0.0);
    std::vector<Id> order;
    if (tree.root != kNoId) order.push_back(tree.root);
    for (std::size_t i = 0; i < order.size(); ++i) {
        for (Id c : tree.nodes[order[i]].children)
            order.push_back(c);
    }
    double replaced = 0.0, proxies = 0.0;
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
        const ClusterNode& n = tree.nodes[*it];
        if (n.isLeaf()) {
            const MeshInstance& inst = scene.instances[n.instance];
            subtree[*it] = static_cast<double>(scene.meshes[inst.mesh].triangleCount());
            continue;
        }
        for (Id c : n.children)
            subtree[*it] += subtree[c];
        replaced += subtree[*it];
        proxies += static_cast<double>(bake.nodes[*it].proxy.triangleCount());
    }
    if (replaced > 0.0) share.replaced = proxies / replaced;
    return share;
}

std::vector<LevelRow> levelTable(const Scene& scene, const ClusterTree& tree,
                                 const BakeResult& bake) {
    std::vector<LevelRow> rows(static_cast<std::size_t>(std::max(tree.height(), 0)) + 1);
    std::vector<std::size_t> children(rows.size(), 0);
    for (std::size_t l = 0; l < rows.size(); ++l)
        rows[l].level = static_cast<int>(l);
    for (Id id = 0; id < tree.nodes.size(); ++id) {
        const ClusterNode& n = tree.nodes[id];
        if (n.parent == kNoId && id != tree.root) continue; // not part of the tree
        const auto l = static_cast<std::size_t>(n.level);
        if (l >= rows.size()) continue;
        LevelRow& row = rows[l];
        const bool first = row.nodes == 0;
        ++row.nodes;
        children[l] += n.children.size();
        if (n.isLeaf()) {
            row.triangles += scene.meshes[scene.instances[n.instance].mesh].triangleCount();
            continue;
        }
        const NodeBake& b = bake.nodes[id];
        row.triangles += b.proxy.triangleCount();
        row.budgetMin = first ? b.errorBudget : std::min(row.budgetMin, b.errorBudget);
        row.budgetMax = first ? b.errorBudget : std::max(row.budgetMax, b.errorBudget);
    }
    const double original = static_cast<double>(originalStats(scene).triangles);
    for (std::size_t l = 0; l < rows.size(); ++l) {
        LevelRow& row = rows[l];
        if (row.nodes) row.meanChildren = static_cast<double>(children[l]) / row.nodes;
        row.share = original > 0.0 ? static_cast<double>(row.triangles) / original : 0.0;
    }
    return rows;
}

std::string hlodVersionName(const ClusterTree& tree) {
    switch (tree.volume) {
    case VolumeType::Sphere:
        return "HLOD, sphere";
    case VolumeType::Aabb: {
        char k[32];
        std::snprintf(k, sizeof(k), "%g", tree.k);
        return std::string("HLOD, AABB k=") + k;
    }
    case VolumeType::Octree:
        return "HLOD, octree";
    case VolumeType::Original:
        return "HLOD, original hierarchy";
    }
    return "HLOD";
}

} // namespace hlod
