// Cost-balanced cut of a cluster tree into shards (best-first splits, LPT), see ShardPlan.h.
// ShardPlan.h.
#include "pipeline/proxy/ShardPlan.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

#include "pipeline/core/Error.h"

namespace hlod {

namespace {

// How many of the costliest units each greedy step tries to split.
constexpr std::size_t kSplitCandidates = 8;
// A key held by more groups than this (a part repeated all over the scene) does not merge them.
constexpr std::size_t kMaxHolders = 16;

// Estimated input triangles of every inner node (ShardPlan.h "Cost"), children first.
std::vector<double> estimatedInputs(const Scene& scene, const ClusterTree& tree, double rho) {
    std::vector<double> est(tree.nodes.size(), 0.0);
    if (tree.root == kNoId) return est;
    for (Id id : childrenFirst(tree, {tree.root})) {
        const ClusterNode& node = tree.nodes[id];
        for (Id c : node.children) {
            const ClusterNode& child = tree.nodes[c];
            if (!child.isLeaf()) {
                est[id] += rho * est[c];
            } else if (child.instance != kNoId) {
                est[id] += static_cast<double>(
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
        std::vector<std::vector<std::size_t>> groups = overlapGroups(units);
        std::vector<std::vector<std::uint64_t>> groupKeys(groups.size());
        std::unordered_map<std::uint64_t, int> holders;
        for (std::size_t g = 0; g < groups.size(); ++g) {
            groupKeys[g] = keysOf(units, groups[g]);
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
    // The distinct keys of the units `members`, sorted.
    static std::vector<std::uint64_t> keysOf(const std::vector<Unit>& units,
                                             const std::vector<std::size_t>& members) {
        std::vector<std::uint64_t> keys;
        for (std::size_t u : members)
            keys.insert(keys.end(), units[u].keys.begin(), units[u].keys.end());
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
        return keys;
    }

    // Units with equal root keys (copies) form one group; groups sharing at least half of the
    // smaller one's cost are merged (ShardPlan.h "Shared work"): in different shards, the
    // shard that happens to reach the shared nodes first would bake them all.
    std::vector<std::vector<std::size_t>> overlapGroups(const std::vector<Unit>& units) const {
        std::vector<std::vector<std::size_t>> groups;
        std::unordered_map<std::uint64_t, std::size_t> groupOfRootKey;
        for (std::size_t u = 0; u < units.size(); ++u) {
            const auto [it, fresh] = groupOfRootKey.emplace(key_[units[u].root], groups.size());
            if (fresh) groups.emplace_back();
            groups[it->second].push_back(u);
        }
        std::vector<std::vector<std::uint64_t>> keys(groups.size());
        std::vector<double> own(groups.size(), 0.0);
        std::unordered_map<std::uint64_t, std::vector<std::size_t>> holders;
        for (std::size_t g = 0; g < groups.size(); ++g) {
            keys[g] = keysOf(units, groups[g]);
            for (std::uint64_t k : keys[g]) {
                own[g] += weight_.at(k);
                holders[k].push_back(g);
            }
        }
        std::map<std::pair<std::size_t, std::size_t>, double> shared;
        for (std::size_t g = 0; g < groups.size(); ++g) {
            for (std::uint64_t k : keys[g]) {
                const std::vector<std::size_t>& h = holders.at(k);
                if (h.size() < 2 || h.size() > kMaxHolders || h.front() != g) continue;
                for (std::size_t a = 0; a < h.size(); ++a)
                    for (std::size_t b = a + 1; b < h.size(); ++b)
                        shared[{h[a], h[b]}] += weight_.at(k);
            }
        }
        std::vector<std::size_t> parent(groups.size());
        std::iota(parent.begin(), parent.end(), std::size_t(0));
        const auto find = [&](std::size_t g) {
            while (parent[g] != g)
                g = parent[g] = parent[parent[g]];
            return g;
        };
        bool merged = false;
        for (const auto& [pair, weight] : shared) { // ascending pairs: deterministic
            if (weight < 0.5 * std::min(own[pair.first], own[pair.second])) continue;
            const std::size_t a = find(pair.first), b = find(pair.second);
            if (a != b) parent[std::max(a, b)] = std::min(a, b);
            merged = true;
        }
        if (!merged) return groups;
        std::vector<std::vector<std::size_t>> out;
        std::vector<std::size_t> index(groups.size(), groups.size());
        for (std::size_t g = 0; g < groups.size(); ++g) {
            const std::size_t r = find(g);
            if (index[r] == groups.size()) {
                index[r] = out.size();
                out.emplace_back();
            }
            auto& into = out[index[r]];
            into.insert(into.end(), groups[g].begin(), groups[g].end());
        }
        return out;
    }

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

// Per inner node its cost (ShardPlan.h "Measured costs"); sets plan.measuredNodes and
// plan.secondsPerTriangle.
std::vector<double> nodeCosts(const Scene& scene, const ClusterTree& tree, const BakeParams& params,
                              const std::vector<std::uint64_t>& keys, const MeasuredCosts& measured,
                              ShardPlan& plan) {
    std::vector<double> cost = estimatedInputs(scene, tree, params.proxyRatio);
    if (measured.empty()) return cost;
    double seconds = 0.0, estimate = 0.0;
    std::vector<char> found(tree.nodes.size(), 0);
    for (Id id = 0; id < tree.nodes.size(); ++id) {
        if (tree.nodes[id].isLeaf()) continue;
        const auto it = measured.find(keys[id]);
        if (it == measured.end()) continue;
        found[id] = 1;
        ++plan.measuredNodes;
        seconds += it->second;
        estimate += cost[id];
    }
    if (plan.measuredNodes == 0 || estimate <= 0.0 || seconds <= 0.0) {
        plan.measuredNodes = 0;
        return cost;
    }
    plan.secondsPerTriangle = seconds / estimate;
    for (Id id = 0; id < tree.nodes.size(); ++id)
        cost[id] = found[id] ? measured.at(keys[id]) : cost[id] * plan.secondsPerTriangle;
    return cost;
}

// Whether splitting the unit at `root` makes new units (it has inner children).
bool splittable(const ClusterTree& tree, Id root) {
    for (Id c : tree.nodes[root].children) {
        if (!tree.nodes[c].isLeaf()) return true;
    }
    return false;
}

// The units and the nodes above the cut of one cut.
struct Cut {
    std::vector<Unit> units;
    std::vector<Id> top;
    double makespan = 0.0;
};

// The best-first search of ShardPlan.h "Cut".
Cut searchCut(const ClusterTree& tree, const Planner& planner,
              const std::vector<std::uint64_t>& keys, double total, int shards) {
    Cut cut;
    cut.units.push_back(planner.makeUnit(tree.root));
    cut.makespan = planner.assign(cut.units, nullptr, nullptr);
    Cut best = cut;
    const double n = static_cast<double>(shards);
    // Enough for any tree we bake; the bound below ends the search long before.
    const std::size_t maxSteps = 16 * tree.nodes.size() + 64;
    for (std::size_t step = 0; step < maxSteps; ++step) {
        std::vector<std::size_t> byCost;
        for (std::size_t u = 0; u < cut.units.size(); ++u) {
            if (splittable(tree, cut.units[u].root)) byCost.push_back(u);
        }
        std::stable_sort(byCost.begin(), byCost.end(), [&](std::size_t a, std::size_t b) {
            return cut.units[a].cost > cut.units[b].cost;
        });
        byCost.resize(std::min(byCost.size(), kSplitCandidates));
        if (byCost.empty()) break;
        Cut next;
        next.makespan = -1.0;
        for (std::size_t u : byCost) {
            Cut candidate;
            candidate.units.reserve(cut.units.size() +
                                    tree.nodes[cut.units[u].root].children.size());
            for (std::size_t other = 0; other < cut.units.size(); ++other) {
                if (other != u) candidate.units.push_back(cut.units[other]);
            }
            for (Id c : tree.nodes[cut.units[u].root].children) {
                if (!tree.nodes[c].isLeaf()) candidate.units.push_back(planner.makeUnit(c));
            }
            candidate.top = cut.top;
            candidate.top.push_back(cut.units[u].root);
            candidate.makespan = topCost(planner, keys, candidate.top) +
                                 planner.assign(candidate.units, nullptr, nullptr);
            if (next.makespan < 0.0 || candidate.makespan < next.makespan)
                next = std::move(candidate);
        }
        cut = std::move(next);
        if (cut.makespan < best.makespan) best = cut;
        const double above = topCost(planner, keys, cut.top);
        if (total / n + above * (1.0 - 1.0 / n) >= best.makespan) break;
    }
    return best;
}

} // namespace

double ShardPlan::largestOverMean() const {
    double sum = 0.0, largest = 0.0;
    for (double c : cost) {
        sum += c;
        largest = std::max(largest, c);
    }
    return sum > 0.0 ? largest * static_cast<double>(cost.size()) / sum : 1.0;
}

double ShardPlan::predictedSpeedup() const {
    double largest = 0.0;
    for (double c : cost)
        largest = std::max(largest, c);
    return topCost + largest > 0.0 ? totalCost / (topCost + largest) : 1.0;
}

ShardPlan planShards(const Scene& scene, const ClusterTree& tree, const BakeParams& params,
                     int shards, const MeasuredCosts& measured) {
    const bool empty = tree.root == kNoId || tree.nodes[tree.root].isLeaf();
    return planShards(scene, tree, params, shards,
                      empty || shards < 1 ? std::vector<std::uint64_t>()
                                          : structuralKeys(scene, tree, params),
                      measured);
}

ShardPlan planShards(const Scene& scene, const ClusterTree& tree, const BakeParams& params,
                     int shards, const std::vector<std::uint64_t>& keys,
                     const MeasuredCosts& measured) {
    if (shards < 1 || shards > 100000) {
        throw Error(ErrorCode::InvalidArgument,
                    "shards must be within [1, 100000], got " + std::to_string(shards));
    }
    ShardPlan plan;
    plan.shards = shards;
    plan.roots.resize(static_cast<std::size_t>(shards));
    plan.cost.assign(static_cast<std::size_t>(shards), 0.0);
    if (tree.root == kNoId || tree.nodes[tree.root].isLeaf()) return plan;
    if (keys.size() != tree.nodes.size())
        throw Error(ErrorCode::InvalidArgument, "shard plan: the keys do not match the tree");

    const Planner planner(tree, keys, nodeCosts(scene, tree, params, keys, measured, plan), shards);
    plan.totalCost = planner.makeUnit(tree.root).cost;
    Cut cut = searchCut(tree, planner, keys, plan.totalCost, shards);
    std::vector<std::vector<std::size_t>> members;
    planner.assign(cut.units, &members, &plan.cost);
    for (std::size_t s = 0; s < members.size(); ++s) {
        for (std::size_t u : members[s])
            plan.roots[s].push_back(cut.units[u].root);
        std::sort(plan.roots[s].begin(), plan.roots[s].end());
    }
    std::sort(cut.top.begin(), cut.top.end());
    plan.topCost = topCost(planner, keys, cut.top);
    plan.top = std::move(cut.top);
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
    return sliceScene(scene, meshUsed);
}

Scene sliceScene(const Scene& scene, const std::vector<char>& meshUsed) {
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
