// Clustering driver: leaves, constraints, one merging strategy (see ClusterDriver.h).
#include "pipeline/cluster/ClusterDriver.h"

#include <algorithm>
#include <numeric>
#include <string>

#include "pipeline/bounds/InstanceBounds.h"
#include "pipeline/cluster/LevelGrowth.h"
#include "pipeline/cluster/LocalConstraints.h"
#include "pipeline/core/Error.h"

namespace hlod {

namespace {

constexpr double kRelativeMinExtent = 1e-4;
constexpr double kFallbackMinExtent = 1e-6;

[[noreturn]] void invalid(const std::string& what) {
    throw Error(ErrorCode::InvalidArgument, what);
}

} // namespace

double clusteringMinExtent(const std::vector<Aabb>& boxes) {
    Aabb all;
    for (const Aabb& b : boxes)
        all.expand(b);
    const double d = all.diagonal();
    return d > 0.0 ? d * kRelativeMinExtent : kFallbackMinExtent;
}

void validateConstraints(const ClusterParams& params, std::size_t instanceCount) {
    if (params.maxChildren < 2) invalid("max children must be at least 2");
    // The arithmetic's limits only (the cost's (max / min extent)^k overflows past 1e6); the
    // range a user may choose is the parameter declaration's (pipeline/graph/Parameters.cpp).
    if (!(params.k >= 0.0) || params.k > 1e6)
        invalid("k must be a non-negative number the cost can raise to (at most 1e6)");
    // 0 = free, 1 = locked, 2 = excluded
    std::vector<unsigned char> state(instanceCount, 0);
    auto check = [&](Id id) {
        if (id >= instanceCount) {
            invalid("instance " + std::to_string(id) + " does not exist (the scene has " +
                    std::to_string(instanceCount) + ")");
        }
    };
    for (std::size_t g = 0; g < params.lockedGroups.size(); ++g) {
        if (params.lockedGroups[g].empty())
            invalid("locked group " + std::to_string(g) + " is empty");
        for (Id id : params.lockedGroups[g]) {
            check(id);
            if (state[id] != 0) {
                invalid("instance " + std::to_string(id) + " appears twice in the locked groups");
            }
            state[id] = 1;
        }
    }
    for (Id id : params.excluded) {
        check(id);
        if (state[id] == 1) {
            invalid("instance " + std::to_string(id) + " is both locked and excluded");
        }
        state[id] = 2;
    }
}

ClusterTree buildConstrainedTree(const Scene& scene, const ClusterParams& params,
                                 const CostModel& model, const UnitMerger& merge,
                                 const Progress& progress) {
    validateConstraints(params, scene.instances.size());

    progress.emit(ProgressInfo{"bounds", 0, scene.instances.size(), ""});
    const std::vector<InstanceBounds> bounds = computeInstanceBounds(scene, progress);
    std::vector<Aabb> boxes;
    boxes.reserve(bounds.size());
    for (const InstanceBounds& b : bounds)
        boxes.push_back(b.box);
    const double minExtent = clusteringMinExtent(boxes);

    TreeBuilder builder(model);
    builder.reserve(2 * bounds.size());
    for (Id i = 0; i < bounds.size(); ++i) {
        builder.addLeaf(i, bounds[i].box, model.leaf(bounds[i].sphere, bounds[i].box, minExtent));
    }
    // The automatic tree over every instance; the hand edits then change it locally.
    std::vector<Id> units(bounds.size());
    std::iota(units.begin(), units.end(), Id{0});
    const Id root = units.empty() ? kNoId : merge(builder, units, params.maxChildren, progress);
    ClusterTree tree = builder.finish(root, params.volume, params.k);
    // Levels at least levelGrowth apart (the merging trees only; the baselines keep theirs).
    if (params.volume == VolumeType::Sphere || params.volume == VolumeType::Aabb)
        tree = coarsenLevels(tree, params.levelGrowth);
    if (params.lockedGroups.empty() && params.excluded.empty()) return tree;
    return applyLocalConstraints(std::move(tree), params, model, minExtent);
}

} // namespace hlod
