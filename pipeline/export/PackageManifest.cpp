// hlod.json, format 2 (see PackageManifest.h).
#include "pipeline/export/PackageManifest.h"

#include <map>

#include "pipeline/export/JsonNumbers.h"

namespace hlod {

namespace {

nlohmann::json vec(const glm::dvec3& v) {
    return {shortNumber(v.x), shortNumber(v.y), shortNumber(v.z)};
}

nlohmann::json frameJson(const glm::dmat4& m) {
    glm::dmat4 t(1.0);
    t[3] = m[3];
    if (t == m) return {{"translation", {m[3][0], m[3][1], m[3][2]}}};
    nlohmann::json a = nlohmann::json::array();
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            a.push_back(m[c][r]);
    }
    return {{"matrix", std::move(a)}};
}

nlohmann::json tilesJson(const ManifestInput& in, const std::vector<int>& fileOfContent) {
    nlohmann::json tiles = nlohmann::json::array();
    for (const TilePlan& t : in.layout.tiles) {
        nlohmann::json j = frameJson(t.frame);
        j["node"] = t.node == kNoId ? nlohmann::json() : nlohmann::json(t.node);
        j["parent"] = t.parent;
        j["file"] = t.content < 0 ? -1 : fileOfContent[static_cast<std::size_t>(t.content)];
        j["positionError"] =
            t.content < 0
                ? 0.0
                : shortNumberUp(in.encoded[static_cast<std::size_t>(t.content)].positionError);
        tiles.push_back(std::move(j));
    }
    return tiles;
}

nlohmann::json meshesJson(const Scene& scene, const SizeTable* sizes) {
    nlohmann::json meshes = nlohmann::json::array();
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        const Mesh& m = scene.meshes[i];
        meshes.push_back({{"name", m.name},
                          {"material", scene.materials[m.material].name},
                          {"triangles", sizes ? sizes->meshes[i].triangles : m.triangleCount()},
                          {"vertices", sizes ? sizes->meshes[i].vertices : m.vertexCount()}});
    }
    return meshes;
}

nlohmann::json innerNode(const ManifestInput& in, Id i) {
    const ClusterNode& n = in.tree.nodes[i];
    const NodeBake& b = in.bake.nodes[i];
    // A node inside a subtree too small to matter has no tile (nor proxy) of its own.
    const int tile = in.layout.tileOfNode[i];
    const MeshSize size = in.sizes ? in.sizes->proxies[i]
                                   : MeshSize{b.proxy.triangleCount(), b.proxy.vertexCount(), 0};
    const bool shown = b.hasProxy && size.triangles > 0 &&
                       in.layout.tiles[static_cast<std::size_t>(tile)].node == i;
    return {
        {"parent", n.parent == kNoId ? nlohmann::json() : nlohmann::json(n.parent)},
        {"children", n.children},
        {"level", n.level},
        {"box", {{"min", vec(n.box.min)}, {"max", vec(n.box.max)}}},
        {"sphere", {{"center", vec(n.sphere.center)}, {"radius", shortNumberUp(n.sphere.radius)}}},
        {"diameter", shortNumber(b.diameter)},
        {"errorBudget", shortNumber(b.errorBudget)},
        {"switchDistance", shortNumber(b.switchDistance)},
        {"triangles", shown ? size.triangles : 0},
        {"vertices", shown ? size.vertices : 0},
        {"tile", in.layout.tileOfNode[i]}};
}

nlohmann::json leafNode(const ManifestInput& in, Id i, const LeafInContent& where) {
    const ClusterNode& n = in.tree.nodes[i];
    const MeshInstance& inst = in.scene.instances[n.instance];
    nlohmann::json j = {{"parent", n.parent == kNoId ? nlohmann::json() : nlohmann::json(n.parent)},
                        {"children", nlohmann::json::array()},
                        {"instance", n.instance},
                        {"name", in.scene.nodes[inst.node].name},
                        {"mesh", inst.mesh},
                        {"tile", in.layout.tileOfNode[i]},
                        {"contentNode", where.node}};
    if (where.merged)
        j["contentRange"] = {where.firstVertex, where.vertexCount, where.firstIndex,
                             where.indexCount};
    return j;
}

} // namespace

nlohmann::json buildManifest(const ManifestInput& in) {
    // Files: content plans whose bytes are equal share one.
    std::vector<std::string> files;
    std::map<std::string, int> fileIndex;
    std::vector<int> fileOfContent;
    for (const std::string& uri : in.contentUris) {
        auto [it, added] = fileIndex.try_emplace(uri, static_cast<int>(files.size()));
        if (added) files.push_back(uri);
        fileOfContent.push_back(it->second);
    }
    // Where each leaf is inside its content.
    std::vector<LeafInContent> where(in.tree.nodes.size());
    for (std::size_t c = 0; c < in.layout.contents.size(); ++c) {
        const ContentPlan& plan = in.layout.contents[c];
        for (std::size_t s = 0; s < plan.leaves.size(); ++s)
            where[plan.leaves[s].leaf] = in.encoded[c].leaves[s];
    }
    nlohmann::json nodes = nlohmann::json::array();
    for (Id i = 0; i < in.tree.nodes.size(); ++i)
        nodes.push_back(in.tree.nodes[i].isLeaf() ? leafNode(in, i, where[i]) : innerNode(in, i));
    const ScreenParams& sp = in.bakeParams.screen;
    return {{"format", "hlod-studio-package"},
            {"formatVersion", 2},
            {"generator", std::string("HLOD Studio ") + HLOD_VERSION},
            {"source", {{"inputs", in.options.inputs}}},
            {"contentUpAxis", "Y"},
            {"screen",
             {{"screenSizePx", sp.screenSize},
              {"pixelError", sp.pixelError},
              {"fovYDegrees", sp.fovYDegrees},
              {"viewportHeightPx", sp.viewportHeight},
              {"maximumScreenSpaceError", sp.pixelError}}},
            {"volume", toString(in.tree.volume)},
            {"k", in.tree.k},
            {"proxyMethod", toString(in.bakeParams.method)},
            {"compression", toString(in.options.compression)},
            {"parameters", in.options.parameters},
            {"statistics", in.options.statistics},
            {"root", in.tree.root},
            {"files", files},
            {"tiles", tilesJson(in, fileOfContent)},
            {"meshes", meshesJson(in.scene, in.sizes)},
            {"nodes", std::move(nodes)}};
}

} // namespace hlod
