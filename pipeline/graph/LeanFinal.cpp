// The lean final step of a distributed bake: the plan's, the shards' and the final build's part
// (see LeanFinal.h).
#include "pipeline/graph/LeanFinal.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

#include "pipeline/cluster/ClusterTreeBinary.h"
#include "pipeline/core/AtomicFile.h"
#include "pipeline/core/Error.h"
#include "pipeline/export/DiskUsage.h"
#include "pipeline/export/Package.h"
#include "pipeline/export/PackageLayout.h"
#include "pipeline/export/Placement.h"
#include "pipeline/export/TileContent.h"
#include "pipeline/graph/BakePlan.h"
#include "pipeline/graph/PlanFiles.h"
#include "pipeline/proxy/BakeStats.h"
#include "pipeline/proxy/ContentHash.h"
#include "pipeline/proxy/ProxyCache.h"
#include "pipeline/proxy/ProxyEconomy.h"
#include "pipeline/proxy/ProxyLook.h"
#include "pipeline/scene/SceneBinary.h"

namespace hlod {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr const char* kTopScene = "top.scene";
constexpr const char* kSizes = "sizes.bin";

std::string tilesName(int index) { return "shard-" + std::to_string(index) + ".tiles"; }

// ---- JSON of the values a layout and a bake decision hold (doubles round-trip exactly) ----

json vec3(const glm::dvec3& v) { return {v.x, v.y, v.z}; }
glm::dvec3 vec3(const json& j) {
    return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}

// A square matrix, column-major.
template <int N> json matrix(const glm::mat<N, N, double>& m) {
    json a = json::array();
    for (int c = 0; c < N; ++c)
        for (int r = 0; r < N; ++r)
            a.push_back(m[c][r]);
    return a;
}
template <int N> glm::mat<N, N, double> matrix(const json& j) {
    glm::mat<N, N, double> m(1.0);
    for (int c = 0; c < N; ++c)
        for (int r = 0; r < N; ++r)
            m[c][r] = j.at(static_cast<std::size_t>(c * N + r)).get<double>();
    return m;
}
json mat3(const glm::dmat3& m) { return matrix<3>(m); }
glm::dmat3 mat3(const json& j) { return matrix<3>(j); }
json mat4(const glm::dmat4& m) { return matrix<4>(m); }
glm::dmat4 mat4(const json& j) { return matrix<4>(j); }
json box(const Aabb& b) {
    if (b.empty()) return nullptr;
    return {b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z};
}
Aabb box(const json& j) {
    Aabb b;
    if (j.is_null()) return b;
    b.expand(glm::dvec3(j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()));
    b.expand(glm::dvec3(j.at(3).get<double>(), j.at(4).get<double>(), j.at(5).get<double>()));
    return b;
}
json look(const ProxyLookSums& s) {
    return {s.doubleSided ? 1 : 0, s.area, vec3(s.emissiveOverBase), vec3(s.emissive)};
}
ProxyLookSums look(const json& j) {
    ProxyLookSums s;
    s.doubleSided = j.at(0).get<int>() != 0;
    s.area = j.at(1).get<double>();
    s.emissiveOverBase = vec3(j.at(2));
    s.emissive = vec3(j.at(3));
    return s;
}
json idJson(Id id) { return id == kNoId ? json() : json(id); }
Id idFrom(const json& j) { return j.is_null() ? kNoId : j.get<Id>(); }

json placementJson(const Placement& p) {
    return {{"center", vec3(p.center)},    {"radius", p.radius},       {"sceneUp", vec3(p.sceneUp)},
            {"eye", vec3(p.eye)},          {"target", vec3(p.target)}, {"up", vec3(p.up)},
            {"fovYDegrees", p.fovYDegrees}};
}
Placement placementFrom(const json& j) {
    Placement p;
    p.center = vec3(j.at("center"));
    p.radius = j.at("radius").get<double>();
    p.sceneUp = vec3(j.at("sceneUp"));
    p.eye = vec3(j.at("eye"));
    p.target = vec3(j.at("target"));
    p.up = vec3(j.at("up"));
    p.fovYDegrees = j.at("fovYDegrees").get<double>();
    return p;
}

// A file's size and content hash (read in pieces: a scene file may be large).
json fingerprint(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return {{"path", file.string()}, {"bytes", -1}, {"hash", ""}};
    std::vector<char> buf(4u << 20);
    std::uint64_t h = 0, bytes = 0;
    while (in) {
        in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
        const auto n = static_cast<std::size_t>(in.gcount());
        if (n == 0) break;
        h = hashBytes(buf.data(), n, h);
        bytes += n;
    }
    return {{"path", file.string()}, {"bytes", bytes}, {"hash", toHex(h)}};
}

std::vector<fs::path> filesOf(const Scene& scene) {
    std::vector<fs::path> files = scene.sourceFiles;
    files.insert(files.end(), scene.referencedFiles.begin(), scene.referencedFiles.end());
    return files;
}

json sourcesJson(const std::vector<fs::path>& sources) {
    json a = json::array();
    for (const fs::path& p : sources)
        a.push_back(p.lexically_normal().string());
    return a;
}

// A leaf that hangs from a node above the cut, or an inner node whose parent is above the cut:
// the leaves below `id`.
void leavesBelow(const ClusterTree& tree, Id id, std::vector<Id>& out) {
    if (tree.nodes[id].isLeaf()) {
        out.push_back(id);
        return;
    }
    for (Id c : tree.nodes[id].children)
        leavesBelow(tree, c, out);
}

// The bytes of `file`, empty when it cannot be read.
std::string fileBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return {};
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool sameFileBytes(const fs::path& file, const std::vector<std::uint8_t>& bytes) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec) || fs::file_size(file, ec) != bytes.size()) return false;
    const std::string have = fileBytes(file);
    return have.size() == bytes.size() && std::memcmp(have.data(), bytes.data(), bytes.size()) == 0;
}

