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

std::vector<MeshSize> meshSizes(const Scene& scene) {
    std::vector<MeshSize> out;
    out.reserve(scene.meshes.size());
    for (const Mesh& m : scene.meshes)
        out.push_back({m.triangleCount(), m.vertexCount(), meshBytes(m)});
    return out;
}

SizeTable sizeTable(const Scene& scene, const BakeResult& bake) {
    SizeTable t;
    t.meshes = meshSizes(scene);
    t.proxies.resize(bake.nodes.size());
    for (std::size_t id = 0; id < bake.nodes.size(); ++id) {
        const ProxyMesh& p = bake.nodes[id].proxy;
        if (!p.empty()) t.proxies[id] = {p.triangleCount(), p.vertexCount(), meshBytes(p)};
    }
    return t;
}

GeometryStats originalStats(const Scene& scene, const SizeTable& sizes) {
    GeometryStats s;
    s.version = "Original";
    for (const MeshInstance& inst : scene.instances) {
        const MeshSize& m = sizes.meshes[inst.mesh];
        s.triangles += m.triangles;
        s.vertices += m.vertices;
        s.meshes += 1;
        s.bytes += m.bytes;
    }
    return s;
}

GeometryStats originalStats(const Scene& scene) {
    return originalStats(scene, SizeTable{meshSizes(scene), {}});
}

GeometryStats dlodStats(const DlodSummary& summary) {
    return GeometryStats{"DLOD chain", summary.triangles, summary.vertices, summary.meshes,
                         summary.bytes};
}

GeometryStats hlodStats(const Scene& scene, const ClusterTree& tree, const SizeTable& sizes,
                        const std::string& version) {
    GeometryStats s = originalStats(scene, sizes);
    s.version = version;
    for (std::size_t id = 0; id < tree.nodes.size() && id < sizes.proxies.size(); ++id) {
        if (tree.nodes[id].isLeaf()) continue;
        const MeshSize& p = sizes.proxies[id];
        if (p.triangles == 0) continue;
        s.triangles += p.triangles;
        s.vertices += p.vertices;
        s.meshes += 1;
        s.bytes += p.bytes;
    }
    return s;
}

GeometryStats hlodStats(const Scene& scene, const ClusterTree& tree, const BakeResult& bake,
                        const std::string& version) {
    return hlodStats(scene, tree, sizeTable(scene, bake), version);
}

ProxyShare proxyShare(const Scene& scene, const ClusterTree& tree, const BakeResult& bake,
                      const SizeTable& sizes) {
    ProxyShare share;
    const double original = static_cast<double>(originalStats(scene, sizes).triangles);
    if (original <= 0.0) return share;
    auto proxyTriangles = [&](Id id) {
        return id < sizes.proxies.size() ? static_cast<double>(sizes.proxies[id].triangles) : 0.0;
    };
    share.allProxies = static_cast<double>(bake.proxyTriangles) / original;
    if (tree.root != kNoId && tree.root < bake.nodes.size() && !tree.nodes[tree.root].isLeaf())
        share.rootProxy = proxyTriangles(tree.root) / original;
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
            subtree[*it] = static_cast<double>(sizes.meshes[inst.mesh].triangles);
            continue;
        }
        for (Id c : n.children)
            subtree[*it] += subtree[c];
        replaced += subtree[*it];
        proxies += proxyTriangles(*it);
    }
    if (replaced > 0.0) share.replaced = proxies / replaced;
    return share;
}

ProxyShare proxyShare(const Scene& scene, const ClusterTree& tree, const BakeResult& bake) {
    return proxyShare(scene, tree, bake, sizeTable(scene, bake));
}

std::vector<LevelRow> levelTable(const Scene& scene, const ClusterTree& tree,
                                 const BakeResult& bake, const SizeTable& sizes) {
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
            row.triangles += sizes.meshes[scene.instances[n.instance].mesh].triangles;
            continue;
        }
        const NodeBake& b = bake.nodes[id];
        row.triangles += id < sizes.proxies.size() ? sizes.proxies[id].triangles : 0;
        row.budgetMin = first ? b.errorBudget : std::min(row.budgetMin, b.errorBudget);
        row.budgetMax = first ? b.errorBudget : std::max(row.budgetMax, b.errorBudget);
    }
    const double original = static_cast<double>(originalStats(scene, sizes).triangles);
    for (std::size_t l = 0; l < rows.size(); ++l) {
        LevelRow& row = rows[l];
        if (row.nodes) row.meanChildren = static_cast<double>(children[l]) / row.nodes;
        row.share = original > 0.0 ? static_cast<double>(row.triangles) / original : 0.0;
    }
    return rows;
}

std::vector<LevelRow> levelTable(const Scene& scene, const ClusterTree& tree,
                                 const BakeResult& bake) {
    return levelTable(scene, tree, bake, sizeTable(scene, bake));
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
