// BVH build and queries, see SurfaceBvh.h.
#include "pipeline/proxy/atlas/SurfaceBvh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hlod {

namespace {

constexpr std::uint32_t kLeafSize = 4;

float boxDistanceSquared(const glm::vec3& p, const glm::vec3& lo, const glm::vec3& hi) {
    const glm::vec3 d = glm::max(glm::max(lo - p, p - hi), glm::vec3(0.0f));
    return glm::dot(d, d);
}

// Ericson 5.1.5: the point of triangle abc closest to p, as barycentric weights.
glm::vec3 closestBary(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
                      const glm::vec3& c) {
    const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0f && d2 <= 0.0f) return {1, 0, 0};
    const glm::vec3 bp = p - b;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0f && d4 <= d3) return {0, 1, 0};
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) {
        const float v = d1 / (d1 - d3);
        return {1 - v, v, 0};
    }
    const glm::vec3 cp = p - c;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0f && d5 <= d6) return {0, 0, 1};
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) {
        const float w = d2 / (d2 - d6);
        return {1 - w, 0, w};
    }
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f) {
        const float w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {0, 1 - w, w};
    }
    const float sum = va + vb + vc;
    if (!(std::abs(sum) > 0.0f)) return {1, 0, 0}; // degenerate: its first corner
    const float v = vb / sum, w = vc / sum;
    return {1 - v - w, v, w};
}

} // namespace

SurfaceBvh::SurfaceBvh(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices)
    : positions_(positions), indices_(indices) {
    const auto n = static_cast<std::uint32_t>(indices.size() / 3);
    if (n == 0) return;
    order_.resize(n);
    std::vector<glm::vec3> centroids(n);
    for (std::uint32_t t = 0; t < n; ++t) {
        order_[t] = t;
        centroids[t] = (corner(t, 0) + corner(t, 1) + corner(t, 2)) / 3.0f;
    }
    nodes_.reserve(2 * (n / kLeafSize + 1));
    build(0, n, centroids, 0);
    edges_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const glm::vec3 a = corner(order_[i], 0);
        edges_[i] = Edges{a, corner(order_[i], 1) - a, corner(order_[i], 2) - a};
    }
}

// Binned surface area heuristic (Wald 2007): 16 bins of the centroids along `axis`, the split
// with the least sum of box area x triangle count; the median when no bin split separates.
std::uint32_t SurfaceBvh::sahSplit(std::uint32_t begin, std::uint32_t end,
                                   const std::vector<glm::vec3>& centroids, int axis, float lo,
                                   float extent) {
    constexpr int kBins = 16;
    struct Bin {
        glm::vec3 lo{std::numeric_limits<float>::max()}, hi{-std::numeric_limits<float>::max()};
        std::uint32_t count = 0;
    } bins[kBins];
    auto binOf = [&](std::uint32_t t) {
        const int b = static_cast<int>((centroids[t][axis] - lo) / extent * kBins);
        return std::clamp(b, 0, kBins - 1);
    };
    for (std::uint32_t i = begin; i < end; ++i) {
        const std::uint32_t t = order_[i];
        Bin& b = bins[binOf(t)];
        ++b.count;
        for (int k = 0; k < 3; ++k) {
            b.lo = glm::min(b.lo, corner(t, k));
            b.hi = glm::max(b.hi, corner(t, k));
        }
    }
    auto area = [](const glm::vec3& a, const glm::vec3& b) {
        const glm::vec3 d = glm::max(b - a, glm::vec3(0.0f));
        return d.x * d.y + d.y * d.z + d.z * d.x;
    };
    float rightCost[kBins] = {};
    glm::vec3 rlo(std::numeric_limits<float>::max()), rhi(-std::numeric_limits<float>::max());
    std::uint32_t rcount = 0;
    for (int b = kBins - 1; b > 0; --b) {
        rlo = glm::min(rlo, bins[b].lo);
        rhi = glm::max(rhi, bins[b].hi);
        rcount += bins[b].count;
        rightCost[b] = rcount ? area(rlo, rhi) * static_cast<float>(rcount) : 0.0f;
    }
    glm::vec3 llo(std::numeric_limits<float>::max()), lhi(-std::numeric_limits<float>::max());
    std::uint32_t lcount = 0;
    float bestCost = std::numeric_limits<float>::max();
    int bestBin = -1;
    for (int b = 1; b < kBins; ++b) {
        llo = glm::min(llo, bins[b - 1].lo);
        lhi = glm::max(lhi, bins[b - 1].hi);
        lcount += bins[b - 1].count;
        if (lcount == 0 || lcount == end - begin) continue;
        const float cost = area(llo, lhi) * static_cast<float>(lcount) + rightCost[b];
        if (cost < bestCost) {
            bestCost = cost;
            bestBin = b;
        }
    }
    if (bestBin < 0) {
        const std::uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                         [&](std::uint32_t a, std::uint32_t b) {
                             const float ca = centroids[a][axis], cb = centroids[b][axis];
                             return ca < cb || (ca == cb && a < b);
                         });
        return mid;
    }
    const auto split = std::stable_partition(order_.begin() + begin, order_.begin() + end,
                                             [&](std::uint32_t t) { return binOf(t) < bestBin; });
    return static_cast<std::uint32_t>(split - order_.begin());
}

