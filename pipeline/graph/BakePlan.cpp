// The plan folder of a distributed bake: writing it, running one shard from it, and checking it
// before the final build. See BakePlan.h.
#include "pipeline/graph/BakePlan.h"

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "pipeline/cluster/ClusterTreeBinary.h"
#include "pipeline/core/AtomicFile.h"
#include "pipeline/core/Error.h"
#include "pipeline/graph/PlanFiles.h"
#include "pipeline/proxy/BakeCosts.h"
#include "pipeline/proxy/ContentHash.h"
#include "pipeline/scene/SceneBinary.h"

namespace hlod {

namespace {

using namespace plan;

double secondsSince(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

} // namespace

namespace plan {

void writeChecked(const std::filesystem::path& file, std::string bytes) {
    const std::uint64_t sum = hashBytes(bytes.data(), bytes.size());
    bytes.append(reinterpret_cast<const char*>(&sum), sizeof sum);
    writeFileAtomic(file, bytes);
}

std::string readChecked(const std::filesystem::path& file) {
    std::string bytes = readFileBytes(file, kRunPlan);
    std::uint64_t sum = 0;
    if (bytes.size() < sizeof sum) {
        throw Error(ErrorCode::Malformed, file, "is truncated (run hlod plan again)");
    }
    std::memcpy(&sum, bytes.data() + bytes.size() - sizeof sum, sizeof sum);
    bytes.resize(bytes.size() - sizeof sum);
    if (sum != hashBytes(bytes.data(), bytes.size())) {
        throw Error(ErrorCode::Malformed, file,
                    "is damaged (checksum mismatch; run hlod plan again)");
    }
    return bytes;
}

bool shardFinished(const std::filesystem::path& folder, const std::string& planId, int index) {
    const std::filesystem::path marker = folder / markerName(index);
    std::error_code ec;
    if (!std::filesystem::exists(marker, ec)) return false;
    std::ifstream in(marker);
    const nlohmann::json m = nlohmann::json::parse(in, nullptr, false);
    return m.is_object() && m.value("plan", std::string()) == planId &&
           m.value("shard", -1) == index;
}

} // namespace plan

namespace {

nlohmann::json readJson(const std::filesystem::path& file, const char* hint) {
    const std::string text = readFileBytes(file, hint);
    nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) {
        throw Error(ErrorCode::Malformed, file, "is not valid JSON (damaged?)");
    }
    return j;
}

} // namespace

// plan.json, checked for what the readers rely on.
nlohmann::json plan::readPlanJson(const std::filesystem::path& cacheDir) {
    const std::filesystem::path file = planFolder(cacheDir) / kPlanFile;
    nlohmann::json j = readJson(file, kRunPlan);
    try {
        if (j.at("format").get<int>() != kFormat) {
            throw Error(ErrorCode::Malformed, file,
                        "has plan format " + j.at("format").dump() + ", this hlod reads " +
                            std::to_string(kFormat) + " (run hlod plan again)");
        }
        const int shards = j.at("shards").get<int>();
        if (shards < 1 || j.at("shard_list").size() != static_cast<std::size_t>(shards) ||
            !j.at("id").is_string() || !j.at("bake").is_object()) {
            throw Error(ErrorCode::Malformed, file, "is inconsistent (damaged?)");
        }
    } catch (const nlohmann::json::exception& e) {
        throw Error(ErrorCode::Malformed, file, std::string("is incomplete: ") + e.what());
    }
    return j;
}

namespace {

void hashScene(ContentHash& h, const Scene& scene) {
    h.addValue(static_cast<std::uint64_t>(scene.nodes.size()));
    for (const Node& n : scene.nodes) {
        h.addString(n.name);
        h.addValue(n.parent);
        h.addVector(n.children);
        h.addValue(n.local);
    }
    h.addValue(static_cast<std::uint64_t>(scene.meshes.size()));
    for (const Mesh& m : scene.meshes) {
        h.addString(m.name);
        h.addVector(m.positions);
        h.addVector(m.normals);
        h.addVector(m.uvs);
        h.addVector(m.colors);
        h.addVector(m.indices);
        h.addValue(m.material);
    }
    h.addValue(static_cast<std::uint64_t>(scene.materials.size()));
    for (const Material& m : scene.materials) {
        h.addString(m.name);
        h.addValue(m.baseColor);
        h.addValue(static_cast<std::uint8_t>(m.hasTexture));
        h.addValue(m.textureMean);
        h.addValue(m.texture);
        h.addValue(m.alphaMode);
        h.addValue(m.alphaCutoff);
        h.addValue(static_cast<std::uint8_t>(m.doubleSided));
        h.addValue(m.emissive);
        h.addValue(m.emissiveTexture);
        h.addValue(m.emissiveMean);
    }
    h.addValue(static_cast<std::uint64_t>(scene.textures.size()));
    for (const Texture& t : scene.textures) {
        h.addString(t.name);
        h.addValue(static_cast<std::int32_t>(t.image ? t.image->width : -1));
        h.addValue(static_cast<std::int32_t>(t.image ? t.image->height : -1));
        if (t.image) h.addVector(t.image->pixels);
    }
    h.addVector(scene.instances);
}

std::uint64_t planIdFrom(const Scene& scene, const std::string& treeBytes,
                         const BakeParams& params) {
    ContentHash h(0x706c616e); // "plan"
    hashScene(h, scene);
    h.addString(treeBytes);
    h.addValue(bakeParamsKey(params));
    return h.digest();
}

// Shard `index`'s slice of the scene into `folder`; its entry of plan.json "shard_list".
nlohmann::json writeSlice(const std::filesystem::path& folder, const Scene& scene,
                          const ClusterTree& tree, int index, PlanSummary& s) {
    const std::vector<Id>& roots = s.shards.roots[static_cast<std::size_t>(index)];
    const Scene slice = sliceScene(scene, tree, roots);
    std::size_t meshes = 0, triangles = 0, inner = 0;
    for (const Mesh& m : slice.meshes) {
        meshes += m.indices.empty() ? 0 : 1;
        triangles += m.triangleCount();
    }
    std::vector<Id> stack(roots.begin(), roots.end());
    while (!stack.empty()) {
        const Id id = stack.back();
        stack.pop_back();
        inner += tree.nodes[id].isLeaf() ? 0 : 1;
        for (Id c : tree.nodes[id].children)
            stack.push_back(c);
    }
    std::string bytes = writeSceneBinary(slice);
    s.shardBytes.push_back(bytes.size() + sizeof(std::uint64_t));
    writeChecked(folder / sliceName(index), std::move(bytes));
    s.shardInnerNodes.push_back(inner);
    s.shardMeshes.push_back(meshes);
    s.shardTriangles.push_back(triangles);
    return {{"index", index},        {"file", sliceName(index)},
            {"roots", roots},        {"cost", s.shards.cost[static_cast<std::size_t>(index)]},
            {"inner_nodes", inner},  {"meshes", meshes},
            {"triangles", triangles}};
}

// The plan's structural keys (keys.bin), one per tree node.
std::vector<std::uint64_t> readKeys(const std::filesystem::path& file, const ClusterTree& tree) {
    const std::string bytes = readChecked(file);
    if (bytes.size() != tree.nodes.size() * sizeof(std::uint64_t) && !bytes.empty())
        throw Error(ErrorCode::Malformed, file, "does not match the plan's tree");
    std::vector<std::uint64_t> keys(bytes.size() / sizeof(std::uint64_t));
    std::memcpy(keys.data(), bytes.data(), bytes.size());
    return keys;
}

// What each node this shard baked cost, under its structural key, for the next plan
// (BakeCosts.h); nodes taken from the cache cost nothing here and are not recorded.
void recordCosts(const std::filesystem::path& cacheDir, const std::string& name,
                 const std::vector<std::uint64_t>& keys, const BakeResult& bake) {
    std::vector<std::pair<std::uint64_t, double>> costs;
    for (std::size_t id = 0; id < keys.size() && id < bake.nodes.size(); ++id) {
        if (bake.nodes[id].cpuSeconds > 0.0)
            costs.emplace_back(keys[id], bake.nodes[id].cpuSeconds);
    }
    writeBakeCosts(cacheDir, name, costs);
}

// The fresh plan folder takes the place of the old one (which goes, with its shard-I.done).
void swapIn(const std::filesystem::path& fresh, const std::filesystem::path& folder,
            const std::filesystem::path& old) {
    std::error_code ec;
    std::filesystem::remove_all(old, ec);
    if (std::filesystem::exists(folder, ec)) {
        std::filesystem::rename(folder, old, ec);
        if (ec) throw Error(ErrorCode::Io, folder, "cannot replace the old plan: " + ec.message());
    }
    std::filesystem::rename(fresh, folder, ec);
    if (ec) throw Error(ErrorCode::Io, folder, "cannot move the plan into place: " + ec.message());
    std::filesystem::remove_all(old, ec);
}

} // namespace

std::filesystem::path planFolder(const std::filesystem::path& cacheDir) {
    return cacheDir / "plan";
}

std::uint64_t bakePlanId(const Scene& scene, const ClusterTree& tree, const BakeParams& params) {
    return planIdFrom(scene, writeClusterTreeBinary(tree), params);
}

PlanSummary writeBakePlan(const std::filesystem::path& cacheDir, const Scene& scene,
                          const ClusterTree& tree, const ParamValues& bakeValues, int shards,
                          const Progress& progress, const LeanInputs* lean) {
    const auto start = std::chrono::steady_clock::now();
    if (cacheDir.empty()) {
        throw Error(ErrorCode::InvalidArgument,
                    "a plan needs the shared cache folder (--cache DIR)");
    }
    const BakeParams params = bakeParamsFrom(bakeValues);
    PlanSummary s;
    s.folder = planFolder(cacheDir);
    progress.emit(ProgressInfo{"plan", 0, static_cast<std::uint64_t>(shards) + 1, "cutting"});
    const std::vector<std::uint64_t> keys = tree.root == kNoId || tree.nodes[tree.root].isLeaf()
                                                ? std::vector<std::uint64_t>()
                                                : structuralKeys(scene, tree, params);
    s.shards = planShards(scene, tree, params, shards, keys, readBakeCosts(cacheDir));
    const std::string treeBytes = writeClusterTreeBinary(tree);
    s.id = toHex(planIdFrom(scene, treeBytes, params));
    s.nodes = tree.nodes.size();
    for (const ClusterNode& n : tree.nodes)
        s.innerNodes += n.isLeaf() ? 0 : 1;

    // Everything goes into a fresh folder that then replaces the old plan (BakePlan.h).
    std::error_code ec;
    std::filesystem::create_directories(cacheDir, ec);
    if (ec) throw Error(ErrorCode::Io, cacheDir, "cannot create the cache folder: " + ec.message());
    // Unique among concurrent planners on machines sharing the folder (pid and clock).
    const std::string suffix =
        std::to_string(::getpid()) + "-" +
        std::to_string(std::chrono::steady_clock::now().time_since_epoch().count());
    const std::filesystem::path fresh = cacheDir / ("plan.new-" + suffix);
    std::filesystem::remove_all(fresh, ec);
    std::filesystem::create_directories(fresh, ec);
    if (ec) throw Error(ErrorCode::Io, fresh, "cannot create folder: " + ec.message());
    try {
        writeChecked(fresh / kTreeFile, treeBytes);
        writeChecked(fresh / kKeysFile, std::string(reinterpret_cast<const char*>(keys.data()),
                                                    keys.size() * sizeof(std::uint64_t)));
        nlohmann::json list = nlohmann::json::array();
        for (int i = 0; i < shards; ++i) {
            progress.throwIfCancelled();
            list.push_back(writeSlice(fresh, scene, tree, i, s));
            progress.emit(ProgressInfo{"plan", static_cast<std::uint64_t>(i) + 1,
                                       static_cast<std::uint64_t>(shards) + 1,
                                       "wrote " + sliceName(i)});
        }
        const nlohmann::json leanJson =
            lean ? writeLeanPlan(fresh, scene, tree, s.shards, *lean) : nlohmann::json();
        s.lean = !leanJson.is_null();
        const nlohmann::json j = {
            {"format", kFormat},
            {"lean", leanJson},
            {"id", s.id},
            {"shards", shards},
            {"bake", paramsToJson(NodeKind::Bake, bakeValues)},
            {"nodes", s.nodes},
            {"inner_nodes", s.innerNodes},
            {"tree", kTreeFile},
            {"cost", {{"total", s.shards.totalCost}, {"above_cut", s.shards.topCost}}},
            {"above_cut", s.shards.top},
            {"shard_list", list}};
        writeFileAtomic(fresh / kPlanFile, j.dump(1) + "\n");
        swapIn(fresh, s.folder, cacheDir / ("plan.old-" + suffix));
    } catch (...) {
        std::filesystem::remove_all(fresh, ec);
        throw;
    }
    s.seconds = secondsSince(start);
    progress.emit(ProgressInfo{"plan", static_cast<std::uint64_t>(shards) + 1,
                               static_cast<std::uint64_t>(shards) + 1, "done"});
    return s;
}

ShardResult runBakeShard(const std::filesystem::path& cacheDir, int index, int shards, int threads,
                         const Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    const std::filesystem::path folder = planFolder(cacheDir);
    const nlohmann::json plan = readPlanJson(cacheDir);
    const int planned = plan.at("shards").get<int>();
    if (shards != planned) {
        throw Error(ErrorCode::InvalidArgument, "the plan in " + folder.string() + " has " +
                                                    std::to_string(planned) + " shards, not " +
                                                    std::to_string(shards));
    }
    if (index < 0 || index >= shards) {
        throw Error(ErrorCode::InvalidArgument, "shard index " + std::to_string(index) +
                                                    " is outside 0.." + std::to_string(shards - 1));
    }
    const std::filesystem::path planFile = folder / kPlanFile;
    BakeParams params;
    std::vector<Id> roots;
    try {
        params = bakeParamsFrom(paramsFromJson(NodeKind::Bake, plan.at("bake"), planFile));
        roots = plan.at("shard_list")
                    .at(static_cast<std::size_t>(index))
                    .at("roots")
                    .get<std::vector<Id>>();
    } catch (const nlohmann::json::exception& e) {
        throw Error(ErrorCode::Malformed, planFile, std::string("is incomplete: ") + e.what());
    }
    params.cacheDir = cacheDir;
    params.threads = threads;
    params.boundWorkingSets = true; // a shard's machine is sized by its peak memory
    const ClusterTree tree =
        readClusterTreeBinary(readChecked(folder / kTreeFile), folder / kTreeFile);
    const std::filesystem::path sliceFile = folder / sliceName(index);
    const Scene slice = readSceneBinary(readChecked(sliceFile), sliceFile);
    for (Id r : roots) {
        if (r >= tree.nodes.size() || tree.nodes[r].isLeaf())
            throw Error(ErrorCode::Malformed, planFile,
                        "names a shard root that is not in the tree");
    }
    for (const MeshInstance& inst : slice.instances) {
        if (inst.mesh >= slice.meshes.size() || inst.node >= slice.nodes.size())
            throw Error(ErrorCode::Malformed, sliceFile, "has an instance out of range");
    }
    for (const ClusterNode& n : tree.nodes) {
        if (n.isLeaf() && n.instance != kNoId && n.instance >= slice.instances.size())
            throw Error(ErrorCode::Malformed, sliceFile, "does not match the plan's tree");
    }

    BakeResult bake = bakeSubtrees(slice, tree, roots, params, progress);
    recordCosts(cacheDir, plan.at("id").get<std::string>() + "-" + std::to_string(index),
                readKeys(folder / kKeysFile, tree), bake);
    const std::size_t innerNodes = bake.innerNodes, baked = bake.baked, reused = bake.reused,
                      damaged = bake.damaged;
    writeShardTiles(cacheDir, plan, index, slice, tree, roots, std::move(bake));
    ShardResult r;
    r.index = index;
    r.shards = shards;
    r.subtrees = roots.size();
    r.innerNodes = innerNodes;
    r.baked = baked;
    r.reused = reused;
    r.corrupt = damaged;
    for (const Mesh& m : slice.meshes) {
        r.meshes += m.indices.empty() ? 0 : 1;
        r.triangles += m.triangleCount();
    }
    r.seconds = secondsSince(start);
    r.marker = folder / markerName(index);
    const nlohmann::json done = {{"plan", plan.at("id")}, {"shard", index},
                                 {"shards", shards},      {"inner_nodes", r.innerNodes},
                                 {"baked", r.baked},      {"reused", r.reused},
                                 {"damaged", r.corrupt},  {"seconds", r.seconds}};
    writeFileAtomic(r.marker, done.dump(1) + "\n");
    return r;
}

PlanCheck checkBakePlan(const std::filesystem::path& cacheDir, const Scene& scene,
                        const ClusterTree& tree, const BakeParams& params) {
    PlanCheck c;
    const std::filesystem::path folder = planFolder(cacheDir);
    std::error_code ec;
    if (cacheDir.empty() || !std::filesystem::exists(folder / kPlanFile, ec)) return c;
    const nlohmann::json plan = readPlanJson(cacheDir);
    c.found = true;
    c.id = plan.at("id").get<std::string>();
    c.shards = plan.at("shards").get<int>();
    c.aboveCut = plan.contains("above_cut") ? plan.at("above_cut").size() : 0;
    c.matches = c.id == toHex(bakePlanId(scene, tree, params));
    if (!c.matches) return c;
    for (int i = 0; i < c.shards; ++i)
        if (!shardFinished(folder, c.id, i)) c.missing.push_back(i);
    return c;
}

std::string describeMissingShards(const PlanCheck& check) {
    const std::size_t n = check.missing.size();
    std::string list, files;
    for (std::size_t k = 0; k < n; ++k) {
        const std::string sep = k == 0 ? "" : (k + 1 == n ? " and " : ", ");
        list += sep + std::to_string(check.missing[k]);
        files += (k == 0 ? "" : ", ") + markerName(check.missing[k]);
    }
    return std::string(n == 1 ? "shard " : "shards ") + list + " of " +
           std::to_string(check.shards) + (n == 1 ? " has" : " have") + " not finished (no " +
           files + ")";
}

int shardIndexFromEnvironment(const std::function<const char*(const char*)>& getenv) {
    for (const char* name :
         {"SLURM_ARRAY_TASK_ID", "JOB_COMPLETION_INDEX", "AWS_BATCH_JOB_ARRAY_INDEX"}) {
        const char* value = getenv(name);
        if (!value || !*value) continue;
        char* end = nullptr;
        errno = 0;
        const long v = std::strtol(value, &end, 10);
        if (errno != 0 || *end != '\0' || v < 0 || v > 1000000) {
            throw Error(ErrorCode::InvalidArgument,
                        std::string(name) + "=" + value + " is not a shard index");
        }
        return static_cast<int>(v);
    }
    throw Error(ErrorCode::InvalidArgument,
                "--shard auto/N: none of SLURM_ARRAY_TASK_ID, JOB_COMPLETION_INDEX, "
                "AWS_BATCH_JOB_ARRAY_INDEX is set (give the index: --shard I/N)");
}

} // namespace hlod
