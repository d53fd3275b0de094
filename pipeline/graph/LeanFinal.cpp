// The final build's part of the lean final step (LeanFinal.h): recognising its plan, reading
// the shards' parts, baking the nodes above the cut and writing the package.
#include "pipeline/graph/LeanFinal.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstring>
#include <map>
#include <set>

#include "pipeline/cluster/ClusterTreeBinary.h"
#include "pipeline/core/AtomicFile.h"
#include "pipeline/core/Error.h"
#include "pipeline/export/DiskUsage.h"
#include "pipeline/export/Package.h"
#include "pipeline/export/PackageLayout.h"
#include "pipeline/graph/BakePlan.h"
#include "pipeline/graph/LeanParts.h"
#include "pipeline/graph/PlanFiles.h"
#include "pipeline/proxy/BakeStats.h"
#include "pipeline/proxy/ContentHash.h"
#include "pipeline/proxy/ProxyCache.h"
#include "pipeline/proxy/ProxyEconomy.h"
#include "pipeline/scene/SceneBinary.h"

namespace hlod {

namespace fs = std::filesystem;
using namespace lean;

namespace {

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

// A node id of the plan's tree.
Id idIn(const json& j, std::size_t nodes, const fs::path& file) {
    const Id id = idFrom(j);
    if (id != kNoId && id >= nodes) throw malformed(file, "names a node not in the tree");
    return id;
}

std::vector<Id> idsFrom(const json& j, std::size_t nodes, const fs::path& file) {
    std::vector<Id> ids;
    for (const json& e : j)
        ids.push_back(idIn(e, nodes, file));
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

// A tile a shard wrote: present, and its bytes hash to its name ("tiles/HASH.glb").
void checkTile(const fs::path& cacheDir, const std::string& uri, const fs::path& part, int shard,
               int shards) {
    const fs::path file = cacheDir / uri;
    const std::string again = ": run hlod build --shard " + std::to_string(shard) + "/" +
                              std::to_string(shards) + " --cache " + cacheDir.string() + " again";
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) {
        throw Error(ErrorCode::FileNotFound, file,
                    "is missing (a tile " + part.filename().string() + " names)" + again);
    }
    const std::string bytes = readFileBytes(file);
    if (toHex(hashBytes(bytes.data(), bytes.size())) != fs::path(uri).stem().string())
        throw Error(ErrorCode::Malformed, file,
                    "is damaged (its bytes do not match its name)" + again);
}

// A block of shard tiles in the plan tree's ids, and its contents' files.
struct Block {
    PackageLayout layout;
    std::vector<GivenContent> contents;
};

// Everything the shards' parts say, in the plan tree's ids.
struct ShardParts {
    std::vector<NodeBake> nodes; // the shards' decisions (inner nodes, handed-up leaves)
    std::vector<MeshSize> proxySize;
    BakeBelow below;
    std::map<Id, Block> blocks;          // by subtree root
    std::vector<std::vector<Id>> leaves; // per shard: leaves whose meshes the final step needs
    std::size_t dissolved = 0, inputTriangles = 0, proxyTriangles = 0, proxyVertices = 0,
                damaged = 0, baked = 0, reused = 0;
    std::set<std::string> checkedTiles;
};

class PartReader {
public:
    PartReader(const fs::path& cacheDir, const json& planJson, const ClusterTree& tree)
        : cacheDir_(cacheDir), plan_(planJson), tree_(tree), n_(tree.nodes.size()),
          shards_(planJson.at("shards").get<int>()) {
        parts_.nodes.resize(n_);
        parts_.proxySize.resize(n_);
        parts_.below.given.assign(n_, 0);
        parts_.below.standIns.resize(n_);
        parts_.below.looks.resize(n_);
        parts_.leaves.resize(static_cast<std::size_t>(shards_));
    }

