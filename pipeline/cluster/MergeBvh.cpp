// Median-split BVH forest for best-partner queries (see MergeBvh.h).
#include "pipeline/cluster/MergeBvh.h"

#include <limits>
#include <numeric>

namespace hlod {

namespace {

constexpr std::uint32_t kLeafSize = 2;

void include(Region& into, const Region& r) {
    into.box.expand(r.box);
    into.maxFv = std::max(into.maxFv, r.maxFv);
    into.minRadius = std::min(into.minRadius, r.minRadius);
    into.minVolume = std::min(into.minVolume, r.minVolume);
    into.minExtent = glm::min(into.minExtent, r.minExtent);
}

Region emptyRegion() {
    Region r;
    constexpr double big = std::numeric_limits<double>::max();
    r.minRadius = big;
    r.minVolume = big;
    r.minExtent = glm::dvec3(big);
    return r;
}

} // namespace

void MergeBvh::build(const std::vector<Region>& items, const std::vector<int>& sizeClass) {
    const auto n = static_cast<std::uint32_t>(items.size());
    nodes_.clear();
    roots_.clear();
    order_.resize(n);
    leafOf_.assign(n, 0);
    if (n == 0) return;
    nodes_.reserve(2 * (n / kLeafSize + 1) + 64);
    std::vector<glm::dvec3> centers(n);
    for (std::uint32_t i = 0; i < n; ++i)
        centers[i] = items[i].box.center();
    // Items grouped by size class (stable: ties keep item order), one hierarchy per class.
    std::iota(order_.begin(), order_.end(), 0u);
    std::stable_sort(order_.begin(), order_.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return sizeClass[a] < sizeClass[b]; });
    std::uint32_t begin = 0;
    while (begin < n) {
        std::uint32_t end = begin + 1;
        while (end < n && sizeClass[order_[end]] == sizeClass[order_[begin]])
            ++end;
        roots_.push_back(buildRange(begin, end, items, centers, 0xffffffffu));
        begin = end;
    }
    ordered_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i)
        ordered_[i] = items[order_[i]];
}

std::uint32_t MergeBvh::buildRange(std::uint32_t begin, std::uint32_t end,
                                   const std::vector<Region>& items,
                                   const std::vector<glm::dvec3>& centers, std::uint32_t parent) {
    const auto id = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back(Node{});
    nodes_[id].parent = parent;
    Region region = emptyRegion();
    Aabb centerBox;
    for (std::uint32_t i = begin; i < end; ++i) {
        include(region, items[order_[i]]);
        centerBox.expand(centers[order_[i]]);
    }
    nodes_[id].region = region;
    if (end - begin <= kLeafSize) {
        nodes_[id].first = begin;
        nodes_[id].count = end - begin;
        for (std::uint32_t i = begin; i < end; ++i)
            leafOf_[order_[i]] = id;
        return id;
    }
    const glm::dvec3 e = centerBox.extent();
    const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    const std::uint32_t mid = begin + (end - begin) / 2;
    // Ties broken by item index so the shape is a pure function of the input.
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) {
                         const double ca = centers[a][axis];
                         const double cb = centers[b][axis];
                         return ca < cb || (ca == cb && a < b);
                     });
    const std::uint32_t left = buildRange(begin, mid, items, centers, id);
    const std::uint32_t right = buildRange(mid, end, items, centers, id);
    nodes_[id].first = left;
    nodes_[id].second = right;
    return id;
}

void MergeBvh::grow(std::uint32_t item, const Aabb& box, double fv) {
    std::uint32_t n = leafOf_[item];
    while (n != 0xffffffffu) {
        Region& r = nodes_[n].region;
        const bool holdsBox = glm::all(glm::lessThanEqual(r.box.min, box.min)) &&
                              glm::all(glm::greaterThanEqual(r.box.max, box.max));
        if (holdsBox && r.maxFv >= fv) return; // ancestors hold what this node holds
        r.box.expand(box);
        r.maxFv = std::max(r.maxFv, fv);
        n = nodes_[n].parent;
    }
}

} // namespace hlod