std::uint32_t SurfaceBvh::build(std::uint32_t begin, std::uint32_t end,
                                const std::vector<glm::vec3>& centroids, int depth) {
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back({});
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    glm::vec3 clo = lo, chi = hi;
    for (std::uint32_t i = begin; i < end; ++i) {
        const std::uint32_t t = order_[i];
        for (int k = 0; k < 3; ++k) {
            lo = glm::min(lo, corner(t, k));
            hi = glm::max(hi, corner(t, k));
        }
        clo = glm::min(clo, centroids[t]);
        chi = glm::max(chi, centroids[t]);
    }
    nodes_[index].lo = lo;
    nodes_[index].hi = hi;
    const glm::vec3 extent = chi - clo;
    if (end - begin <= kLeafSize || depth > 60 ||
        std::max({extent.x, extent.y, extent.z}) <= 0.0f) {
        nodes_[index].first = begin;
        nodes_[index].count = end - begin;
        return index;
    }
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                     : extent.y >= extent.z                       ? 1
                                                                  : 2;
    const std::uint32_t mid = sahSplit(begin, end, centroids, axis, clo[axis], extent[axis]);
    build(begin, mid, centroids, depth + 1);
    const std::uint32_t right = build(mid, end, centroids, depth + 1);
    nodes_[index].first = right;
    nodes_[index].count = 0;
    return index;
}

ClosestPoint SurfaceBvh::closest(const glm::vec3& p, float maxDistanceSquared) const {
    ClosestPoint best;
    best.distanceSquared = maxDistanceSquared;
    if (nodes_.empty()) return best;
    std::uint32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const std::uint32_t id = stack[--top];
        const Node& node = nodes_[id];
        if (boxDistanceSquared(p, node.lo, node.hi) > best.distanceSquared) continue;
        if (node.count == 0) {
            const Node& left = nodes_[id + 1];
            const Node& right = nodes_[node.first];
            const float dl = boxDistanceSquared(p, left.lo, left.hi);
            const float dr = boxDistanceSquared(p, right.lo, right.hi);
            if (top + 2 > 128) continue;
            // Nearer child last (popped first); the order never changes the result.
            if (dl <= dr) {
                stack[top++] = node.first;
                stack[top++] = id + 1;
            } else {
                stack[top++] = id + 1;
                stack[top++] = node.first;
            }
            continue;
        }
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
            const std::uint32_t t = order_[i];
            const glm::vec3 a = corner(t, 0), b = corner(t, 1), c = corner(t, 2);
            const glm::vec3 w = closestBary(p, a, b, c);
            const glm::vec3 q = w.x * a + w.y * b + w.z * c;
            const float d = glm::dot(q - p, q - p);
            if (d < best.distanceSquared ||
                (d == best.distanceSquared && best.triangle != 0xffffffffu && t < best.triangle)) {
                best.triangle = t;
                best.distanceSquared = d;
                best.bary = w;
            }
        }
    }
    return best;
}

} // namespace hlod