// A tile a shard wrote: present, and its bytes hash to its name ("tiles/HASH.glb").
void checkTile(const fs::path& cacheDir, const std::string& uri, const fs::path& fragment,
               int shard, int shards) {
    const fs::path file = cacheDir / uri;
    const std::string again = ": run hlod build --shard " + std::to_string(shard) + "/" +
                              std::to_string(shards) + " --cache " + cacheDir.string() + " again";
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) {
        throw Error(ErrorCode::FileNotFound, file,
                    "is missing (a tile " + fragment.filename().string() + " names)" + again);
    }
    const std::string bytes = fileBytes(file);
    const std::string name = fs::path(uri).stem().string();
    if (toHex(hashBytes(bytes.data(), bytes.size())) != name)
        throw Error(ErrorCode::Malformed, file,
                    "is damaged (its bytes do not match its name)" + again);
}

Error malformed(const fs::path& file, const std::string& what) {
    return Error(ErrorCode::Malformed, file, what + " (run the shard again)");
}

// A 64-bit key written as hex.
std::uint64_t keyFrom(const json& j, const fs::path& file) {
    const std::string text = j.get<std::string>();
    std::uint64_t v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v, 16);
    if (ec != std::errc() || end != text.data() + text.size() || text.empty())
        throw malformed(file, "holds a key that is not hexadecimal");
    return v;
}

// Node ids of the plan's tree.
std::vector<Id> idsFrom(const json& j, std::size_t nodes, const fs::path& file) {
    std::vector<Id> ids = j.get<std::vector<Id>>();
    for (Id id : ids)
        if (id >= nodes) throw malformed(file, "names a node not in the tree");
    return ids;
}

// A block's tiles and contents refer to each other by index: all in range, tile 0 the root.
void checkBlock(const PackageLayout& layout, const fs::path& file) {
    const auto tiles = static_cast<int>(layout.tiles.size());
    const auto contents = static_cast<int>(layout.contents.size());
    bool ok = tiles > 0 && layout.tiles[0].parent == -1;
    for (std::size_t i = 0; ok && i < layout.tiles.size(); ++i) {
        const TilePlan& t = layout.tiles[i];
        ok = t.content >= -1 && t.content < contents &&
             (i == 0 || (t.parent >= 0 && t.parent < tiles));
        for (int c : t.children)
            ok = ok && c > 0 && c < tiles;
    }
    for (int t : layout.tileOfNode)
        ok = ok && t >= -1 && t < tiles;
    if (!ok) throw malformed(file, "holds a layout whose tiles do not fit together");
}

} // namespace

// ------------------------------------------------------------------------------------------
// The plan

