// Median-split BVH forest for best-partner queries and the self-join (see MergeBvh.h).
#include "pipeline/cluster/MergeBvh.h"

#include <numeric>

namespace hlod {

namespace {

constexpr std::uint32_t kLeafSize = 4;

} // namespace

void MergeBvh::build(const std::vector<Region>& items, const std::vector<int>& sizeClass,
                     bool boxModel) {
    const auto n = static_cast<std::uint32_t>(items.size());
    boxModel_ = boxModel;
    nodes_.clear();
    nodeExtra_.clear();
    roots_.clear();
    order_.resize(n);
    ordered_.resize(n);
    orderedExtra_.resize(boxModel_ ? n : 0);
    if (n == 0) return;
    nodes_.reserve(2 * (n / kLeafSize + 1) + 64);
    if (boxModel_) nodeExtra_.reserve(nodes_.capacity());
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
        roots_.push_back(buildRange(begin, end, items, centers));
        begin = end;
    }
    PackedExtra unused{};
    for (std::uint32_t i = 0; i < n; ++i) {
        packRegion(items[order_[i]], boxModel_, ordered_[i], boxModel_ ? orderedExtra_[i] : unused);
    }
}

std::uint32_t MergeBvh::buildRange(std::uint32_t begin, std::uint32_t end,
                                   const std::vector<Region>& items,
                                   const std::vector<glm::dvec3>& centers) {
    const auto id = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back(Node{});
    if (boxModel_) nodeExtra_.emplace_back();
    PackedExtra unused{};
    PackedExtra& extra = boxModel_ ? nodeExtra_[id] : unused;
    if (end - begin <= kLeafSize) {
        Region region = emptyRegion();
        for (std::uint32_t i = begin; i < end; ++i) {
            includeRegion(region, items[order_[i]]);
        }
        packRegion(region, boxModel_, nodes_[id].region, extra);
        nodes_[id].first = begin;
        nodes_[id].count = end - begin;
        return id;
    }
    Aabb centerBox;
    for (std::uint32_t i = begin; i < end; ++i)
        centerBox.expand(centers[order_[i]]);
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
    const std::uint32_t left = buildRange(begin, mid, items, centers);
    const std::uint32_t right = buildRange(mid, end, items, centers);
    // The region bottom-up from the children (one merge per node, not one per item and
    // depth); the children's packed regions are floats already, so packing their union is
    // exact. nodeExtra_ may have grown: take the slot again.
    Region region = unpackRegion(nodeRef(left));
    includeRegion(region, unpackRegion(nodeRef(right)));
    packRegion(region, boxModel_, nodes_[id].region, boxModel_ ? nodeExtra_[id] : unused);
    nodes_[id].first = right;
    return id;
}

} // namespace hlod
