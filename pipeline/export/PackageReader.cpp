// Reads a package written by PackageWriter back: hlod.json gives the tree and where every
// leaf's geometry is; every referenced content file is checked to be a safe relative path that
// exists. Format 2 (PackageManifest.h) and the older format 1 (one GLB per node, "content" per
// node) are both read.
#include <fstream>
#include <limits>
#include <map>
#include <memory>

#include "pipeline/core/Error.h"
#include "pipeline/export/Package.h"
#include "pipeline/io/Import.h"

namespace hlod {

namespace fs = std::filesystem;

namespace {

nlohmann::json readJson(const fs::path& file) {
    // A folder opens as a stream on Linux, and reading it throws std::ios_base::failure from
    // the stream buffer (found by fuzz_package: a section named "hlod.json/").
    std::error_code ec;
    if (fs::exists(file, ec) && !fs::is_regular_file(file, ec))
        throw Error(ErrorCode::Malformed, file, "is not a file");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(ErrorCode::Malformed, file, "missing from the package");
    try {
        return nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        throw Error(ErrorCode::Malformed, file, std::string("bad JSON: ") + e.what());
    } catch (const std::ios_base::failure& e) {
        throw Error(ErrorCode::Io, file, std::string("cannot be read: ") + e.what());
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

// A non-negative integer that fits T. nlohmann's get<integer>() casts floats and negative
// numbers as they are (1e300 to unsigned is undefined behaviour, -1 a huge id; found by
// fuzz_package), so ids, counts and indices are read through this. Throws std::out_of_range
// (readPackage turns it into Error naming hlod.json).
template <typename T> T whole(const nlohmann::json& j) {
    if (j.is_number_unsigned()) {
        const auto v = j.get<std::uint64_t>();
        if (v <= std::numeric_limits<T>::max()) return static_cast<T>(v);
    } else if (j.is_number_integer()) {
        const auto v = j.get<std::int64_t>();
        if (v >= 0 && static_cast<std::uint64_t>(v) <= std::numeric_limits<T>::max())
            return static_cast<T>(v);
    }
    throw std::out_of_range("expected a non-negative integer, got " + j.dump());
}

ClusterNode readNode(const nlohmann::json& j, std::size_t count) {
    ClusterNode n;
    n.parent = j.at("parent").is_null() ? kNoId : whole<Id>(j.at("parent"));
    for (const auto& c : j.at("children"))
        n.children.push_back(whole<Id>(c));
    n.level = j.contains("level") ? whole<int>(j.at("level")) : 0;
    if (j.contains("box")) {
        n.box.min = vec3(j.at("box").at("min"));
        n.box.max = vec3(j.at("box").at("max"));
    }
    if (j.contains("sphere")) {
        n.sphere.center = vec3(j.at("sphere").at("center"));
        n.sphere.radius = j.at("sphere").at("radius").get<double>();
    }
    if (j.contains("instance")) n.instance = whole<Id>(j.at("instance"));
    if ((n.parent != kNoId && n.parent >= count)) throw std::out_of_range("parent id");
    for (Id c : n.children) {
        if (c >= count) throw std::out_of_range("child id");
    }
    return n;
}

// Structure only (bounds are the writer's business): the root has no parent, every child link
// agrees with the child's parent, no node has two parents and every node hangs under the root,
// so walks over the tree (height, leaves) end. Throws std::out_of_range.
void checkStructure(const ClusterTree& t) {
    const std::size_t n = t.nodes.size();
    if (t.nodes[t.root].parent != kNoId) throw std::out_of_range("the root has a parent");
    std::vector<char> linked(n, 0);
    for (Id i = 0; i < n; ++i) {
        for (Id c : t.nodes[i].children) {
            if (c == t.root || t.nodes[c].parent != i || linked[c]++ != 0)
                throw std::out_of_range("parent and child links disagree at node " +
                                        std::to_string(c));
        }
    }
    std::vector<Id> stack{t.root};
    std::size_t reached = 0;
    while (!stack.empty()) {
        const Id id = stack.back();
        stack.pop_back();
        ++reached;
        for (Id c : t.nodes[id].children)
            stack.push_back(c);
    }
    if (reached != n) throw std::out_of_range("some nodes are not under the root");
}

// The file of node `j` in a format-2 manifest ("" when it has none).
std::string contentOf(const nlohmann::json& m, const nlohmann::json& j) {
    if (!j.contains("tile")) return {};
    const nlohmann::json& tile = m.at("tiles").at(whole<std::size_t>(j.at("tile")));
    const nlohmann::json& fileIndex = tile.at("file");
    if (fileIndex.is_number_integer() && fileIndex.get<std::int64_t>() < 0) return {};
    const auto file = whole<std::size_t>(fileIndex);
    const bool leaf = j.at("children").empty();
    if (!leaf && !tile.at("node").is_number()) return {}; // a node shown by no tile of its own
    return m.at("files").at(file).get<std::string>();
}

void readTree(PackageInfo& info) {
    const nlohmann::json& m = info.manifest;
    const auto& nodes = m.at("nodes");
    const bool v2 = m.value("formatVersion", 1) >= 2;
    info.tree.root = whole<Id>(m.at("root"));
    info.tree.volume = volumeTypeFromString(m.at("volume").get<std::string>());
    info.tree.k = m.value("k", 0.0);
    for (const auto& j : nodes) {
        info.tree.nodes.push_back(readNode(j, nodes.size()));
        info.content.push_back(v2 ? contentOf(m, j) : j.at("content").get<std::string>());
        const bool leaf = info.tree.nodes.back().isLeaf();
        std::size_t tris = 0;
        if (v2 && leaf)
            tris = whole<std::size_t>(
                m.at("meshes").at(whole<std::size_t>(j.at("mesh"))).at("triangles"));
        else
            tris = whole<std::size_t>(j.at("triangles"));
        (leaf ? info.leafTriangles : info.proxyTriangles) += tris;
    }
    if (info.tree.root >= info.tree.nodes.size()) throw std::out_of_range("root id");
    checkStructure(info.tree);
}

} // namespace

bool isPackageFolder(const fs::path& dir) {
    std::error_code ec;
    return fs::is_directory(dir, ec) && fs::is_regular_file(dir / "hlod.json", ec) &&
           fs::is_regular_file(dir / "tileset.json", ec);
}

// The string under `key`, or "" when `j` is no object or the value no string (json::value
// throws on both, and a mutated manifest must be refused with a message naming the file; found
// by fuzz_package).
namespace {

std::string textOf(const nlohmann::json& j, const char* key) {
    if (!j.is_object()) return {};
    const auto it = j.find(key);
    return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
}

} // namespace

PackageInfo readPackage(const fs::path& dirIn) {
    PackageInfo info;
    info.dir = fs::absolute(dirIn).lexically_normal();
    const fs::path manifestFile = info.dir / "hlod.json";
    info.manifest = readJson(manifestFile);
    const nlohmann::json tileset = readJson(info.dir / "tileset.json");
    if (textOf(info.manifest, "format") != "hlod-studio-package") {
        throw Error(ErrorCode::Malformed, manifestFile, "not an HLOD Studio package manifest");
    }
    const nlohmann::json none;
    const nlohmann::json& asset =
        tileset.is_object() && tileset.contains("asset") ? tileset["asset"] : none;
    if (textOf(asset, "version") != "1.1") {
        throw Error(ErrorCode::Malformed, info.dir / "tileset.json", "not a 3D Tiles 1.1 tileset");
    }
    try {
        readTree(info);
    } catch (const Error& e) {
        // e.g. volumeTypeFromString's InvalidArgument, which names no file.
        if (!e.file().empty()) throw;
        throw Error(ErrorCode::Malformed, manifestFile, "bad tree: " + e.problem());
    } catch (const std::exception& e) {
        throw Error(ErrorCode::Malformed, manifestFile, std::string("bad tree: ") + e.what());
    }
    for (const std::string& rel : info.content) {
        if (!rel.empty()) checkContentPath(info.dir, manifestFile, rel);
    }
    return info;
}

namespace {

// A content file of a format-2 package, imported once, and what the output scene took from it.
struct LoadedFile {
    Scene scene;
    std::map<Id, Id> meshes;    // file mesh -> output mesh (instanced leaves share it)
    std::map<Id, Id> materials; // file material -> output material
};

Id outputMaterial(LoadedFile& f, Id material, Scene& out) {
    auto [it, added] = f.materials.try_emplace(material, 0);
    if (added) it->second = out.addMaterial(f.scene.materials[material]);
    return it->second;
}

// Vertices [first, first + count) and indices [firstIndex, firstIndex + indexCount) of `m`.
Mesh sliceMesh(const Mesh& m, const nlohmann::json& range, const fs::path& manifest) {
    const auto fv = whole<std::size_t>(range.at(0)), nv = whole<std::size_t>(range.at(1));
    const auto fi = whole<std::size_t>(range.at(2)), ni = whole<std::size_t>(range.at(3));
    if (fv > m.vertexCount() || nv > m.vertexCount() - fv || fi > m.indices.size() ||
        ni > m.indices.size() - fi || ni % 3 != 0)
        throw Error(ErrorCode::Malformed, manifest, "a contentRange lies outside its primitive");
    Mesh s;
    s.name = m.name;
    s.material = m.material;
    auto part = [&](const auto& v, auto& out) {
        if (!v.empty()) out.assign(v.begin() + long(fv), v.begin() + long(fv + nv));
    };
    part(m.positions, s.positions);
    part(m.normals, s.normals);
    part(m.uvs, s.uvs);
    part(m.colors, s.colors);
    for (std::size_t i = fi; i < fi + ni; ++i) {
        if (m.indices[i] < fv || m.indices[i] >= fv + nv)
            throw Error(ErrorCode::Malformed, manifest,
                        "a contentRange's index leaves its vertices");
        s.indices.push_back(m.indices[i] - static_cast<std::uint32_t>(fv));
    }
    return s;
}

glm::dmat4 tileFrame(const nlohmann::json& tile) {
    glm::dmat4 f(1.0);
    if (tile.contains("matrix")) {
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                f[c][r] = tile.at("matrix").at(std::size_t(c * 4 + r)).get<double>();
    } else {
        f[3] = glm::dvec4(vec3(tile.at("translation")), 1.0);
    }
    return f;
}

Scene readScene2(const PackageInfo& info) {
    const fs::path manifest = info.dir / "hlod.json";
    const nlohmann::json& m = info.manifest;
    Scene out;
    out.nodes[0].name = info.dir.filename().string();
    std::map<std::string, std::unique_ptr<LoadedFile>> files;
    const auto& nodes = m.at("nodes");
    for (Id i = 0; i < info.tree.nodes.size(); ++i) {
        if (!info.tree.nodes[i].isLeaf() || info.content[i].empty()) continue;
        const nlohmann::json& j = nodes[i];
        std::unique_ptr<LoadedFile>& f = files[info.content[i]];
        if (!f) {
            f = std::make_unique<LoadedFile>();
            f->scene = importGltf(info.dir / info.content[i], ImportOptions{});
        }
        // Our files are flat: glTF node k is the importer's node k + 1 (0 is its root).
        const Id gltfNode = whole<Id>(j.at("contentNode")) + 1;
        if (gltfNode >= f->scene.nodes.size())
            throw Error(ErrorCode::Malformed, manifest, "a contentNode does not exist");
        const glm::dmat4 world = tileFrame(m.at("tiles").at(whole<std::size_t>(j.at("tile")))) *
                                 f->scene.nodes[gltfNode].world;
        const Id node = out.addNode(j.value("name", "leaf " + std::to_string(i)), 0, world);
        for (const MeshInstance& inst : f->scene.instances) {
            if (inst.node != gltfNode) continue;
            const Mesh& src = f->scene.meshes[inst.mesh];
            Id mesh;
            if (j.contains("contentRange")) {
                Mesh s = sliceMesh(src, j.at("contentRange"), manifest);
                s.material = outputMaterial(*f, src.material, out);
                mesh = out.addMesh(std::move(s));
            } else {
                auto [it, added] = f->meshes.try_emplace(inst.mesh, 0);
                if (added) {
                    Mesh copy = src;
                    copy.material = outputMaterial(*f, src.material, out);
                    it->second = out.addMesh(std::move(copy));
                }
                mesh = it->second;
            }
            out.addInstance(mesh, node);
        }
    }
    out.updateWorldTransforms();
    return out;
}

Scene readScene1(const PackageInfo& info) {
    Scene scene;
    scene.nodes[0].name = info.dir.filename().string();
    const auto& nodes = info.manifest.at("nodes");
    for (Id i = 0; i < info.tree.nodes.size(); ++i) {
        if (!info.tree.nodes[i].isLeaf() || info.content[i].empty()) continue;
        Scene tile = importGltf(info.dir / info.content[i], ImportOptions{});
        tile.sourceFiles.clear();
        tile.referencedFiles.clear();
        scene.append(std::move(tile), nodes[i].value("name", "leaf " + std::to_string(i)));
    }
    return scene;
}

} // namespace

Scene readPackageScene(const PackageInfo& info) {
    Scene scene;
    try {
        scene = info.manifest.value("formatVersion", 1) >= 2 ? readScene2(info) : readScene1(info);
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(ErrorCode::Malformed, info.dir / "hlod.json",
                    std::string("bad tree: ") + e.what());
    }
    scene.sourceFiles.push_back(info.dir);
    validateScene(scene, info.dir);
    return scene;
}

} // namespace hlod