    ShardParts read(const Progress& progress) {
        for (int i = 0; i < shards_; ++i) {
            progress.throwIfCancelled();
            const fs::path file = planFolder(cacheDir_) / tilesName(i);
            const std::string id = plan_.at("id").get<std::string>();
            const json part = json::parse(plan::readChecked(file), nullptr, false);
            if (part.is_discarded() || !part.is_object() || part.value("plan", std::string()) != id)
                throw malformed(file,
                                "is not shard " + std::to_string(i) + "'s part of plan " + id);
            try {
                readPart(part, i, file);
            } catch (const json::exception& e) {
                throw malformed(file, std::string("is incomplete: ") + e.what());
            }
        }
        return std::move(parts_);
    }

private:
    void readPart(const json& part, int shard, const fs::path& file) {
        for (const json& j : part.at("nodes"))
            readDecision(j, file);
        const std::vector<Id> planned = plan_.at("shard_list")
                                            .at(static_cast<std::size_t>(shard))
                                            .at("roots")
                                            .get<std::vector<Id>>();
        if (part.at("handed").size() != planned.size())
            throw malformed(file, "does not hold the shard's subtrees");
        for (const json& h : part.at("handed"))
            readHandUp(h, planned, file);
        for (const auto& [key, value] : part.at("looks").items()) {
            Id node = kNoId;
            const auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), node);
            if (ec != std::errc() || end != key.data() + key.size() || node >= n_)
                throw malformed(file, "names a node not in the tree");
            parts_.below.looks[node] = look(value);
        }
        parts_.leaves[static_cast<std::size_t>(shard)] = idsFrom(part.at("leaves"), n_, file);
        for (const json& b : part.at("blocks"))
            readBlock(b, shard, file);
        const json& t = part.at("totals");
        parts_.baked += t.at("baked").get<std::size_t>();
        parts_.reused += t.at("reused").get<std::size_t>();
        parts_.damaged += t.at("damaged").get<std::size_t>();
        parts_.dissolved += t.at("dissolved").get<std::size_t>();
        parts_.inputTriangles += t.at("input_triangles").get<std::size_t>();
        parts_.proxyTriangles += t.at("proxy_triangles").get<std::size_t>();
        parts_.proxyVertices += t.at("proxy_vertices").get<std::size_t>();
    }

    void readDecision(const json& j, const fs::path& file) {
        const Id node = idIn(j.at("id"), n_, file);
        if (node == kNoId || tree_.nodes[node].isLeaf())
            throw malformed(file, "names a node not in the tree");
        NodeBake& b = parts_.nodes[node];
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
        parts_.proxySize[node] = {s.at(0).get<std::size_t>(), s.at(1).get<std::size_t>(),
                                  s.at(2).get<std::size_t>()};
    }

    // A subtree root of the shard: everything below it is given; what it hands up.
    void readHandUp(const json& h, const std::vector<Id>& planned, const fs::path& file) {
        const Id root = h.at("id").get<Id>();
        if (std::find(planned.begin(), planned.end(), root) == planned.end() || root >= n_ ||
            tree_.nodes[root].isLeaf())
            throw malformed(file, "names a subtree that is not the shard's");
        for (Id id : childrenFirst(tree_, {root}))
            parts_.below.given[id] = 1;
        if (parts_.nodes[root].dissolved)
            parts_.below.standIns[root] = idsFrom(h.at("up"), n_, file);
        parts_.below.looks[root] = look(h.at("look"));
        for (const json& l : h.at("up_leaves")) {
            const Id leaf = idIn(l.at("id"), n_, file);
            if (leaf == kNoId || !tree_.nodes[leaf].isLeaf())
                throw malformed(file, "names a leaf not in the tree");
            NodeBake& b = parts_.nodes[leaf];
            b.key = keyFrom(l.at("key"), file);
            b.frame = {vec3(l.at("o")), mat3(l.at("r"))};
            b.proxy.origin = b.frame.origin;
        }
    }

    void readBlock(const json& b, int shard, const fs::path& file) {
        Block block;
        for (const json& t : b.at("tiles")) {
            TilePlan tile;
            tile.node = idIn(t.at("node"), n_, file);
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
            plan.node = idIn(c.at("node"), n_, file);
            for (Id leaf : idsFrom(c.at("leaves"), n_, file)) {
                LeafSlot slot;
                slot.leaf = leaf;
                plan.leaves.push_back(slot);
            }
            block.contents.push_back(givenContent(c, shard, file));
            if (block.contents.back().encoded.leaves.size() != plan.leaves.size())
                throw malformed(file, "is inconsistent");
            block.layout.contents.push_back(std::move(plan));
        }
        block.layout.tileOfNode.assign(n_, -1);
        for (const json& p : b.at("tile_of")) {
            const Id node = idIn(p.at(0), n_, file);
            if (node == kNoId) throw malformed(file, "names a node not in the tree");
            block.layout.tileOfNode[node] = p.at(1).get<int>();
        }
        checkBlock(block.layout, file);
        const Id root = idIn(b.at("root"), n_, file);
        if (root == kNoId || tree_.nodes[root].isLeaf())
            throw malformed(file, "names a node not in the tree");
        parts_.blocks.emplace(root, std::move(block));
    }

