// Order-independent iterative dilation, see DilateAtlas.h.
#include "pipeline/proxy/atlas/DilateAtlas.h"

#include <algorithm>
#include <cmath>

namespace hlod {

namespace {

// One channel group (colour: r, g, b; or alpha) spread from `known` texels. Each pass visits
// only its frontier (unknown texels next to known ones) and reads values known before it.
void spread(RgbaImage& image, std::vector<std::uint8_t> known, int first, int count, int passes) {
    const int w = image.width, h = image.height;
    auto forNeighbours = [&](std::size_t i, auto&& f) {
        const int x = static_cast<int>(i % static_cast<std::size_t>(w));
        const int y = static_cast<int>(i / static_cast<std::size_t>(w));
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int nx = x + dx, ny = y + dy;
                if ((dx || dy) && nx >= 0 && ny >= 0 && nx < w && ny < h)
                    f(static_cast<std::size_t>(ny) * w + nx);
            }
    };
    // The first frontier: unknown texels with a known texel in their 3 x 3 block, found from
    // each row's vertical OR of three rows (no division per texel), in index order.
    std::vector<std::size_t> frontier;
    std::vector<std::uint8_t> queued(known.size(), 0);
    std::vector<std::uint8_t> column(static_cast<std::size_t>(w) + 2, 0);
    for (int y = 0; y < h; ++y) {
        const std::uint8_t* row = &known[static_cast<std::size_t>(y) * w];
        const std::uint8_t* above = y > 0 ? row - w : nullptr;
        const std::uint8_t* below = y + 1 < h ? row + w : nullptr;
        for (int x = 0; x < w; ++x)
            column[static_cast<std::size_t>(x) + 1] =
                static_cast<std::uint8_t>(row[x] | (above ? above[x] : 0) | (below ? below[x] : 0));
        for (int x = 0; x < w; ++x) {
            if (row[x]) continue;
            const std::size_t c = static_cast<std::size_t>(x) + 1;
            if (column[c - 1] | column[c] | column[c + 1]) {
                const std::size_t i = static_cast<std::size_t>(y) * w + x;
                frontier.push_back(i);
                queued[i] = 1;
            }
        }
    }
    std::vector<std::uint8_t> values;
    for (int pass = 0; pass < passes && !frontier.empty(); ++pass) {
        // Values first (from texels known before the pass), then mark: order-independent.
        values.assign(frontier.size() * 4, 0);
        for (std::size_t f = 0; f < frontier.size(); ++f) {
            int sum[4] = {0, 0, 0, 0}, n = 0;
            forNeighbours(frontier[f], [&](std::size_t j) {
                if (!known[j]) return;
                for (int c = 0; c < count; ++c)
                    sum[c] += image.pixels[j * 4 + static_cast<std::size_t>(first + c)];
                ++n;
            });
            for (int c = 0; c < count; ++c)
                values[f * 4 + static_cast<std::size_t>(c)] =
                    static_cast<std::uint8_t>((sum[c] + n / 2) / std::max(n, 1));
        }
        std::vector<std::size_t> next;
        for (std::size_t f = 0; f < frontier.size(); ++f) {
            const std::size_t i = frontier[f];
            for (int c = 0; c < count; ++c)
                image.pixels[i * 4 + static_cast<std::size_t>(first + c)] =
                    values[f * 4 + static_cast<std::size_t>(c)];
            known[i] = 1;
        }
        for (std::size_t i : frontier)
            forNeighbours(i, [&](std::size_t j) {
                if (!known[j] && !queued[j]) {
                    queued[j] = 1;
                    next.push_back(j);
                }
            });
        std::sort(next.begin(), next.end());
        frontier = std::move(next);
    }
    // Whatever no pass reached: the mean of the known texels.
    long long sum[4] = {0, 0, 0, 0}, n = 0;
    for (std::size_t i = 0; i < known.size(); ++i) {
        if (!known[i]) continue;
        for (int c = 0; c < count; ++c)
            sum[c] += image.pixels[i * 4 + static_cast<std::size_t>(first + c)];
        ++n;
    }
    std::uint8_t fill[4];
    for (int c = 0; c < count; ++c)
        fill[c] =
            static_cast<std::uint8_t>(n > 0 ? (sum[c] + n / 2) / n : (first == 3 ? 255 : 128));
    for (std::size_t i = 0; i < known.size(); ++i) {
        if (known[i]) continue;
        for (int c = 0; c < count; ++c)
            image.pixels[i * 4 + static_cast<std::size_t>(first + c)] = fill[c];
    }
}

} // namespace

void dilateAtlas(RgbaImage& image, const std::vector<TexelState>& state, int passes) {
    std::vector<std::uint8_t> colourKnown(state.size()), alphaKnown(state.size());
    bool cutOut = false;
    for (std::size_t i = 0; i < state.size(); ++i) {
        colourKnown[i] = state[i] == TexelState::Opaque;
        alphaKnown[i] = state[i] != TexelState::Empty;
        cutOut = cutOut || state[i] == TexelState::CutOut;
    }
    spread(image, std::move(colourKnown), 0, 3, passes);
    if (cutOut) {
        spread(image, std::move(alphaKnown), 3, 1, passes);
    } else { // every covered texel is opaque: so is everything
        for (std::size_t i = 3; i < image.pixels.size(); i += 4)
            image.pixels[i] = 255;
    }
}

} // namespace hlod
