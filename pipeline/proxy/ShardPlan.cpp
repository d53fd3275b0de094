// Greedy cost-balanced cut of a cluster tree into shards (LPT over subtrees), see ShardPlan.h.
#include "pipeline/proxy/ShardPlan.h"

#include <algorithm>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

#include "pipeline/core/Error.h"

namespace hlod {

namespace {

// How many of the costliest units each greedy step tries to split.
constexpr std::size_t kSplitCandidates = 8;

// Estimated input triangles of every inner node (ShardPlan.h "Cost"), children first.
std::vector<double> estimatedInputs(const Scene& scene, const ClusterTree& tree, double rho) {
    std::vector<double> est(tree.nodes.size(), 0.0);
    if (tree.root == kNoId) return est;
    std::vector<Id> order; // pre-order; walked backwards it puts children before parents
    std::vector<Id> stack{tree.root};
    while (!stack.empty()) {
        const Id id = stack.back();
        stack.pop_back();
        order.push_back(id);
        for (Id c : tree.nodes[id].children)
            stack.push_back(c);
    }
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
        const ClusterNode& node = tree.nodes[*it];
        for (Id c : node.children) {
            const ClusterNode& child = tree.nodes[c];
            if (!child.isLeaf()) {
                est[*it] += rho * est[c];
            } else if (child.instance != kNoId) {
                est[*it] += static_cast<double>(
                    scene.meshes[scene.instances[child.instance].mesh].triangleCount());
            }
        }
    }
    return est;
}

// A unit of the cut: one subtree, with the distinct keys of its inner nodes.
struct Unit {
    Id root = kNoId;
    std::vector<std::uint64_t> keys; // distinct, sorted
    double cost = 0.0;               // sum of their costs
};

class Planner {
public:
    Planner(const ClusterTree& tree, std::vector<std::uint64_t> keys, std::vector<double> est,
            int shards)
        : tree_(tree), key_(std::move(keys)), shards_(shards) {
        for (Id id = 0; id < tree.nodes.size(); ++id) {
            if (!tree.nodes[id].isLeaf()) weight_.emplace(key_[id], est[id]);
        }
    }

    Unit makeUnit(Id root) const {
        Unit u;
        u.root = root;
        std::vector<Id> stack{root};
        while (!stack.empty()) {
            const Id id = stack.back();
            stack.pop_back();
            if (tree_.nodes[id].isLeaf()) continue;
            u.keys.push_back(key_[id]);
            for (Id c : tree_.nodes[id].children)
                stack.push_back(c);
        }
        std::sort(u.keys.begin(), u.keys.end());
        u.keys.erase(std::unique(u.keys.begin(), u.keys.end()), u.keys.end());
        for (std::uint64_t k : u.keys)
            u.cost += weight_.at(k);
        return u;
    }

    double weight(std::uint64_t key) const { return weight_.at(key); }

    // LPT over `units`: per shard its unit indices and cost; returns the largest shard cost.
    // Units with equal root keys (copies) form one group, baked once in one shard. A key in
    // several groups is shared: the shards bake it together through the cache's claims, so
    // each group is charged its share, w / (groups holding it); the loads sum to the total.
    double assign(const std::vector<Unit>& units, std::vector<std::vector<std::size_t>>* members,
                  std::vector<double>* loads) const {
        std::vector<std::vector<std::size_t>> groups;
        std::unordered_map<std::uint64_t, std::size_t> groupOfRootKey;
        for (std::size_t u = 0; u < units.size(); ++u) {
            const auto [it, fresh] = groupOfRootKey.emplace(key_[units[u].root], groups.size());
            if (fresh) groups.emplace_back();
            groups[it->second].push_back(u);
        }
        std::vector<std::vector<std::uint64_t>> groupKeys(groups.size());
        std::unordered_map<std::uint64_t, int> holders;
        for (std::size_t g = 0; g < groups.size(); ++g) {
            for (std::size_t u : groups[g])
                groupKeys[g].insert(groupKeys[g].end(), units[u].keys.begin(), units[u].keys.end());
            std::sort(groupKeys[g].begin(), groupKeys[g].end());
            groupKeys[g].erase(std::unique(groupKeys[g].begin(), groupKeys[g].end()),
                               groupKeys[g].end());
            for (std::uint64_t k : groupKeys[g])
                ++holders[k];
        }
        std::vector<double> cost(groups.size(), 0.0);
        for (std::size_t g = 0; g < groups.size(); ++g) {
            for (std::uint64_t k : groupKeys[g])
                cost[g] += weight_.at(k) / holders.at(k);
        }
        std::vector<std::size_t> order(groups.size());
        std::iota(order.begin(), order.end(), std::size_t(0));
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
        std::vector<double> load(static_cast<std::size_t>(shards_), 0.0);
        std::vector<std::vector<std::size_t>> in(static_cast<std::size_t>(shards_));
        for (std::size_t g : order) {
            const auto s =
                static_cast<std::size_t>(std::min_element(load.begin(), load.end()) - load.begin());
            load[s] += cost[g];
            in[s].insert(in[s].end(), groups[g].begin(), groups[g].end());
        }
        const double worst = load.empty() ? 0.0 : *std::max_element(load.begin(), load.end());
        if (members) *members = std::move(in);
        if (loads) *loads = std::move(load);
        return worst;
    }

private:
    const ClusterTree& tree_;
    std::vector<std::uint64_t> key_;
    std::unordered_map<std::uint64_t, double> weight_;
    int shards_;
};

// Cost of the nodes above the cut, each distinct key once.
double topCost(const Planner& planner, const std::vector<std::uint64_t>& keys,
               const std::vector<Id>& top) {
    std::unordered_set<std::uint64_t> seen;
    double cost = 0.0;
    for (Id id : top) {
        if (seen.insert(keys[id]).second) cost += planner.weight(keys[id]);
    }
    return cost;
}

} // namespace

