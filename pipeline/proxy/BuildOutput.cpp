// Build folder writer (tree JSON + proxy GLBs), written aside and swapped in; see BuildOutput.h.
#include "pipeline/proxy/BuildOutput.h"

#include <fstream>

#include <unistd.h>

#include "pipeline/core/Error.h"
#include "pipeline/io/GlbWriter.h"
#include "pipeline/proxy/ContentHash.h"

namespace hlod {

namespace {

constexpr const char* kFormat = "hlod-build";

nlohmann::json vec3(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

std::string proxyFile(Id id) { return "proxies/node_" + std::to_string(id) + ".glb"; }

nlohmann::json statsJson(const GeometryStats& s) {
    return {{"version", s.version},
            {"triangles", s.triangles},
            {"vertices", s.vertices},
            {"meshes", s.meshes},
            {"bytes", s.bytes}};
}

nlohmann::json nodeJson(const Scene& scene, const ClusterTree& tree, const BakeResult& bake,
                        const BuildInfo& info, Id id) {
    const ClusterNode& n = tree.nodes[id];
    const NodeBake& b = bake.nodes[id];
    nlohmann::json j = {
        {"id", id},
        {"parent", n.parent == kNoId ? nlohmann::json() : nlohmann::json(n.parent)},
        {"children", n.children},
        {"level", n.level},
        {"box", {{"min", vec3(n.box.min)}, {"max", vec3(n.box.max)}}},
        {"sphere", {{"center", vec3(n.sphere.center)}, {"radius", n.sphere.radius}}},
        {"diameter", b.diameter},
        {"geometric_error", b.errorBudget},
        {"screen_size", info.bake.screen.screenSize},
        {"switch_distance", b.switchDistance}};
    if (n.isLeaf()) {
        if (n.instance != kNoId) {
            const MeshInstance& inst = scene.instances[n.instance];
            j["instance"] = n.instance;
            j["mesh"] = scene.meshes[inst.mesh].name;
            j["triangles"] = scene.meshes[inst.mesh].triangleCount();
            j["name"] = scene.nodes[inst.node].name;
        }
        return j;
    }
    j["proxy"] = b.proxy.empty() ? nlohmann::json() : nlohmann::json(proxyFile(id));
    j["proxy_origin"] = vec3(b.frame.origin);
    if (b.frame.turned()) { // the frame's rotation, column-major (BakeFrame.h)
        nlohmann::json r = nlohmann::json::array();
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k)
                r.push_back(b.frame.rotation[c][k]);
        j["proxy_rotation"] = std::move(r);
    }
    j["proxy_triangles"] = b.proxy.triangleCount();
    j["proxy_vertices"] = b.proxy.vertexCount();
    j["input_triangles"] = b.inputTriangles;
    j["key"] = toHex(b.key);
    j["reused"] = b.reused;
    return j;
}

// Refuses to replace a folder that is not empty and not a previous build.
void checkReplaceable(const std::filesystem::path& dir) {
    std::error_code ec;
    if (!std::filesystem::exists(dir, ec)) return;
    if (!std::filesystem::is_directory(dir, ec)) {
        throw Error(ErrorCode::InvalidArgument, dir, "output exists and is not a folder");
    }
    if (std::filesystem::is_empty(dir, ec)) return;
    std::ifstream in(dir / "tree.json");
    const nlohmann::json previous = nlohmann::json::parse(in, nullptr, false);
    if (previous.is_discarded() || !previous.is_object() ||
        previous.value("format", "") != kFormat) {
        throw Error(
            ErrorCode::InvalidArgument, dir,
            "output folder is not empty and holds no previous hlod build; refusing to replace it");
    }
}

std::uintmax_t writeContents(const std::filesystem::path& dir, const ClusterTree& tree,
                             const BakeResult& bake, const nlohmann::json& doc) {
    std::uintmax_t bytes = 0;
    std::filesystem::create_directories(dir / "proxies");
    for (Id id = 0; id < tree.nodes.size(); ++id) {
        const ProxyMesh& p = bake.nodes[id].proxy;
        if (tree.nodes[id].isLeaf() || p.empty()) continue;
        GlbMesh m;
        m.name = "node_" + std::to_string(id);
        // The writer places a mesh by a translation: a turned frame's rotation goes into the
        // positions and normals.
        const RigidFrame& frame = bake.nodes[id].frame;
        std::vector<glm::vec3> positions, normals;
        for (const glm::vec3& v : p.positions)
            positions.push_back(glm::vec3(frame.rotation * glm::dvec3(v)));
        for (const glm::vec3& n : p.normals)
            normals.push_back(glm::vec3(frame.rotation * glm::dvec3(n)));
        m.translation = frame.origin;
        m.positions = positions;
        m.normals = normals;
        m.colors = p.colors;
        m.indices = p.indices;
        writeGlbFile(dir / proxyFile(id), m);
        bytes += std::filesystem::file_size(dir / proxyFile(id));
    }
    const std::string text = doc.dump(1);
    std::ofstream out(dir / "tree.json", std::ios::binary);
    out << text << "\n";
    out.flush();
    if (!out) throw Error(ErrorCode::Io, dir / "tree.json", "cannot write");
    return bytes + text.size() + 1;
}

} // namespace

nlohmann::json buildTreeJson(const Scene& scene, const ClusterTree& tree, const BakeResult& bake,
                             const BuildInfo& info, bool withNodes) {
    nlohmann::json doc;
    doc["format"] = kFormat;
    doc["format_version"] = 1;
    doc["generator"] = std::string("HLOD Studio ") + HLOD_VERSION;
    doc["inputs"] = info.inputs;
    doc["units"] = "m";
    doc["parameters"] = {{"cluster", info.clusterParameters},
                         {"proxy", toString(info.bake.method)},
                         {"screen_size", info.bake.screen.screenSize},
                         {"pixel_error", info.bake.screen.pixelError},
                         {"fov_y_degrees", info.bake.screen.fovYDegrees},
                         {"viewport_height", info.bake.screen.viewportHeight},
                         {"proxy_ratio", info.bake.proxyRatio}};
    doc["root"] = tree.root == kNoId ? nlohmann::json() : nlohmann::json(tree.root);
    nlohmann::json nodes = nlohmann::json::array();
    for (Id id = 0; withNodes && id < tree.nodes.size(); ++id)
        nodes.push_back(nodeJson(scene, tree, bake, info, id));
    if (withNodes) doc["nodes"] = std::move(nodes);
    nlohmann::json stats = nlohmann::json::array();
    for (const GeometryStats& s : info.statistics)
        stats.push_back(statsJson(s));
    doc["statistics"] = std::move(stats);
    doc["proxy_share"] = {{"all_proxies", info.share.allProxies},
                          {"root_proxy", info.share.rootProxy},
                          {"replaced", info.share.replaced}};
    nlohmann::json levels = nlohmann::json::array();
    for (const LevelRow& r : info.levels)
        levels.push_back({{"level", r.level},
                          {"nodes", r.nodes},
                          {"mean_children", r.meanChildren},
                          {"error_budget_min", r.budgetMin},
                          {"error_budget_max", r.budgetMax},
                          {"triangles", r.triangles},
                          {"share", r.share}});
    doc["levels"] = std::move(levels);
    doc["bake"] = {{"inner_nodes", bake.innerNodes},
                   {"baked", bake.baked},
                   {"reused", bake.reused},
                   {"dissolved", bake.dissolved},
                   {"input_triangles", bake.inputTriangles},
                   {"proxy_triangles", bake.proxyTriangles},
                   {"seconds", bake.seconds}};
    return doc;
}

std::uintmax_t writeBuildFolder(const std::filesystem::path& dir, const Scene& scene,
                                const ClusterTree& tree, const BakeResult& bake,
                                const BuildInfo& info) {
    const std::filesystem::path target = std::filesystem::absolute(dir).lexically_normal();
    const std::filesystem::path clean = target.has_filename() ? target : target.parent_path();
    checkReplaceable(clean);
    const std::string suffix = "." + std::to_string(::getpid());
    std::filesystem::path partial = clean;
    partial += ".partial" + suffix;
    std::filesystem::path old = clean;
    old += ".old" + suffix;
    std::error_code ec;
    std::filesystem::remove_all(partial, ec);
    std::uintmax_t bytes = 0;
    try {
        bytes = writeContents(partial, tree, bake, buildTreeJson(scene, tree, bake, info));
        if (std::filesystem::exists(clean)) std::filesystem::rename(clean, old);
        std::filesystem::rename(partial, clean);
    } catch (const std::filesystem::filesystem_error& e) {
        std::filesystem::remove_all(partial, ec);
        if (!std::filesystem::exists(clean, ec) && std::filesystem::exists(old, ec)) {
            std::filesystem::rename(old, clean, ec);
        }
        throw Error(ErrorCode::Io, e.path1().empty() ? clean : e.path1(), e.code().message());
    } catch (...) {
        std::filesystem::remove_all(partial, ec);
        throw;
    }
    std::filesystem::remove_all(old, ec);
    return bytes;
}

} // namespace hlod
