// Order-independent iterative dilation, see DilateAtlas.h.
#include "pipeline/proxy/atlas/DilateAtlas.h"

#include <cmath>

namespace hlod {

namespace {

// One channel group (colour: r, g, b; or alpha) spread from `known` texels.
void spread(RgbaImage& image, std::vector<std::uint8_t> known, int first, int count, int passes) {
    const int w = image.width, h = image.height;
    std::vector<std::uint8_t> next = known;
    for (int pass = 0; pass < passes; ++pass) {
        bool changed = false;
        const std::vector<std::uint8_t> before = image.pixels;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * w + x;
                if (known[i]) continue;
                int sum[4] = {0, 0, 0, 0}, n = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int nx = x + dx, ny = y + dy;
                        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                        const std::size_t j = static_cast<std::size_t>(ny) * w + nx;
                        if (!known[j]) continue;
                        for (int c = 0; c < count; ++c)
                            sum[c] += before[j * 4 + static_cast<std::size_t>(first + c)];
                        ++n;
                    }
                if (n == 0) continue;
                for (int c = 0; c < count; ++c)
                    image.pixels[i * 4 + static_cast<std::size_t>(first + c)] =
                        static_cast<std::uint8_t>((sum[c] + n / 2) / n);
                next[i] = 1;
                changed = true;
            }
        }
        known = next;
        if (!changed) break;
    }
    // Whatever no pass reached: the mean of the known texels.
    long long sum[4] = {0, 0, 0, 0}, n = 0;
    for (std::size_t i = 0; i < known.size(); ++i) {
        if (!known[i]) continue;
        for (int c = 0; c < count; ++c)
            sum[c] += image.pixels[i * 4 + static_cast<std::size_t>(first + c)];
        ++n;
    }
    for (std::size_t i = 0; i < known.size(); ++i) {
        if (known[i]) continue;
        for (int c = 0; c < count; ++c)
            image.pixels[i * 4 + static_cast<std::size_t>(first + c)] =
                static_cast<std::uint8_t>(n > 0 ? (sum[c] + n / 2) / n : (first == 3 ? 255 : 128));
    }
}

} // namespace

void dilateAtlas(RgbaImage& image, const std::vector<TexelState>& state, int passes) {
    std::vector<std::uint8_t> colourKnown(state.size()), alphaKnown(state.size());
    for (std::size_t i = 0; i < state.size(); ++i) {
        colourKnown[i] = state[i] == TexelState::Opaque;
        alphaKnown[i] = state[i] != TexelState::Empty;
    }
    spread(image, std::move(colourKnown), 0, 3, passes);
    spread(image, std::move(alphaKnown), 3, 1, passes);
}

} // namespace hlod
