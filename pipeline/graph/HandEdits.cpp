// Hand-edit constraints: canonical form, lookup by leaf set, JSON (see HandEdits.h).
#include "pipeline/graph/HandEdits.h"

#include <algorithm>
#include <string>

#include <nlohmann/json.hpp>

#include "pipeline/core/Error.h"

namespace hlod {

InstanceSet normalizedSet(InstanceSet ids) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return ids;
}

void normalize(HandEdits& e) {
    for (InstanceSet& g : e.locked)
        g = normalizedSet(std::move(g));
    for (InstanceSet& g : e.dissolved)
        g = normalizedSet(std::move(g));
    std::erase_if(e.locked, [](const InstanceSet& g) { return g.empty(); });
    std::erase_if(e.dissolved, [](const InstanceSet& g) { return g.size() < 2; });
    std::sort(e.locked.begin(), e.locked.end());
    std::sort(e.dissolved.begin(), e.dissolved.end());
    e.dissolved.erase(std::unique(e.dissolved.begin(), e.dissolved.end()), e.dissolved.end());
    e.excluded = normalizedSet(std::move(e.excluded));
}

InstanceSet leafSet(const ClusterTree& tree, Id node) {
    InstanceSet out;
    std::vector<Id> stack{node};
    while (!stack.empty()) {
        const Id id = stack.back();
        stack.pop_back();
        const ClusterNode& n = tree.nodes.at(id);
        if (n.isLeaf()) {
            out.push_back(n.instance);
        } else {
            stack.insert(stack.end(), n.children.begin(), n.children.end());
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

Id findCluster(const ClusterTree& tree, const InstanceSet& set) {
    if (set.empty() || tree.root == kNoId) return kNoId;
    // Walk down from the leaf of the first instance: the cluster, if it exists, is the lowest
    // ancestor whose leaf count reaches the set's size.
    Id leaf = kNoId;
    for (Id i = 0; i < tree.nodes.size(); ++i) {
        if (tree.nodes[i].isLeaf() && tree.nodes[i].instance == set.front()) {
            leaf = i;
            break;
        }
    }
    for (Id n = leaf; n != kNoId; n = tree.nodes[n].parent) {
        const InstanceSet s = leafSet(tree, n);
        if (s.size() == set.size()) return s == set ? n : kNoId;
        if (s.size() > set.size()) return kNoId;
    }
    return kNoId;
}

void applyConstraints(const HandEdits& edits, ClusterParams& params) {
    params.lockedGroups = edits.locked;
    params.excluded = edits.excluded;
}

void validateHandEdits(const HandEdits& e, std::size_t instanceCount) {
    auto bad = [](const std::string& what) { throw Error(ErrorCode::InvalidArgument, what); };
    std::vector<unsigned char> state(instanceCount, 0);
    auto check = [&](Id id, const char* where) {
        if (id >= instanceCount) {
            bad(std::string(where) + " names instance " + std::to_string(id) +
                ", but the scene has " + std::to_string(instanceCount) + " instances");
        }
    };
    for (const InstanceSet& g : e.locked) {
        for (Id id : g) {
            check(id, "a locked group");
            if (state[id]) bad("instance " + std::to_string(id) + " is in two locked groups");
            state[id] = 1;
        }
    }
    for (Id id : e.excluded) {
        check(id, "the exclusions");
        if (state[id]) bad("instance " + std::to_string(id) + " is both locked and excluded");
    }
    for (const InstanceSet& g : e.dissolved) {
        for (Id id : g)
            check(id, "a split cluster");
        if (std::find(e.locked.begin(), e.locked.end(), g) != e.locked.end())
            bad("a cluster is both locked and split");
    }
}

nlohmann::json handEditsToJson(const HandEdits& e) {
    return {{"locked", e.locked}, {"excluded", e.excluded}, {"dissolved", e.dissolved}};
}

namespace {

InstanceSet idsFromJson(const nlohmann::json& j, const std::string& where,
                        const std::filesystem::path& file) {
    auto fail = [&](const std::string& what) {
        if (file.empty()) throw Error(ErrorCode::InvalidArgument, what);
        throw Error(ErrorCode::Malformed, file, what);
    };
    if (!j.is_array()) fail(where + " must be an array of instance ids");
    InstanceSet out;
    for (const auto& v : j) {
        if (!v.is_number_unsigned() || v.get<unsigned long long>() >= kNoId)
            fail(where + " must hold instance ids (non-negative integers)");
        out.push_back(v.get<Id>());
    }
    return out;
}

std::vector<InstanceSet> setsFromJson(const nlohmann::json& j, const std::string& where,
                                      const std::filesystem::path& file) {
    std::vector<InstanceSet> out;
    if (!j.is_array()) {
        const std::string what = where + " must be an array of instance-id arrays";
        if (file.empty()) throw Error(ErrorCode::InvalidArgument, what);
        throw Error(ErrorCode::Malformed, file, what);
    }
    for (const auto& g : j)
        out.push_back(idsFromJson(g, where, file));
    return out;
}

} // namespace

HandEdits handEditsFromJson(const nlohmann::json& j, const std::filesystem::path& file) {
    HandEdits e;
    if (!j.is_object()) {
        const std::string what = "hand_edits must be an object";
        if (file.empty()) throw Error(ErrorCode::InvalidArgument, what);
        throw Error(ErrorCode::Malformed, file, what);
    }
    if (j.contains("locked")) e.locked = setsFromJson(j["locked"], "hand_edits.locked", file);
    if (j.contains("excluded"))
        e.excluded = idsFromJson(j["excluded"], "hand_edits.excluded", file);
    if (j.contains("dissolved"))
        e.dissolved = setsFromJson(j["dissolved"], "hand_edits.dissolved", file);
    normalize(e);
    return e;
}

} // namespace hlod