nlohmann::json writeLeanPlan(const fs::path& folder, const Scene& scene, const ClusterTree& tree,
                             const ShardPlan& shards, const LeanInputs& in) {
    if (!scene.textures.empty() || tree.root == kNoId || tree.nodes[tree.root].isLeaf())
        return nullptr;
    for (const Material& m : scene.materials)
        if (m.texture != kNoId || m.emissiveTexture != kNoId || !m.baseColorTexture.empty())
            return nullptr;
    std::vector<char> top(tree.nodes.size(), 0);
    for (Id id : shards.top)
        top[id] = 1;
    if (!top[tree.root]) return nullptr;
    // The meshes of the leaves hanging from nodes above the cut, and of every leaf below a
    // node above the cut too small for tiles of its own (its leaves join its parent's group).
    std::vector<std::size_t> triangles(tree.nodes.size(), 0);
    for (Id id : childrenFirst(tree, {tree.root})) {
        const ClusterNode& node = tree.nodes[id];
        if (node.isLeaf() && node.instance != kNoId)
            triangles[id] = scene.meshes[scene.instances[node.instance].mesh].triangleCount();
        for (Id c : node.children)
            triangles[id] += triangles[c];
    }
    std::vector<char> used(scene.meshes.size(), 0);
    auto use = [&](Id leaf) {
        if (tree.nodes[leaf].instance != kNoId)
            used[scene.instances[tree.nodes[leaf].instance].mesh] = 1;
    };
    for (Id id : shards.top) {
        if (id != tree.root && triangles[id] <= kSmallSubtreeTriangles) {
            std::vector<Id> leaves;
            leavesBelow(tree, id, leaves);
            for (Id l : leaves)
                use(l);
        }
        for (Id c : tree.nodes[id].children)
            if (tree.nodes[c].isLeaf()) use(c);
    }
    plan::writeChecked(folder / kTopScene, writeSceneBinary(sliceScene(scene, used)));
    std::string sizes;
    for (const MeshSize& m : meshSizes(scene))
        for (std::uint64_t v :
             {std::uint64_t(m.triangles), std::uint64_t(m.vertices), std::uint64_t(m.bytes)})
            sizes.append(reinterpret_cast<const char*>(&v), sizeof v);
    plan::writeChecked(folder / kSizes, std::move(sizes));
    json files = json::array();
    for (const fs::path& f : filesOf(scene))
        files.push_back(fingerprint(f));
    return {{"version", HLOD_VERSION},
            {"sources", sourcesJson(in.sources)},
            {"files", files},
            {"import", in.importParams},
            {"cluster", in.clusterParams},
            {"compression", toString(in.compression)},
            {"placement", placementJson(packagePlacement(scene))},
            {"top_scene", kTopScene},
            {"sizes", kSizes}};
}

// ------------------------------------------------------------------------------------------
// A shard

