// Loose octree baseline (thesis 3.2.2; see OctreeClusterer.h).
#include "pipeline/cluster/OctreeClusterer.h"

#include <algorithm>
#include <array>

#include "pipeline/core/Error.h"

namespace hlod {

namespace {

constexpr int kMaxDepth = 32;

struct Octree {
    TreeBuilder& builder;
    std::size_t maxPerCell;
    const Progress& progress;

    bool fits(const Aabb& box, const glm::dvec3& center, double half) const {
        // Loose bounds of an octant with half size `half`: centre +- 2 * half.
        const glm::dvec3 lo = center - glm::dvec3(2.0 * half);
        const glm::dvec3 hi = center + glm::dvec3(2.0 * half);
        return glm::all(glm::lessThanEqual(lo, box.min)) &&
               glm::all(glm::lessThanEqual(box.max, hi));
    }

    Id join(std::vector<Id>& entries) const {
        if (entries.size() == 1) return entries[0];
        return builder.addFoldedNode(entries);
    }

    // Node for the cell with `center` and half size `half` holding `units`.
    Id cell(std::vector<Id> units, const glm::dvec3& center, double half, int depth) {
        if (units.size() <= maxPerCell || depth >= kMaxDepth) return join(units);
        progress.throwIfCancelled();
        std::array<std::vector<Id>, 8> octants;
        std::vector<Id> stuck;
        const double childHalf = half * 0.5;
        for (Id u : units) {
            const Aabb& box = builder.unit(u).box;
            const glm::dvec3 c = box.center();
            const int o =
                (c.x >= center.x ? 1 : 0) | (c.y >= center.y ? 2 : 0) | (c.z >= center.z ? 4 : 0);
            const glm::dvec3 childCenter = center + glm::dvec3((o & 1) ? childHalf : -childHalf,
                                                               (o & 2) ? childHalf : -childHalf,
                                                               (o & 4) ? childHalf : -childHalf);
            if (fits(box, childCenter, childHalf)) {
                octants[static_cast<std::size_t>(o)].push_back(u);
            } else {
                stuck.push_back(u);
            }
        }
        if (stuck.size() == units.size()) return join(units); // nothing moves down
        std::vector<Id> entries;
        for (int o = 0; o < 8; ++o) {
            std::vector<Id>& list = octants[static_cast<std::size_t>(o)];
            if (list.empty()) continue;
            const glm::dvec3 childCenter = center + glm::dvec3((o & 1) ? childHalf : -childHalf,
                                                               (o & 2) ? childHalf : -childHalf,
                                                               (o & 4) ? childHalf : -childHalf);
            entries.push_back(cell(std::move(list), childCenter, childHalf, depth + 1));
        }
        entries.insert(entries.end(), stuck.begin(), stuck.end());
        return join(entries);
    }
};

} // namespace

Id mergeOctree(TreeBuilder& builder, std::vector<Id> units, int maxChildren,
               const Progress& progress) {
    if (maxChildren < 2) {
        throw Error(ErrorCode::InvalidArgument, "max children must be at least 2");
    }
    if (units.empty()) return kNoId;
    std::sort(units.begin(), units.end());
    Aabb all;
    for (Id u : units)
        all.expand(builder.unit(u).box);
    const glm::dvec3 e = all.extent();
    const double half = std::max({e.x, e.y, e.z, 1e-9}) * 0.5;
    Octree tree{builder, static_cast<std::size_t>(maxChildren), progress};
    return tree.cell(std::move(units), all.center(), half, 0);
}

} // namespace hlod
