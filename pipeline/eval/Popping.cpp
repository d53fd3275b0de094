// Popping at level-of-detail switches (Popping.h has the definition and why).
#include "pipeline/eval/Popping.h"

#include <algorithm>
#include <string>

#include "pipeline/core/Error.h"
#include "pipeline/eval/Flip.h"

namespace hlod {

namespace {

void checkSameSize(const RgbImage& a, const RgbImage& b) {
    if (a.empty() || b.empty()) throw Error(ErrorCode::InvalidArgument, "pop: empty image");
    if (a.width != b.width || a.height != b.height)
        throw Error(ErrorCode::InvalidArgument, "pop: sizes differ (" + std::to_string(a.width) +
                                                    "x" + std::to_string(a.height) + " vs " +
                                                    std::to_string(b.width) + "x" +
                                                    std::to_string(b.height) + ")");
}

// Some ancestor of a unit of `units` that `units` does not hold is in `other`.
bool ancestorIn(const std::vector<int>& units, const std::vector<int>& other,
                const std::function<int(int)>& parent) {
    for (int u : units) {
        if (std::binary_search(other.begin(), other.end(), u)) continue; // drawn in both
        for (int p = parent(u); p >= 0; p = parent(p))
            if (std::binary_search(other.begin(), other.end(), p)) return true;
    }
    return false;
}

} // namespace

RgbImage carriedForward(const RgbImage& previous, const RgbImage& originalPrevious,
                        const RgbImage& originalCurrent) {
    checkSameSize(previous, originalPrevious);
    checkSameSize(previous, originalCurrent);
    RgbImage out = previous;
    for (std::size_t i = 0; i < out.pixels.size(); ++i) {
        const int v = static_cast<int>(previous.pixels[i]) + originalCurrent.pixels[i] -
                      originalPrevious.pixels[i];
        out.pixels[i] = static_cast<std::uint8_t>(std::clamp(v, 0, 255));
    }
    return out;
}

double popFlip(const RgbImage& previous, const RgbImage& current, const RgbImage& originalPrevious,
               const RgbImage& originalCurrent, double pixelsPerDegree) {
    checkSameSize(previous, current);
    return meanFlip(carriedForward(previous, originalPrevious, originalCurrent), current,
                    pixelsPerDegree);
}

bool lodSwitched(const std::vector<int>& previous, const std::vector<int>& current,
                 const std::function<int(int)>& parent) {
    // A unit replaced by its descendants: each descendant (new in `current`) finds it among its
    // ancestors in `previous`; replaced by an ancestor: the old unit finds it in `current`.
    return ancestorIn(current, previous, parent) || ancestorIn(previous, current, parent);
}

} // namespace hlod
