// The plan's and the shards' part of the lean final step (LeanFinal.h): what the plan writes
// for it, and the finished tiles and decisions a shard writes after its bake.
#include <algorithm>
#include <map>
#include <memory>

#include "pipeline/core/AtomicFile.h"
#include "pipeline/core/Error.h"
#include "pipeline/export/PackageLayout.h"
#include "pipeline/export/TileContent.h"
#include "pipeline/graph/BakePlan.h"
#include "pipeline/graph/LeanFinal.h"
#include "pipeline/graph/LeanParts.h"
#include "pipeline/graph/PlanFiles.h"
#include "pipeline/proxy/BakeStats.h"
#include "pipeline/proxy/ContentHash.h"
#include "pipeline/proxy/ProxyEconomy.h"
#include "pipeline/scene/SceneBinary.h"

namespace hlod {

namespace fs = std::filesystem;
using namespace lean;

namespace {

// Whether the lean step can serve the scene: no textures (LeanFinal.h).
bool untextured(const Scene& scene) {
    if (!scene.textures.empty()) return false;
    for (const Material& m : scene.materials)
        if (m.texture != kNoId || m.emissiveTexture != kNoId || !m.baseColorTexture.empty())
            return false;
    return true;
}

// What each dissolved node of `order` hands up: its inputs (ProxyBaker.h), a dissolved child
// replaced by its own.
std::vector<std::vector<Id>> standInsOf(const ClusterTree& tree, const BakeResult& bake,
                                        const std::vector<Id>& order) {
    std::vector<std::vector<Id>> standIns(tree.nodes.size());
    for (Id id : order) {
        if (tree.nodes[id].isLeaf() || !bake.nodes[id].dissolved) continue;
        for (Id c : tree.nodes[id].children) {
            if (!tree.nodes[c].isLeaf() && bake.nodes[c].dissolved)
                standIns[id].insert(standIns[id].end(), standIns[c].begin(), standIns[c].end());
            else
                standIns[id].push_back(c);
        }
    }
    return standIns;
}

// The bake's decision of every inner node of `order`, and the counts over them.
json decisionsJson(const ClusterTree& tree, const BakeResult& bake, const std::vector<Id>& order,
                   json& totals) {
    json nodes = json::array();
    std::size_t dissolved = 0, inputTriangles = 0, proxyTriangles = 0, proxyVertices = 0;
    for (Id id : order) {
        if (tree.nodes[id].isLeaf()) continue;
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
    totals = {{"baked", bake.baked},
              {"reused", bake.reused},
              {"damaged", bake.damaged},
              {"dissolved", dissolved},
              {"input_triangles", inputTriangles},
              {"proxy_triangles", proxyTriangles},
              {"proxy_vertices", proxyVertices}};
    return nodes;
}

// Lays out a handed-up subtree as the whole tree lays it out (the shard's dissolved nodes
// removed), encodes its contents into CACHE/tiles/HASH.glb and gives its layout as JSON in the
// plan tree's ids. Copies (equal content keys) are encoded once.
class BlockWriter {
public:
    BlockWriter(fs::path cacheDir, const Scene& slice, const ClusterTree& tree, BakeResult bake,
                GlbCompression compression)
        : cacheDir_(std::move(cacheDir)), slice_(slice), local_(tree) {
        bake_.nodes = std::move(bake.nodes);
        const std::vector<Id> newId = compactDissolved(local_, bake_);
        toLocal_.resize(tree.nodes.size());
        toPlan_.assign(local_.nodes.size(), kNoId);
        for (Id id = 0; id < tree.nodes.size(); ++id) {
            toLocal_[id] = newId.empty() ? id : newId[id];
            if (toLocal_[id] != kNoId) toPlan_[toLocal_[id]] = id;
        }
        textures_ = std::make_unique<TextureStore>(slice_, imageCacheFolder(cacheDir_));
        encoder_ = std::make_unique<ContentEncoder>(slice_, bake_, *textures_, compression);
    }

    json write(Id root) {
        const PackageLayout layout = planSubtree(slice_, local_, bake_, toLocal_[root]);
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
            json content = encoded(c);
            json leafIds = json::array();
            for (const LeafSlot& s : c.leaves)
                leafIds.push_back(planId(s.leaf));
            content["proxy"] = c.proxy;
            content["node"] = idJson(planId(c.node));
            content["leaves"] = std::move(leafIds);
            contents.push_back(std::move(content));
        }
        for (Id id = 0; id < layout.tileOfNode.size(); ++id)
            if (layout.tileOfNode[id] >= 0) tileOf.push_back({planId(id), layout.tileOfNode[id]});
        return {{"root", root}, {"tiles", tiles}, {"contents", contents}, {"tile_of", tileOf}};
    }

    bool wroteTextures() const { return !textures_->files().empty(); }

private:
    Id planId(Id local) const { return local == kNoId ? kNoId : toPlan_[local]; }

    // The content's file (written unless the cache holds these bytes) and what the manifest
    // needs of it.
    json encoded(const ContentPlan& c) {
        const std::uint64_t key = contentKey(c, bake_, slice_);
        if (auto it = byKey_.find(key); it != byKey_.end()) return it->second;
        const EncodedContent e = encoder_->encode(c);
        const std::string uri =
            "tiles/" + toHex(hashBytes(e.bytes.data(), e.bytes.size())) + ".glb";
        if (!fileHoldsBytes(cacheDir_ / uri, e.bytes)) { // a damaged copy is replaced
            std::error_code ec;
            fs::create_directories(cacheDir_ / "tiles", ec);
            writeFileAtomic(
                cacheDir_ / uri,
                std::string_view(reinterpret_cast<const char*>(e.bytes.data()), e.bytes.size()));
        }
        json where = json::array();
        for (const LeafInContent& l : e.leaves)
            where.push_back({l.node, l.merged ? 1 : 0, l.firstVertex, l.vertexCount, l.firstIndex,
                             l.indexCount});
        return byKey_[key] = {{"uri", uri},
                              {"where", where},
                              {"triangles", e.triangles},
                              {"vertices", e.vertices},
                              {"pe", e.positionError}};
    }

    fs::path cacheDir_;
    const Scene& slice_;
    ClusterTree local_;
    BakeResult bake_;
    std::vector<Id> toLocal_, toPlan_;
    std::unique_ptr<TextureStore> textures_;
    std::unique_ptr<ContentEncoder> encoder_;
    std::map<std::uint64_t, json> byKey_;
};

} // namespace

nlohmann::json writeLeanPlan(const fs::path& folder, const Scene& scene, const ClusterTree& tree,
                             const ShardPlan& shards, const LeanInputs& in) {
    if (!untextured(scene) || tree.root == kNoId || tree.nodes[tree.root].isLeaf() ||
        std::find(shards.top.begin(), shards.top.end(), tree.root) == shards.top.end())
        return nullptr;
    // The meshes of the leaves hanging from nodes above the cut, and of every leaf below a
    // node above the cut too small for tiles of its own (its leaves join its parent's group).
    const std::vector<std::size_t> triangles =
        subtreeTriangles(scene, tree, childrenFirst(tree, {tree.root}));
    std::vector<Id> leaves;
    for (Id id : shards.top) {
        if (id != tree.root && triangles[id] <= kSmallSubtreeTriangles)
            leavesBelow(tree, id, leaves);
        for (Id c : tree.nodes[id].children)
            if (tree.nodes[c].isLeaf()) leaves.push_back(c);
    }
    std::vector<char> used(scene.meshes.size(), 0);
    for (Id leaf : leaves)
        if (tree.nodes[leaf].instance != kNoId)
            used[scene.instances[tree.nodes[leaf].instance].mesh] = 1;
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

void writeShardTiles(const fs::path& cacheDir, const json& planJson, int index, const Scene& slice,
                     const ClusterTree& tree, const std::vector<Id>& roots, BakeResult bake) {
    const auto leanIt = planJson.find("lean");
    if (leanIt == planJson.end() || leanIt->is_null()) return;
    const std::vector<Id> order = childrenFirst(tree, roots);
    const std::vector<std::vector<Id>> standIns = standInsOf(tree, bake, order);
    const std::vector<std::size_t> triangles = subtreeTriangles(slice, tree, order);
    const std::vector<ProxyLookSums> looks = subtreeLookSums(slice, tree, order);
    json totals;
    const json nodes = decisionsJson(tree, bake, order, totals);
    // What each root hands to the nodes above: itself, or a dissolved root's inputs; a leaf
    // among them with its key and frame (a parent above is framed and keyed by them).
    std::vector<std::vector<Id>> ups;
    json handed = json::array();
    for (Id r : roots) {
        ups.push_back(bake.nodes[r].dissolved ? standIns[r] : std::vector<Id>{r});
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
    // Handed-up leaves and small subtrees join a leaf group above (the final step needs their
    // meshes); a larger handed-up subtree is laid out and encoded here.
    BlockWriter writer(cacheDir, slice, tree, std::move(bake),
                       glbCompressionFromString(leanIt->at("compression").get<std::string>()));
    json blocks = json::array(), handedLooks = json::object();
    std::vector<Id> leaves;
    for (const std::vector<Id>& up : ups) {
        for (Id x : up) {
            if (!tree.nodes[x].isLeaf()) handedLooks[std::to_string(x)] = look(looks[x]);
            if (tree.nodes[x].isLeaf() || triangles[x] <= kSmallSubtreeTriangles)
                leavesBelow(tree, x, leaves);
            else
                blocks.push_back(writer.write(x));
        }
    }
    if (writer.wroteTextures()) {
        throw Error(ErrorCode::InvalidArgument,
                    "the lean final step cannot take textured tiles (plan.json says the scene has "
                    "no textures)");
    }
    const json part = {{"plan", planJson.at("id")}, {"shard", index},       {"nodes", nodes},
                       {"handed", handed},          {"looks", handedLooks}, {"leaves", leaves},
                       {"blocks", blocks},          {"totals", totals}};
    plan::writeChecked(planFolder(cacheDir) / tilesName(index), part.dump());
}

} // namespace hlod