    GivenContent givenContent(const json& c, int shard, const fs::path& file) {
        GivenContent given;
        given.uri = c.at("uri").get<std::string>();
        if (given.uri.rfind("tiles/", 0) != 0 || given.uri.find("..") != std::string::npos)
            throw malformed(file, "names a tile outside the cache");
        given.file = cacheDir_ / given.uri;
        if (parts_.checkedTiles.insert(given.uri).second)
            checkTile(cacheDir_, given.uri, file, shard, shards_);
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
        return given;
    }

    fs::path cacheDir_;
    const json& plan_;
    const ClusterTree& tree_;
    std::size_t n_;
    int shards_;
    ShardParts parts_;
};

std::vector<MeshSize> readSizes(const fs::path& file, std::size_t meshes) {
    const std::string bytes = plan::readChecked(file);
    if (bytes.size() != meshes * 3 * sizeof(std::uint64_t))
        throw Error(ErrorCode::Malformed, file, "does not match the plan's scene");
    std::vector<std::uint64_t> v(bytes.size() / sizeof(std::uint64_t));
    std::memcpy(v.data(), bytes.data(), bytes.size());
    std::vector<MeshSize> sizes;
    for (std::size_t m = 0; m < meshes; ++m)
        sizes.push_back({v[3 * m], v[3 * m + 1], v[3 * m + 2]});
    return sizes;
}

// The meshes of the leaves the shards hand up, from their slices (one slice at a time).
void loadHandedMeshes(Scene& scene, const ClusterTree& tree, const fs::path& folder,
                      const std::vector<std::vector<Id>>& leaves) {
    for (std::size_t i = 0; i < leaves.size(); ++i) {
        if (leaves[i].empty()) continue;
        const fs::path file = folder / plan::sliceName(static_cast<int>(i));
        Scene slice = readSceneBinary(plan::readChecked(file), file);
        if (slice.meshes.size() != scene.meshes.size())
            throw Error(ErrorCode::Malformed, file, "does not match the plan's scene");
        for (Id l : leaves[i]) {
            if (!tree.nodes[l].isLeaf() || tree.nodes[l].instance == kNoId) continue;
            const Id mesh = scene.instances.at(tree.nodes[l].instance).mesh;
            if (scene.meshes[mesh].indices.empty())
                scene.meshes[mesh] = std::move(slice.meshes[mesh]);
        }
    }
}

// The proxies the nodes above the cut are baked from: the kept nodes the shards hand up.
void loadHandedProxies(ShardParts& parts, const ClusterTree& tree, const fs::path& cacheDir) {
    const ProxyCache cache(cacheDir);
    const BakeBelow& below = parts.below;
    for (Id top = 0; top < tree.nodes.size(); ++top) {
        if (below.given[top] || tree.nodes[top].isLeaf()) continue;
        for (Id c : tree.nodes[top].children) {
            if (!below.given[c] || tree.nodes[c].isLeaf()) continue;
            const std::vector<Id> up =
                parts.nodes[c].dissolved ? below.standIns[c] : std::vector<Id>{c};
            for (Id x : up) {
                NodeBake& b = parts.nodes[x];
                if (tree.nodes[x].isLeaf() || !b.proxy.empty()) continue;
                bool bad = false;
                std::optional<ProxyMesh> p = cache.load(b.key, &bad);
                if (!p) {
                    throw Error(ErrorCode::FileNotFound, cacheDir,
                                std::string("the proxy of node ") + std::to_string(x) + " is " +
                                    (bad ? "damaged" : "missing") +
                                    " (run hlod build --shard again for the shard that baked it)");
                }
                b.proxy = std::move(*p);
                b.proxy.origin = b.frame.origin;
            }
        }
    }
}

// The whole bake from the shards' decisions and the nodes baked above the cut: counts summed,
// proxy sizes, the proxies below the cut dropped (the package takes the shards' tiles), the
// dissolved nodes removed. Returns per plan node its id in `tree` (kNoId: removed).
std::vector<Id> combine(ShardParts& parts, ClusterTree& tree, BakeResult& bake, SizeTable& sizes) {
    const std::size_t n = tree.nodes.size();
    bake.dissolved += parts.dissolved;
    bake.inputTriangles += parts.inputTriangles;
    bake.proxyTriangles += parts.proxyTriangles;
    bake.proxyVertices += parts.proxyVertices;
    bake.damaged += parts.damaged;
    for (Id id = 0; id < n; ++id) {
        NodeBake& b = bake.nodes[id];
        if (parts.below.given[id])
            b.proxy = ProxyMesh{b.frame.origin, {}, {}, {}, {}};
        else if (!tree.nodes[id].isLeaf() && !b.proxy.empty())
            parts.proxySize[id] = {b.proxy.triangleCount(), b.proxy.vertexCount(),
                                   meshBytes(b.proxy)};
    }
    std::vector<Id> newId = compactDissolved(tree, bake);
    if (newId.empty()) {
        newId.resize(n);
        for (Id id = 0; id < n; ++id)
            newId[id] = id;
    }
    bake.innerNodes = 0;
    for (const ClusterNode& node : tree.nodes)
        bake.innerNodes += node.isLeaf() ? 0 : 1;
    sizes.proxies.assign(tree.nodes.size(), MeshSize{});
    for (Id id = 0; id < n; ++id)
        if (newId[id] != kNoId) sizes.proxies[newId[id]] = parts.proxySize[id];
    return newId;
}