void writeShardTiles(const fs::path& cacheDir, const json& planJson, int index, const Scene& slice,
                     const ClusterTree& tree, const std::vector<Id>& roots, BakeResult bake) {
    const auto leanIt = planJson.find("lean");
    if (leanIt == planJson.end() || leanIt->is_null()) return;
    const GlbCompression compression =
        glbCompressionFromString(leanIt->at("compression").get<std::string>());
    const std::size_t n = tree.nodes.size();
    const std::vector<Id> order = childrenFirst(tree, roots);
    // What a dissolved node hands up (its inputs, ProxyBaker.h) and the triangles below.
    std::vector<std::vector<Id>> standIns(n);
    std::vector<std::size_t> triangles(n, 0);
    for (Id id : order) {
        const ClusterNode& node = tree.nodes[id];
        if (node.isLeaf()) {
            triangles[id] = node.instance == kNoId
                                ? 0
                                : slice.meshes[slice.instances[node.instance].mesh].triangleCount();
            continue;
        }
        for (Id c : node.children) {
            triangles[id] += triangles[c];
            if (!bake.nodes[id].dissolved) continue;
            if (!tree.nodes[c].isLeaf() && bake.nodes[c].dissolved)
                standIns[id].insert(standIns[id].end(), standIns[c].begin(), standIns[c].end());
            else
                standIns[id].push_back(c);
        }
    }
    const std::vector<ProxyLookSums> looks = subtreeLookSums(slice, tree, order);

    json nodes = json::array();
    std::size_t dissolved = 0, inputTriangles = 0, proxyTriangles = 0, proxyVertices = 0;
    for (Id id : order) {
        const ClusterNode& node = tree.nodes[id];
        if (node.isLeaf()) continue;
        const NodeBake& b = bake.nodes[id];
        dissolved += b.dissolved || !b.hasProxy ? 1 : 0;
        inputTriangles += b.inputTriangles;
        const bool kept = !b.dissolved && b.hasProxy && !b.proxy.empty();
        if (kept) {
            proxyTriangles += b.proxy.triangleCount();
            proxyVertices += b.proxy.vertexCount();
        }
        nodes.push_back({{"id", id},
                         {"key", toHex(b.key)},
                         {"d", b.diameter},
                         {"e", b.errorBudget},
                         {"s", b.switchDistance},
                         {"o", vec3(b.frame.origin)},
                         {"r", mat3(b.frame.rotation)},
                         {"x", b.dissolved ? 1 : 0},
                         {"in", b.inputTriangles},
                         {"re", b.reused ? 1 : 0},
                         {"size", kept ? json{b.proxy.triangleCount(), b.proxy.vertexCount(),
                                              meshBytes(b.proxy)}
                                       : json{0, 0, 0}}});
    }

    // The subtrees laid out as the whole tree lays them out: this shard's dissolved nodes
    // removed (ProxyEconomy.h), ids mapped back to the plan tree's.
    // What a root hands up, before the bake's nodes move into the local layout.
    std::vector<std::vector<Id>> ups;
    json handed = json::array();
    for (Id r : roots) {
        ups.push_back(bake.nodes[r].dissolved ? standIns[r] : std::vector<Id>{r});
        // A handed-up leaf's key and frame (a parent above is framed and keyed by them).
        json upLeaves = json::array();
        for (Id x : ups.back())
            if (tree.nodes[x].isLeaf())
                upLeaves.push_back({{"id", x},
                                    {"key", toHex(bake.nodes[x].key)},
                                    {"o", vec3(bake.nodes[x].frame.origin)},
                                    {"r", mat3(bake.nodes[x].frame.rotation)}});
        handed.push_back(
            {{"id", r}, {"up", ups.back()}, {"look", look(looks[r])}, {"up_leaves", upLeaves}});
    }
    const json totals = {{"baked", bake.baked},
                         {"reused", bake.reused},
                         {"damaged", bake.damaged},
                         {"dissolved", dissolved},
                         {"input_triangles", inputTriangles},
                         {"proxy_triangles", proxyTriangles},
                         {"proxy_vertices", proxyVertices}};
    ClusterTree local = tree;
    BakeResult localBake;
    localBake.nodes = std::move(bake.nodes);
    const std::vector<Id> newId = compactDissolved(local, localBake);
    auto toLocal = [&](Id id) { return newId.empty() ? id : newId[id]; };
    std::vector<Id> toPlan(local.nodes.size(), kNoId);
    for (Id id = 0; id < n; ++id)
        if (toLocal(id) != kNoId) toPlan[toLocal(id)] = id;
    auto planId = [&](Id id) { return id == kNoId ? kNoId : toPlan[id]; };

    TextureStore textures(slice);
    ContentEncoder encoder(slice, localBake, textures, compression);
    std::map<std::uint64_t, json> byKey; // content key -> its JSON (uri, leaves, counts)
    const fs::path store = cacheDir / "tiles";
    json blocks = json::array(), leaves = json::array(), handedLooks = json::object();
    for (const std::vector<Id>& up : ups) {
        for (Id x : up) {
            if (tree.nodes[x].isLeaf()) {
                leaves.push_back(x);
                continue;
            }
            handedLooks[std::to_string(x)] = look(looks[x]);
            if (triangles[x] <= kSmallSubtreeTriangles) { // shown by the parent's leaf group
                std::vector<Id> below;
                leavesBelow(tree, x, below);
                for (Id l : below)
                    leaves.push_back(l);
                continue;
            }
            const PackageLayout layout = planSubtree(slice, local, localBake, toLocal(x));
            json tiles = json::array(), contents = json::array(), tileOf = json::array();
            for (const TilePlan& t : layout.tiles)
                tiles.push_back({{"node", idJson(planId(t.node))},
                                 {"content", t.content},
                                 {"parent", t.parent},
                                 {"children", t.children},
                                 {"frame", mat4(t.frame)},
                                 {"error", t.geometricError},
                                 {"box", box(t.worldBox)}});
            for (const ContentPlan& c : layout.contents) {
                const std::uint64_t key = contentKey(c, localBake, slice);
                auto it = byKey.find(key);
                if (it == byKey.end()) {
                    const EncodedContent e = encoder.encode(c);
                    const std::string uri =
                        "tiles/" + toHex(hashBytes(e.bytes.data(), e.bytes.size())) + ".glb";
                    std::error_code ec;
                    if (!sameFileBytes(cacheDir / uri, e.bytes)) { // a damaged copy is replaced
                        fs::create_directories(store, ec);
                        writeFileAtomic(
                            cacheDir / uri,
                            std::string_view(reinterpret_cast<const char*>(e.bytes.data()),
                                             e.bytes.size()));
                    }
                    json where = json::array();
                    for (const LeafInContent& l : e.leaves)
                        where.push_back({l.node, l.merged ? 1 : 0, l.firstVertex, l.vertexCount,
                                         l.firstIndex, l.indexCount});
                    it = byKey
                             .emplace(key, json{{"uri", uri},
                                                {"where", where},
                                                {"triangles", e.triangles},
                                                {"vertices", e.vertices},
                                                {"pe", e.positionError}})
                             .first;
                }
                json content = it->second;
                json leafIds = json::array();
                for (const LeafSlot& s : c.leaves)
                    leafIds.push_back(planId(s.leaf));
                content["proxy"] = c.proxy;
                content["node"] = idJson(planId(c.node));
                content["leaves"] = leafIds;
                contents.push_back(std::move(content));
            }
            for (Id id = 0; id < layout.tileOfNode.size(); ++id)
                if (layout.tileOfNode[id] >= 0)
                    tileOf.push_back({planId(id), layout.tileOfNode[id]});
            blocks.push_back(
                {{"root", x}, {"tiles", tiles}, {"contents", contents}, {"tile_of", tileOf}});
        }
    }
    if (!textures.files().empty()) {
        throw Error(ErrorCode::InvalidArgument,
                    "the lean final step cannot take textured tiles (plan.json says the scene has "
                    "no textures)");
    }
    const json fragment = {{"plan", planJson.at("id")}, {"shard", index},       {"nodes", nodes},
                           {"handed", handed},          {"looks", handedLooks}, {"leaves", leaves},
                           {"blocks", blocks},          {"totals", totals}};
    plan::writeChecked(planFolder(cacheDir) / tilesName(index), fragment.dump());
}

