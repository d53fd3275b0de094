// 4-wide median-split BVH for best-partner queries and the self-join (see MergeBvh.h).
#include "pipeline/cluster/MergeBvh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <numeric>

#include "pipeline/scene/Aabb.h"

namespace hlod {

MergeBvh::Simd MergeBvh::bestSimd() {
#if HLOD_WIDE_AVX2
    static const bool avx2 = __builtin_cpu_supports("avx2") != 0;
    return avx2 ? Simd::Avx2 : Simd::Baseline;
#else
    return Simd::Baseline;
#endif
}

void MergeBvh::build(const std::vector<Region>& items, const std::vector<int>& sizeClass,
                     const CostModel& model) {
    const auto n = static_cast<std::uint32_t>(items.size());
    model_ = &model;
    kind_ = boundKindOf(model);
    const bool boxModel = model.volume() == VolumeType::Aabb;
    nodes_.clear();
    order_.resize(n);
    position_.resize(n);
    packed_.resize(n);
    packedExtra_.assign(n, PackedExtra{});
    if (n == 0) return;
    nodes_.reserve(n / 2 + 16);
    std::vector<glm::dvec3>& centers = centers_;
    centers.resize(n);
    for (std::uint32_t i = 0; i < n; ++i)
        centers[i] = items[i].box.center();
    groupByClass(sizeClass);
    std::vector<Slot> tops;
    std::uint32_t begin = 0;
    while (begin < n) {
        std::uint32_t end = begin + 1;
        while (end < n && sizeClass[order_[end]] == sizeClass[order_[begin]])
            ++end;
        tops.push_back(buildRange(begin, end, items, centers));
        begin = end;
    }
    // The class hierarchies under one top, four slots per node in class order.
    while (tops.size() > 1 || (tops[0].child & kItem) != 0) {
        std::vector<Slot> above;
        for (std::size_t i = 0; i < tops.size(); i += 4) {
            above.push_back(makeNode(tops.data() + i, std::min<std::size_t>(4, tops.size() - i)));
        }
        tops = std::move(above);
    }
    root_ = tops[0].child;
    packRegion(tops[0].region, boxModel, rootRegion_, rootExtra_);
}

void MergeBvh::groupByClass(const std::vector<int>& sizeClass) {
    // Items grouped by size class, ties in item order (a stable sort by class): counting sort
    // over the class range, which spans a few binary exponents in practice; a comparison sort
    // of (class, item) for pathological ranges.
    const auto n = static_cast<std::uint32_t>(sizeClass.size());
    const auto [lo, hi] = std::minmax_element(sizeClass.begin(), sizeClass.end());
    const std::int64_t range = std::int64_t{*hi} - *lo + 1;
    if (range <= 4096) {
        std::vector<std::uint32_t>& start = classStart_;
        start.assign(static_cast<std::size_t>(range) + 1, 0);
        for (std::uint32_t i = 0; i < n; ++i)
            ++start[static_cast<std::size_t>(std::int64_t{sizeClass[i]} - *lo) + 1];
        for (std::size_t c = 1; c < start.size(); ++c)
            start[c] += start[c - 1];
        for (std::uint32_t i = 0; i < n; ++i)
            order_[start[static_cast<std::size_t>(std::int64_t{sizeClass[i]} - *lo)]++] = i;
        return;
    }
    std::iota(order_.begin(), order_.end(), 0u);
    std::sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) {
        return sizeClass[a] < sizeClass[b] || (sizeClass[a] == sizeClass[b] && a < b);
    });
}

std::uint32_t MergeBvh::medianSplit(std::uint32_t begin, std::uint32_t end,
                                    const std::vector<glm::dvec3>& centers) {
    Aabb centerBox;
    for (std::uint32_t i = begin; i < end; ++i)
        centerBox.expand(centers[order_[i]]);
    const glm::dvec3 e = centerBox.extent();
    const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    const std::uint32_t mid = begin + (end - begin) / 2;
    // The keys are gathered once as 64-bit integers (the centre coordinate rounded to a float
    // in the high half, mapped so that integer order is float order; the item in the low half,
    // which breaks ties so the shape is a pure function of the input): the selection then
    // compares contiguous integers instead of loading two scattered centres per comparison.
    // (Rounding only decides which side of the median equal-looking centres fall: any split
    // gives the same answers, MergeBvh.h.)
    std::vector<std::uint64_t>& keyed = splitKeys_;
    keyed.resize(end - begin);
    for (std::uint32_t i = begin; i < end; ++i) {
        const auto bits =
            std::bit_cast<std::uint32_t>(static_cast<float>(centers[order_[i]][axis]));
        const std::uint32_t ordered = (bits & 0x80000000u) != 0 ? ~bits : bits | 0x80000000u;
        keyed[i - begin] = std::uint64_t{ordered} << 32 | order_[i];
    }
    std::nth_element(keyed.begin(), keyed.begin() + (mid - begin), keyed.end());
    for (std::uint32_t i = begin; i < end; ++i)
        order_[i] = static_cast<std::uint32_t>(keyed[i - begin]);
    return mid;
}

MergeBvh::Slot MergeBvh::buildRange(std::uint32_t begin, std::uint32_t end,
                                    const std::vector<Region>& items,
                                    const std::vector<glm::dvec3>& centers) {
    if (end - begin == 1) return Slot{kItem | begin, end, items[order_[begin]]};
    std::array<std::uint32_t, 5> cut{begin, begin + 1, begin + 2, begin + 3, end};
    std::size_t count = end - begin; // parts
    if (count > 4) {
        count = 4;
        cut[2] = medianSplit(begin, end, centers);
        cut[1] = medianSplit(begin, cut[2], centers);
        cut[3] = medianSplit(cut[2], end, centers);
    } else {
        cut[count] = end;
    }
    std::array<Slot, 4> parts;
    for (std::size_t i = 0; i < count; ++i)
        parts[i] = buildRange(cut[i], cut[i + 1], items, centers);
    return makeNode(parts.data(), count);
}

MergeBvh::Slot MergeBvh::makeNode(const Slot* parts, std::size_t count) {
    const auto id = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    Node& node = nodes_.back();
    Slot out{id, 0, emptyRegion()};
    for (std::size_t l = 0; l < count; ++l) {
        const Slot& part = parts[l];
        const bool boxModel = model_->volume() == VolumeType::Aabb;
        if ((part.child & kItem) != 0) {
            // An item's position is final once it is a slot (every split around it is done):
            // its packed region is kept for the queries it makes.
            const std::uint32_t p = part.child & ~kItem;
            position_[order_[p]] = p;
            packRegion(part.region, boxModel, packed_[p], packedExtra_[p]);
            setLane(node.slots, static_cast<int>(l), packed_[p], packedExtra_[p]);
        } else {
            PackedRegion r{};
            PackedExtra e{};
            packRegion(part.region, boxModel, r, e);
            setLane(node.slots, static_cast<int>(l), r, e);
        }
        node.child[l] = part.child;
        node.end[l] = part.end;
        includeRegion(out.region, part.region);
        out.end = std::max(out.end, part.end);
    }
    return out;
}

} // namespace hlod
