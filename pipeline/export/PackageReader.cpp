// Reads a package written by PackageWriter back: hlod.json gives the tree; every referenced
// content file is checked to be a safe relative path that exists.
#include <fstream>

#include "pipeline/core/Error.h"
#include "pipeline/export/Package.h"
#include "pipeline/io/Import.h"

namespace hlod {

namespace fs = std::filesystem;

namespace {

nlohmann::json readJson(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(ErrorCode::Malformed, file, "missing from the package");
    try {
        return nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        throw Error(ErrorCode::Malformed, file, std::string("bad JSON: ") + e.what());
    }
}

glm::dvec3 vec3(const nlohmann::json& j) {
    return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}

void checkContentPath(const fs::path& dir, const fs::path& manifest, const std::string& rel) {
    const fs::path p(rel);
    bool unsafe = p.is_absolute() || rel.find('\\') != std::string::npos;
    for (const auto& part : p)
        unsafe |= part == "..";
    if (unsafe || !isInsideFolder(dir / p, dir)) {
        throw Error(ErrorCode::UnsafePath, manifest,
                    "content path '" + rel + "' leaves the package");
    }
    std::error_code ec;
    if (!fs::is_regular_file(dir / p, ec)) {
        throw Error(ErrorCode::Malformed, manifest, "content file '" + rel + "' is missing");
    }
}

ClusterNode readNode(const nlohmann::json& j, std::size_t count) {
    ClusterNode n;
    n.parent = j.at("parent").is_null() ? kNoId : j.at("parent").get<Id>();
    n.children = j.at("children").get<std::vector<Id>>();
    n.level = j.at("level").get<int>();
    n.box.min = vec3(j.at("box").at("min"));
    n.box.max = vec3(j.at("box").at("max"));
    n.sphere.center = vec3(j.at("sphere").at("center"));
    n.sphere.radius = j.at("sphere").at("radius").get<double>();
    if (j.contains("instance")) n.instance = j.at("instance").get<Id>();
    if ((n.parent != kNoId && n.parent >= count)) throw std::out_of_range("parent id");
    for (Id c : n.children) {
        if (c >= count) throw std::out_of_range("child id");
    }
    return n;
}

} // namespace

bool isPackageFolder(const fs::path& dir) {
    std::error_code ec;
    return fs::is_directory(dir, ec) && fs::is_regular_file(dir / "hlod.json", ec) &&
           fs::is_regular_file(dir / "tileset.json", ec);
}

PackageInfo readPackage(const fs::path& dirIn) {
    PackageInfo info;
    info.dir = fs::absolute(dirIn).lexically_normal();
    const fs::path manifestFile = info.dir / "hlod.json";
    info.manifest = readJson(manifestFile);
    const nlohmann::json tileset = readJson(info.dir / "tileset.json");
    if (info.manifest.value("format", "") != "hlod-studio-package") {
        throw Error(ErrorCode::Malformed, manifestFile, "not an HLOD Studio package manifest");
    }
    if (tileset.value("asset", nlohmann::json::object()).value("version", "") != "1.1") {
        throw Error(ErrorCode::Malformed, info.dir / "tileset.json", "not a 3D Tiles 1.1 tileset");
    }
    try {
        const auto& nodes = info.manifest.at("nodes");
        info.tree.root = info.manifest.at("root").get<Id>();
        info.tree.volume = volumeTypeFromString(info.manifest.at("volume").get<std::string>());
        info.tree.k = info.manifest.value("k", 0.0);
        for (const auto& j : nodes) {
            info.tree.nodes.push_back(readNode(j, nodes.size()));
            info.content.push_back(j.at("content").get<std::string>());
            const auto tris = j.at("triangles").get<std::size_t>();
            (info.tree.nodes.back().isLeaf() ? info.leafTriangles : info.proxyTriangles) += tris;
        }
        if (info.tree.root >= info.tree.nodes.size()) throw std::out_of_range("root id");
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(ErrorCode::Malformed, manifestFile, std::string("bad tree: ") + e.what());
    }
    for (const std::string& rel : info.content) {
        if (!rel.empty()) checkContentPath(info.dir, manifestFile, rel);
    }
    return info;
}

Scene readPackageScene(const PackageInfo& info) {
    Scene scene;
    scene.nodes[0].name = info.dir.filename().string();
    const auto& nodes = info.manifest.at("nodes");
    for (Id i = 0; i < info.tree.nodes.size(); ++i) {
        if (!info.tree.nodes[i].isLeaf() || info.content[i].empty()) continue;
        Scene tile = importGltf(info.dir / info.content[i], ImportOptions{});
        tile.sourceFiles.clear();
        scene.append(std::move(tile), nodes[i].value("name", "leaf " + std::to_string(i)));
    }
    scene.sourceFiles.push_back(info.dir);
    validateScene(scene, info.dir);
    return scene;
}

} // namespace hlod