// A block's ids renumbered from the plan tree's into the final tree's (`newId`).
void renumber(PackageLayout& layout, const std::vector<Id>& newId, std::size_t nodes) {
    auto to = [&](Id id) { return id == kNoId ? kNoId : newId[id]; };
    for (TilePlan& t : layout.tiles)
        t.node = to(t.node);
    for (ContentPlan& c : layout.contents) {
        c.node = to(c.node);
        for (LeafSlot& s : c.leaves)
            s.leaf = to(s.leaf);
    }
    std::vector<int> tileOf(nodes, -1);
    for (Id id = 0; id < layout.tileOfNode.size(); ++id)
        if (layout.tileOfNode[id] >= 0 && newId[id] != kNoId)
            tileOf[newId[id]] = layout.tileOfNode[id];
    layout.tileOfNode = std::move(tileOf);
}

double secondsSince(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

} // namespace

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
    for (int i = 0; i < c.shards; ++i)
        if (!plan::shardFinished(folder, c.id, i) || !fs::exists(folder / tilesName(i), ec))
            c.missing.push_back(i);
    return c;
}

LeanFinalResult runLeanFinal(const LeanFinalRequest& r, const Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    const fs::path folder = planFolder(r.cacheDir);
    const json planJson = plan::readPlanJson(r.cacheDir);
    BakeParams params = bakeParamsFrom(r.bakeValues);
    params.threads = r.threads;
    params.cacheDir = r.cacheDir;
    ClusterTree tree = readClusterTreeBinary(plan::readChecked(folder / plan::kTreeFile),
                                             folder / plan::kTreeFile);
    Scene scene = readSceneBinary(plan::readChecked(folder / kTopScene), folder / kTopScene);
    SizeTable sizes;
    sizes.meshes = readSizes(folder / kSizes, scene.meshes.size());

    ShardParts parts = PartReader(r.cacheDir, planJson, tree).read(progress);
    loadHandedMeshes(scene, tree, folder, parts.leaves);
    loadHandedProxies(parts, tree, r.cacheDir);
    BakeResult bake = bakeAbove(scene, tree, std::move(parts.nodes), parts.below, params, progress);
    const std::vector<Id> newId = combine(parts, tree, bake, sizes);

    // The shards' blocks spliced into the layout of the whole tree.
    LayoutBlocks layoutBlocks;
    std::map<Id, const Block*> blockOf; // by root, final ids
    for (auto& [root, block] : parts.blocks) {
        renumber(block.layout, newId, tree.nodes.size());
        layoutBlocks.byRoot[newId[root]] = &block.layout;
        blockOf[newId[root]] = &block;
    }
    for (const MeshSize& m : sizes.meshes)
        layoutBlocks.meshTriangles.push_back(m.triangles);
    const PackageLayout layout = planPackage(scene, tree, bake, layoutBlocks);
    for (const ContentSource& s : layout.sources)
        if (s.block != kNoId && !blockOf.count(s.block))
            throw Error(ErrorCode::Malformed, folder / plan::kPlanFile,
                        "a shard's tiles do not match the tree");

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
    const PackageParts package{layout,
                               [&](const ContentSource& s) -> const GivenContent& {
                                   return blockOf.at(s.block)->contents.at(
                                       static_cast<std::size_t>(s.index));
                               },
                               sizes, placementFrom(planJson.at("lean").at("placement"))};
    out.export_.written =
        writePackage(r.output, scene, tree, bake, params,
                     packageOptionsFor(in, out.export_.info, options), package, progress);
    out.export_.writeSeconds = secondsSince(writeStart);
    out.export_.source = sourceFootprint(scene);
    out.shardBaked = parts.baked;
    out.shardReused = parts.reused;
    out.tree = std::move(tree);
    out.bake = std::move(bake);
    out.seconds = secondsSince(start);
    return out;
}

} // namespace hlod
