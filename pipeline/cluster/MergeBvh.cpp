// Median-split BVH for best-partner queries (see MergeBvh.h).
#include "pipeline/cluster/MergeBvh.h"

#include <algorithm>

namespace hlod {

namespace {

constexpr std::uint32_t kLeafSize = 4;

} // namespace

void MergeBvh::build(const std::vector<Aabb>& boxes, const std::vector<double>& fv) {
    boxes_ = &boxes;
    fv_ = &fv;
    const auto n = static_cast<std::uint32_t>(boxes.size());
    nodes_.clear();
    order_.resize(n);
    leafOf_.assign(n, 0);
    if (n == 0) return;
    nodes_.reserve(2 * (n / kLeafSize + 1));
    std::vector<glm::dvec3> centers(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        order_[i] = i;
        centers[i] = boxes[i].center();
    }
    buildRange(0, n, centers, 0xffffffffu);
}

std::uint32_t MergeBvh::buildRange(std::uint32_t begin, std::uint32_t end,
                                   const std::vector<glm::dvec3>& centers,
                                   std::uint32_t parent) {
    const auto id = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back(Node{});
    nodes_[id].parent = parent;
    Aabb box;
    Aabb centerBox;
    double maxFv = 0.0;
    for (std::uint32_t i = begin; i < end; ++i) {
        box.expand((*boxes_)[order_[i]]);
        centerBox.expand(centers[order_[i]]);
        maxFv = std::max(maxFv, (*fv_)[order_[i]]);
    }
    nodes_[id].box = box;
    nodes_[id].maxFv = maxFv;
    if (end - begin <= kLeafSize) {
        nodes_[id].first = begin;
        nodes_[id].count = end - begin;
        for (std::uint32_t i = begin; i < end; ++i) leafOf_[order_[i]] = id;
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
    const std::uint32_t left = buildRange(begin, mid, centers, id);
    const std::uint32_t right = buildRange(mid, end, centers, id);
    nodes_[id].first = left;
    nodes_[id].second = right;
    return id;
}

void MergeBvh::grow(std::uint32_t item, const Aabb& box, double fv) {
    std::uint32_t n = leafOf_[item];
    while (n != 0xffffffffu) {
        Node& node = nodes_[n];
        const bool holdsBox = glm::all(glm::lessThanEqual(node.box.min, box.min)) &&
                              glm::all(glm::greaterThanEqual(node.box.max, box.max));
        if (holdsBox && node.maxFv >= fv) return; // ancestors hold what this node holds
        node.box.expand(box);
        node.maxFv = std::max(node.maxFv, fv);
        n = node.parent;
    }
}

} // namespace hlod