ShardPlan planShards(const Scene& scene, const ClusterTree& tree, const BakeParams& params,
                     int shards) {
    if (shards < 1 || shards > 100000) {
        throw Error(ErrorCode::InvalidArgument,
                    "shards must be within [1, 100000], got " + std::to_string(shards));
    }
    ShardPlan plan;
    plan.shards = shards;
    plan.roots.resize(static_cast<std::size_t>(shards));
    plan.cost.assign(static_cast<std::size_t>(shards), 0.0);
    if (tree.root == kNoId || tree.nodes[tree.root].isLeaf()) return plan;

    const std::vector<std::uint64_t> keys = structuralKeys(scene, tree, params);
    const Planner planner(tree, keys, estimatedInputs(scene, tree, params.proxyRatio), shards);
    std::vector<Unit> units{planner.makeUnit(tree.root)};
    plan.totalCost = units[0].cost;
    std::vector<Id> top;
    double makespan = planner.assign(units, nullptr, nullptr);
    // Greedy splits while the estimated makespan drops (ShardPlan.h): of the costliest units,
    // the one whose split lowers it most.
    for (;;) {
        std::vector<std::size_t> byCost(units.size());
        std::iota(byCost.begin(), byCost.end(), std::size_t(0));
        std::stable_sort(byCost.begin(), byCost.end(), [&](std::size_t a, std::size_t b) {
            return units[a].cost > units[b].cost;
        });
        byCost.resize(std::min(byCost.size(), kSplitCandidates));
        std::vector<Unit> best;
        std::vector<Id> bestTop;
        double bestMakespan = makespan;
        for (std::size_t u : byCost) {
            std::vector<Unit> next;
            next.reserve(units.size() + tree.nodes[units[u].root].children.size());
            for (std::size_t other = 0; other < units.size(); ++other) {
                if (other != u) next.push_back(units[other]);
            }
            for (Id c : tree.nodes[units[u].root].children) {
                if (!tree.nodes[c].isLeaf()) next.push_back(planner.makeUnit(c));
            }
            std::vector<Id> nextTop = top;
            nextTop.push_back(units[u].root);
            const double candidate =
                topCost(planner, keys, nextTop) + planner.assign(next, nullptr, nullptr);
            if (candidate < bestMakespan) {
                bestMakespan = candidate;
                best = std::move(next);
                bestTop = std::move(nextTop);
            }
        }
        if (bestTop.empty()) break;
        makespan = bestMakespan;
        units = std::move(best);
        top = std::move(bestTop);
    }
    std::vector<std::vector<std::size_t>> members;
    planner.assign(units, &members, &plan.cost);
    for (std::size_t s = 0; s < members.size(); ++s) {
        for (std::size_t u : members[s])
            plan.roots[s].push_back(units[u].root);
        std::sort(plan.roots[s].begin(), plan.roots[s].end());
    }
    std::sort(top.begin(), top.end());
    plan.topCost = topCost(planner, keys, top);
    plan.top = std::move(top);
    return plan;
}

Scene sliceScene(const Scene& scene, const ClusterTree& tree, const std::vector<Id>& roots) {
    std::vector<char> meshUsed(scene.meshes.size(), 0);
    std::vector<Id> stack(roots.begin(), roots.end());
    while (!stack.empty()) {
        const Id id = stack.back();
        stack.pop_back();
        const ClusterNode& node = tree.nodes.at(id);
        if (node.isLeaf() && node.instance != kNoId)
            meshUsed[scene.instances.at(node.instance).mesh] = 1;
        for (Id c : node.children)
            stack.push_back(c);
    }
    std::vector<char> textureUsed(scene.textures.size(), 0);
    Scene slice;
    slice.nodes = scene.nodes;
    slice.materials = scene.materials;
    slice.instances = scene.instances;
    slice.sourceFiles = scene.sourceFiles;
    slice.referencedFiles = scene.referencedFiles;
    slice.meshes.reserve(scene.meshes.size());
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        if (meshUsed[m]) {
            slice.meshes.push_back(mesh);
            const Id mat = mesh.material < scene.materials.size() ? mesh.material : 0;
            const Id tex = scene.materials[mat].texture;
            if (tex != kNoId && tex < textureUsed.size()) textureUsed[tex] = 1;
        } else {
            Mesh empty;
            empty.name = mesh.name;
            empty.material = mesh.material;
            slice.meshes.push_back(std::move(empty));
        }
    }
    slice.textures = scene.textures;
    for (std::size_t t = 0; t < slice.textures.size(); ++t) {
        if (!textureUsed[t]) slice.textures[t].image.reset();
    }
    return slice;
}

} // namespace hlod