// ------------------------------------------------------------------------------------------
// The final build

LeanCheck checkLeanPlan(const LeanFinalRequest& r) {
    LeanCheck c;
    std::error_code ec;
    const fs::path folder = planFolder(r.cacheDir);
    if (r.cacheDir.empty() || !fs::exists(folder / plan::kPlanFile, ec)) return c;
    json planJson;
    try {
        planJson = plan::readPlanJson(r.cacheDir);
    } catch (const Error&) {
        return c; // the classic check names the problem
    }
    const auto lean = planJson.find("lean");
    if (lean == planJson.end() || !lean->is_object()) return c;
    try {
        const BakeParams params = bakeParamsFrom(r.bakeValues);
        const BakeParams planned =
            bakeParamsFrom(paramsFromJson(NodeKind::Bake, planJson.at("bake")));
        if (lean->at("version") != HLOD_VERSION ||
            lean->at("sources") != sourcesJson(r.given.sources) ||
            lean->at("import") != r.given.importParams ||
            lean->at("cluster") != r.given.clusterParams ||
            lean->at("compression") != toString(r.given.compression) ||
            bakeParamsKey(params) != bakeParamsKey(planned))
            return c;
        for (const json& f : lean->at("files"))
            if (fingerprint(f.at("path").get<std::string>()) != f) return c;
    } catch (const std::exception&) {
        return c;
    }
    c.lean = true;
    c.id = planJson.at("id").get<std::string>();
    c.shards = planJson.at("shards").get<int>();
    c.aboveCut = planJson.value("above_cut", json::array()).size();
    for (int i = 0; i < c.shards; ++i) {
        const fs::path marker = folder / plan::markerName(i);
        bool ok = false;
        if (fs::exists(marker, ec) && fs::exists(folder / tilesName(i), ec)) {
            std::ifstream in(marker);
            const json m = json::parse(in, nullptr, false);
            ok = m.is_object() && m.value("plan", std::string()) == c.id &&
                 m.value("shard", -1) == i;
        }
        if (!ok) c.missing.push_back(i);
    }
    return c;
}

namespace {

// One shard's part as the final step reads it.
struct ShardPart {
    std::vector<Id> leaves; // leaves the final step needs the meshes of
};

// A block of shard tiles in the plan tree's ids, and its contents' files.
struct Block {
    PackageLayout layout;
    std::vector<GivenContent> contents;
};

} // namespace

