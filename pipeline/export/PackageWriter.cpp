// Writes the package of Package.h: tile contents, tileset.json, hlod.json, all into a
// temporary sibling folder that is renamed into place at the end.
#include <fstream>
#include <random>

#include <unistd.h>

#include "pipeline/core/Error.h"
#include "pipeline/export/Package.h"
#include "pipeline/export/TileContent.h"

namespace hlod {

namespace fs = std::filesystem;

namespace {

void writeText(const fs::path& file, const std::string& text) {
    std::ofstream out(file, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw Error(ErrorCode::Io, file, "cannot write the file");
}

nlohmann::json vec(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

nlohmann::json manifestNodes(const Scene& scene, const ClusterTree& tree, const BakeResult& bake,
                             const std::vector<TileStats>& stats) {
    nlohmann::json nodes = nlohmann::json::array();
    for (Id i = 0; i < tree.nodes.size(); ++i) {
        const ClusterNode& n = tree.nodes[i];
        const NodeBake& b = bake.nodes[i];
        nlohmann::json j = {
            {"id", i},
            {"parent", n.parent == kNoId ? nlohmann::json() : nlohmann::json(n.parent)},
            {"children", n.children},
            {"level", n.level},
            {"box", {{"min", vec(n.box.min)}, {"max", vec(n.box.max)}}},
            {"sphere", {{"center", vec(n.sphere.center)}, {"radius", n.sphere.radius}}},
            {"diameter", b.diameter},
            {"errorBudget", n.isLeaf() ? 0.0 : b.errorBudget},
            {"switchDistance", b.switchDistance},
            {"triangles", stats[i].triangles},
            {"vertices", stats[i].vertices},
            {"content", stats[i].triangles ? "tiles/" + std::to_string(i) + ".glb" : ""}};
        if (n.isLeaf()) {
            const MeshInstance& inst = scene.instances[n.instance];
            j["instance"] = n.instance;
            j["name"] = scene.nodes[inst.node].name;
            j["mesh"] = scene.meshes[inst.mesh].name;
            j["material"] = scene.materials[scene.meshes[inst.mesh].material].name;
        }
        nodes.push_back(std::move(j));
    }
    return nodes;
}

fs::path siblingTemp(const fs::path& dir, const char* tag) {
    std::random_device rd;
    return dir.parent_path() / ("." + dir.filename().string() + tag + std::to_string(getpid()) +
                                "-" + std::to_string(rd()));
}

// Replaces `dir` by `tmp`; an existing package is moved aside first and removed only once the
// new one is in place (restored if the final rename fails).
void commitFolder(const fs::path& tmp, const fs::path& dir) {
    std::error_code ec;
    fs::path old;
    if (fs::exists(dir, ec)) {
        old = siblingTemp(dir, ".old-");
        fs::rename(dir, old, ec);
        if (ec)
            throw Error(ErrorCode::Io, dir, "cannot replace the existing folder: " + ec.message());
    }
    fs::rename(tmp, dir, ec);
    if (ec) {
        if (!old.empty()) fs::rename(old, dir);
        throw Error(ErrorCode::Io, dir, "cannot move the package into place: " + ec.message());
    }
    if (!old.empty()) fs::remove_all(old, ec);
}

} // namespace

PackageSummary writePackage(const fs::path& dirIn, const Scene& scene, const ClusterTree& tree,
                            const BakeResult& bake, const BakeParams& bakeParams,
                            const PackageOptions& options, const Progress& progress) {
    const fs::path dir = fs::absolute(dirIn).lexically_normal();
    if (tree.root == kNoId || bake.nodes.size() != tree.nodes.size()) {
        throw Error(ErrorCode::InvalidArgument, "package: the proxies do not match the tree");
    }
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) {
        throw Error(ErrorCode::Io, dir, "exists and is not a folder");
    }
    fs::create_directories(dir.parent_path(), ec);
    const fs::path tmp = siblingTemp(dir, ".tmp-");
    PackageSummary summary;
    try {
        fs::create_directories(tmp / "tiles");
        std::vector<TileStats> stats(tree.nodes.size());
        std::vector<bool> hasContent(tree.nodes.size(), false);
        TextureCache textures(scene, tmp / "tiles");
        for (Id i = 0; i < tree.nodes.size(); ++i) {
            progress.throwIfCancelled();
            const fs::path file = tmp / "tiles" / (std::to_string(i) + ".glb");
            stats[i] =
                tree.nodes[i].isLeaf()
                    ? writeLeafContent(file, scene, tree.nodes[i].instance, textures)
                    : writeProxyContent(file, bake.nodes[i].proxy, "proxy " + std::to_string(i));
            hasContent[i] = stats[i].triangles > 0;
            summary.bytes += stats[i].bytes;
            summary.files += hasContent[i] ? 1 : 0;
            progress.emit({"export", i + 1, tree.nodes.size(), ""});
        }
        summary.bytes += textures.bytesWritten();
        summary.files += textures.filesWritten();
        const nlohmann::json tileset = buildTileset(tree, bake, hasContent, options.geo);
        writeText(tmp / "tileset.json", tileset.dump(1));
        const ScreenParams& sp = bakeParams.screen;
        nlohmann::json manifest = {{"format", "hlod-studio-package"},
                                   {"formatVersion", 1},
                                   {"generator", std::string("HLOD Studio ") + HLOD_VERSION},
                                   {"source", {{"inputs", options.inputs}}},
                                   {"contentUpAxis", "Y"},
                                   {"screen",
                                    {{"screenSizePx", sp.screenSize},
                                     {"pixelError", sp.pixelError},
                                     {"fovYDegrees", sp.fovYDegrees},
                                     {"viewportHeightPx", sp.viewportHeight},
                                     {"maximumScreenSpaceError", sp.pixelError}}},
                                   {"volume", toString(tree.volume)},
                                   {"k", tree.k},
                                   {"proxyMethod", toString(bakeParams.method)},
                                   {"parameters", options.parameters},
                                   {"statistics", options.statistics},
                                   {"root", tree.root},
                                   {"nodes", manifestNodes(scene, tree, bake, stats)}};
        writeText(tmp / "hlod.json", manifest.dump(1));
        progress.throwIfCancelled();
        commitFolder(tmp, dir);
    } catch (...) {
        fs::remove_all(tmp, ec);
        throw;
    }
    summary.tiles = tree.nodes.size();
    summary.files += 2;
    return summary;
}

} // namespace hlod
