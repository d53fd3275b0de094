// 4-wide BVH in Morton order for best-partner queries and the self-join (see MergeBvh.h).
#include "pipeline/cluster/MergeBvh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <numeric>

#include "pipeline/cluster/Morton.h"
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
                     const CostModel& model, const std::vector<std::uint64_t>* given) {
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
    const bool haveCodes = given != nullptr && given->size() == n;
    if (!haveCodes)
        mortonCodes(
            n, [&](std::size_t i) { return items[i].box.center(); }, codes_);
    const std::vector<std::uint64_t>& codes = haveCodes ? *given : codes_;
    groupByClass(sizeClass);
    keys_.resize(n);
    std::vector<Slot> tops;
    std::uint32_t begin = 0;
    while (begin < n) {
        std::uint32_t end = begin + 1;
        while (end < n && sizeClass[order_[end]] == sizeClass[order_[begin]])
            ++end;
        // The class in Morton order, ties by item (a level's items come in that order
        // already: then only the check runs).
        const ByCode byCode{codes};
        if (!std::is_sorted(order_.begin() + begin, order_.begin() + end, byCode))
            std::sort(order_.begin() + begin, order_.begin() + end, byCode);
        for (std::uint32_t p = begin; p < end; ++p)
            keys_[p] = codes[order_[p]];
        tops.push_back(buildRange(begin, end, items));
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

std::uint32_t MergeBvh::split(std::uint32_t begin, std::uint32_t end) const {
    // keys_[begin, end) ascending, end - begin >= 2. They share the bits above the highest one
    // in which the first and last differ: the range splits where that bit turns on.
    const std::uint64_t first = keys_[begin];
    const std::uint64_t last = keys_[end - 1];
    if (first == last) return begin + (end - begin) / 2;
    const std::uint64_t bit = std::uint64_t{1} << (63 - std::countl_zero(first ^ last));
    const auto at = std::partition_point(keys_.begin() + begin, keys_.begin() + end,
                                         [&](std::uint64_t key) { return (key & bit) == 0; });
    return static_cast<std::uint32_t>(at - keys_.begin());
}

MergeBvh::Slot MergeBvh::buildRange(std::uint32_t begin, std::uint32_t end,
                                    const std::vector<Region>& items) {
    if (end - begin == 1) return Slot{kItem | begin, end, items[order_[begin]]};
    // Up to four parts: the two halves of split(), each split again if it holds two items or
    // more (a half of one item stays one part).
    std::array<std::uint32_t, 5> cut{begin, begin + 1, begin + 2, begin + 3, end};
    std::size_t count = end - begin;
    if (count > 4) {
        const std::uint32_t mid = split(begin, end);
        count = 0;
        for (const auto& [lo, hi] : {std::pair{begin, mid}, std::pair{mid, end}}) {
            if (hi - lo >= 2) cut[++count] = split(lo, hi);
            cut[++count] = hi;
        }
    } else {
        cut[count] = end;
    }
    std::array<Slot, 4> parts;
    for (std::size_t i = 0; i < count; ++i)
        parts[i] = buildRange(cut[i], cut[i + 1], items);
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