LeanFinalResult runLeanFinal(const LeanFinalRequest& r, const Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    const fs::path folder = planFolder(r.cacheDir);
    const json planJson = plan::readPlanJson(r.cacheDir);
    const fs::path planFile = folder / plan::kPlanFile;
    const std::string planIdText = planJson.at("id").get<std::string>();
    const json& lean = planJson.at("lean");
    const int shards = planJson.at("shards").get<int>();
    BakeParams params = bakeParamsFrom(r.bakeValues);
    params.threads = r.threads;
    params.cacheDir = r.cacheDir;

    ClusterTree tree = readClusterTreeBinary(plan::readChecked(folder / plan::kTreeFile),
                                             folder / plan::kTreeFile);
    Scene scene = readSceneBinary(plan::readChecked(folder / kTopScene), folder / kTopScene);
    SizeTable sizes;
    {
        const std::string bytes = plan::readChecked(folder / kSizes);
        if (bytes.size() != scene.meshes.size() * 3 * sizeof(std::uint64_t))
            throw Error(ErrorCode::Malformed, folder / kSizes, "does not match the plan's scene");
        std::vector<std::uint64_t> v(bytes.size() / sizeof(std::uint64_t));
        std::memcpy(v.data(), bytes.data(), bytes.size());
        for (std::size_t m = 0; m < scene.meshes.size(); ++m)
            sizes.meshes.push_back({v[3 * m], v[3 * m + 1], v[3 * m + 2]});
    }
    const std::size_t n = tree.nodes.size();

    // Every shard's decisions, hand-ups and blocks.
    std::vector<NodeBake> nodes(n);
    std::vector<MeshSize> proxySize(n);
    BakeBelow below;
    below.given.assign(n, 0);
    below.standIns.resize(n);
    below.looks.resize(n);
    std::map<Id, Block> blocks;
    std::size_t dissolved = 0, inputTriangles = 0, proxyTriangles = 0, proxyVertices = 0,
                damaged = 0, shardBaked = 0, shardReused = 0;
    std::vector<std::vector<Id>> neededLeaves(static_cast<std::size_t>(shards));
    std::set<std::string> checked; // tiles verified
    for (int i = 0; i < shards; ++i) {
        progress.throwIfCancelled();
        const fs::path file = folder / tilesName(i);
        const json frag = json::parse(plan::readChecked(file), nullptr, false);
        if (frag.is_discarded() || !frag.is_object() ||
            frag.value("plan", std::string()) != planIdText)
            throw malformed(file,
                            "is not shard " + std::to_string(i) + "'s part of plan " + planIdText);
        try {
            for (const json& j : frag.at("nodes")) {
                const Id node = j.at("id").get<Id>();
                if (node >= n || tree.nodes[node].isLeaf())
                    throw malformed(file, "names a node not in the tree");
                NodeBake& b = nodes[node];
                b.key = keyFrom(j.at("key"), file);
                b.diameter = j.at("d").get<double>();
                b.errorBudget = j.at("e").get<double>();
                b.switchDistance = j.at("s").get<double>();
                b.frame = {vec3(j.at("o")), mat3(j.at("r"))};
                b.proxy.origin = b.frame.origin;
                b.dissolved = j.at("x").get<int>() != 0;
                b.inputTriangles = j.at("in").get<std::size_t>();
                b.reused = j.at("re").get<int>() != 0;
                const json& s = j.at("size");
                proxySize[node] = {s.at(0).get<std::size_t>(), s.at(1).get<std::size_t>(),
                                   s.at(2).get<std::size_t>()};
            }
            const std::vector<Id> planned = planJson.at("shard_list")
                                                .at(static_cast<std::size_t>(i))
                                                .at("roots")
                                                .get<std::vector<Id>>();
            if (frag.at("handed").size() != planned.size())
                throw malformed(file, "does not hold the shard's subtrees");
            for (const json& h : frag.at("handed")) {
                const Id root = h.at("id").get<Id>();
                if (std::find(planned.begin(), planned.end(), root) == planned.end() || root >= n ||
                    tree.nodes[root].isLeaf())
                    throw malformed(file, "names a subtree that is not the shard's");
                std::vector<Id> stack{root};
                while (!stack.empty()) { // everything below the cut here is the shard's
                    const Id at = stack.back();
                    stack.pop_back();
                    below.given[at] = 1;
                    for (Id c : tree.nodes[at].children)
                        stack.push_back(c);
                }
                if (nodes[root].dissolved) below.standIns[root] = idsFrom(h.at("up"), n, file);
                below.looks[root] = look(h.at("look"));
                for (const json& l : h.at("up_leaves")) {
                    const Id leaf = l.at("id").get<Id>();
                    if (leaf >= n || !tree.nodes[leaf].isLeaf())
                        throw malformed(file, "names a leaf not in the tree");
                    NodeBake& b = nodes[leaf];
                    b.key = keyFrom(l.at("key"), file);
                    b.frame = {vec3(l.at("o")), mat3(l.at("r"))};
                    b.proxy.origin = b.frame.origin;
                }
            }
            for (const auto& [key, value] : frag.at("looks").items()) {
                Id node = kNoId;
                const auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), node);
                if (ec != std::errc() || end != key.data() + key.size() || node >= n)
                    throw malformed(file, "names a node not in the tree");
                below.looks[node] = look(value);
            }
            neededLeaves[static_cast<std::size_t>(i)] = idsFrom(frag.at("leaves"), n, file);
            for (const json& b : frag.at("blocks")) {
                Block block;
                for (const json& t : b.at("tiles")) {
                    TilePlan tile;
                    tile.node = idFrom(t.at("node"));
                    if (tile.node != kNoId && tile.node >= n)
                        throw malformed(file, "names a node not in the tree");
                    tile.content = t.at("content").get<int>();
                    tile.parent = t.at("parent").get<int>();
                    tile.children = t.at("children").get<std::vector<int>>();
                    tile.frame = mat4(t.at("frame"));
                    tile.geometricError = t.at("error").get<double>();
                    tile.worldBox = box(t.at("box"));
                    block.layout.tiles.push_back(std::move(tile));
                }
                for (const json& c : b.at("contents")) {
                    ContentPlan plan;
                    plan.proxy = c.at("proxy").get<bool>();
                    plan.node = idFrom(c.at("node"));
                    if (plan.node != kNoId && plan.node >= n)
                        throw malformed(file, "names a node not in the tree");
                    for (Id leaf : idsFrom(c.at("leaves"), n, file)) {
                        LeafSlot slot;
                        slot.leaf = leaf;
                        plan.leaves.push_back(slot);
                    }
                    GivenContent given;
                    given.uri = c.at("uri").get<std::string>();
                    if (given.uri.rfind("tiles/", 0) != 0 ||
                        given.uri.find("..") != std::string::npos)
                        throw malformed(file, "names a tile outside the cache");
                    given.file = r.cacheDir / given.uri;
                    if (checked.insert(given.uri).second)
                        checkTile(r.cacheDir, given.uri, file, i, shards);
                    given.encoded.triangles = c.at("triangles").get<std::size_t>();
                    given.encoded.vertices = c.at("vertices").get<std::size_t>();
                    given.encoded.positionError = c.at("pe").get<double>();
                    for (const json& w : c.at("where")) {
                        LeafInContent in;
                        in.node = w.at(0).get<int>();
                        in.merged = w.at(1).get<int>() != 0;
                        in.firstVertex = w.at(2).get<std::size_t>();
                        in.vertexCount = w.at(3).get<std::size_t>();
                        in.firstIndex = w.at(4).get<std::size_t>();
                        in.indexCount = w.at(5).get<std::size_t>();
                        given.encoded.leaves.push_back(in);
                    }
                    if (given.encoded.leaves.size() != plan.leaves.size())
                        throw malformed(file, "is inconsistent");
                    block.layout.contents.push_back(std::move(plan));
                    block.contents.push_back(std::move(given));
                }
                block.layout.tileOfNode.assign(n, -1);
                for (const json& p : b.at("tile_of")) {
                    const Id node = p.at(0).get<Id>();
                    if (node >= n) throw malformed(file, "names a node not in the tree");
                    block.layout.tileOfNode[node] = p.at(1).get<int>();
                }
                checkBlock(block.layout, file);
                const Id root = b.at("root").get<Id>();
                if (root >= n || tree.nodes[root].isLeaf())
                    throw malformed(file, "names a node not in the tree");
                blocks.emplace(root, std::move(block));
            }
            const json& t = frag.at("totals");
            shardBaked += t.at("baked").get<std::size_t>();
            shardReused += t.at("reused").get<std::size_t>();
            damaged += t.at("damaged").get<std::size_t>();
            dissolved += t.at("dissolved").get<std::size_t>();
            inputTriangles += t.at("input_triangles").get<std::size_t>();
            proxyTriangles += t.at("proxy_triangles").get<std::size_t>();
            proxyVertices += t.at("proxy_vertices").get<std::size_t>();
        } catch (const json::exception& e) {
            throw malformed(file, std::string("is incomplete: ") + e.what());
        }
    }

    // The meshes of the leaves handed up, from the shards' slices (one at a time).
    for (int i = 0; i < shards; ++i) {
        const std::vector<Id>& leaves = neededLeaves[static_cast<std::size_t>(i)];
        if (leaves.empty()) continue;
        const fs::path file = folder / plan::sliceName(i);
        Scene slice = readSceneBinary(plan::readChecked(file), file);
        if (slice.meshes.size() != scene.meshes.size())
            throw Error(ErrorCode::Malformed, file, "does not match the plan's scene");
        for (Id l : leaves) {
            if (l >= n || !tree.nodes[l].isLeaf() || tree.nodes[l].instance == kNoId) continue;
            const Id mesh = scene.instances.at(tree.nodes[l].instance).mesh;
            if (scene.meshes[mesh].indices.empty())
                scene.meshes[mesh] = std::move(slice.meshes[mesh]);
        }
    }
    // The proxies the nodes above are baked from: the kept nodes the shards hand up.
    const ProxyCache cache(r.cacheDir);
    for (Id top = 0; top < n; ++top) {
        if (below.given[top] || tree.nodes[top].isLeaf()) continue;
        for (Id c : tree.nodes[top].children) {
            if (!below.given[c] || tree.nodes[c].isLeaf()) continue;
            const std::vector<Id> up = nodes[c].dissolved ? below.standIns[c] : std::vector<Id>{c};
            for (Id x : up) {
                if (x >= n || tree.nodes[x].isLeaf() || !nodes[x].proxy.empty()) continue;
                bool bad = false;
                std::optional<ProxyMesh> p = cache.load(nodes[x].key, &bad);
                if (!p) {
                    throw Error(ErrorCode::FileNotFound, r.cacheDir,
                                std::string("the proxy of node ") + std::to_string(x) + " is " +
                                    (bad ? "damaged" : "missing") +
                                    " (run hlod build --shard again for the shard that baked it)");
                }
                nodes[x].proxy = std::move(*p);
                nodes[x].proxy.origin = nodes[x].frame.origin;
            }
        }
    }

    BakeResult bake = bakeAbove(scene, tree, std::move(nodes), below, params, progress);
    // The whole bake's counts: the shards' and this step's (BakeStats, the manifest).
    bake.dissolved += dissolved;
    bake.inputTriangles += inputTriangles;
    bake.proxyTriangles += proxyTriangles;
    bake.proxyVertices += proxyVertices;
    bake.damaged += damaged;
    for (Id id = 0; id < n; ++id) {
        const NodeBake& b = bake.nodes[id];
        if (!below.given[id] && !tree.nodes[id].isLeaf() && !b.dissolved && b.hasProxy &&
            !b.proxy.empty())
            proxySize[id] = {b.proxy.triangleCount(), b.proxy.vertexCount(), meshBytes(b.proxy)};
        // Proxies below the cut were read only to bake the nodes above: the package takes
        // the shards' tiles.
        if (below.given[id]) bake.nodes[id].proxy = ProxyMesh{b.frame.origin, {}, {}, {}, {}};
    }
    const std::vector<Id> newId = compactDissolved(tree, bake);
    auto finalId = [&](Id id) { return id == kNoId || newId.empty() ? id : newId[id]; };
    bake.innerNodes = 0;
    for (const ClusterNode& node : tree.nodes)
        bake.innerNodes += node.isLeaf() ? 0 : 1;
    sizes.proxies.assign(tree.nodes.size(), MeshSize{});
    for (Id id = 0; id < n; ++id)
        if (finalId(id) != kNoId) sizes.proxies[finalId(id)] = proxySize[id];

    // The blocks in the final tree's ids.
    LayoutBlocks layoutBlocks;
    std::map<Id, const Block*> blockOf; // by final root id
    for (auto& [root, block] : blocks) {
        for (TilePlan& t : block.layout.tiles)
            t.node = finalId(t.node);
        for (ContentPlan& c : block.layout.contents) {
            c.node = finalId(c.node);
            for (LeafSlot& s : c.leaves)
                s.leaf = finalId(s.leaf);
        }
        std::vector<int> tileOf(tree.nodes.size(), -1);
        for (Id id = 0; id < n; ++id)
            if (block.layout.tileOfNode[id] >= 0 && finalId(id) != kNoId)
                tileOf[finalId(id)] = block.layout.tileOfNode[id];
        block.layout.tileOfNode = std::move(tileOf);
        layoutBlocks.byRoot[finalId(root)] = &block.layout;
        blockOf[finalId(root)] = &block;
    }
    for (const MeshSize& m : sizes.meshes)
        layoutBlocks.meshTriangles.push_back(m.triangles);
    const PackageLayout layout = planPackage(scene, tree, bake, layoutBlocks);
    for (std::size_t i = 0; i < layout.contents.size(); ++i) {
        const ContentSource& s = layout.sources[i];
        if (s.block != kNoId && !blockOf.count(s.block))
            throw Error(ErrorCode::Malformed, planFile, "a shard's tiles do not match the tree");
    }

    LeanFinalResult out;
    const HandEdits edits;
    const BuildInputs in{scene, tree, bake, r.cluster, edits, params, r.inputs, &sizes};
    ExportOptions options;
    options.output = r.output;
    options.dlod = false;
    options.geo = r.geo;
    options.compression = r.given.compression;
    out.export_.output = r.output;
    out.export_.info = makeBuildInfo(in, false);
    const auto writeStart = std::chrono::steady_clock::now();
    const PackageParts parts{layout,
                             [&](const ContentSource& s) -> const GivenContent& {
                                 return blockOf.at(s.block)->contents.at(
                                     static_cast<std::size_t>(s.index));
                             },
                             sizes, placementFrom(lean.at("placement"))};
    out.export_.written =
        writePackage(r.output, scene, tree, bake, params,
                     packageOptionsFor(in, out.export_.info, options), parts, progress);
    out.export_.writeSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - writeStart).count();
    out.export_.source = sourceFootprint(scene);
    out.shardBaked = shardBaked;
    out.shardReused = shardReused;
    out.tree = std::move(tree);
    out.bake = std::move(bake);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

} // namespace hlod
