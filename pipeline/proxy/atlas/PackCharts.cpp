// Atlas sizing and skyline packing with stb_rect_pack, see PackCharts.h.
#include "pipeline/proxy/atlas/PackCharts.h"

#include <algorithm>
#include <cmath>

#include <stb_rect_pack.h>

namespace hlod {

namespace {

glm::ivec2 rectOf(const Chart& chart, float texelSize, int padding) {
    const int w = std::max(1, static_cast<int>(std::ceil(chart.size.x / texelSize)));
    const int h = std::max(1, static_cast<int>(std::ceil(chart.size.y / texelSize)));
    return {w + 2 * padding, h + 2 * padding};
}

bool tryPack(const std::vector<glm::ivec2>& sizes, int width, int height,
             std::vector<ChartPlacement>& out) {
    std::vector<stbrp_rect> rects(sizes.size());
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        rects[i].id = static_cast<int>(i);
        rects[i].w = sizes[i].x;
        rects[i].h = sizes[i].y;
    }
    std::vector<stbrp_node> nodes(static_cast<std::size_t>(width));
    stbrp_context context;
    stbrp_init_target(&context, width, height, nodes.data(), width);
    stbrp_setup_heuristic(&context, STBRP_HEURISTIC_Skyline_BL_sortHeight);
    if (!stbrp_pack_rects(&context, rects.data(), static_cast<int>(rects.size()))) return false;
    out.resize(sizes.size());
    for (const stbrp_rect& r : rects)
        out[static_cast<std::size_t>(r.id)] = {{r.x, r.y}, {r.w, r.h}};
    return true;
}

} // namespace

int roundUp4(double v) { return (static_cast<int>(std::ceil(v)) + 3) & ~3; }

AtlasLayout packCharts(const std::vector<Chart>& charts, float texelSize, int maxSize,
                       int padding) {
    AtlasLayout layout;
    layout.padding = padding;
    layout.texelSize = texelSize;
    for (int attempt = 0; attempt < 200; ++attempt) {
        std::vector<glm::ivec2> sizes;
        double area = 0.0;
        int widest = 1, tallest = 1;
        for (const Chart& c : charts) {
            sizes.push_back(rectOf(c, layout.texelSize, padding));
            area += static_cast<double>(sizes.back().x) * sizes.back().y;
            widest = std::max(widest, sizes.back().x);
            tallest = std::max(tallest, sizes.back().y);
        }
        // A square with room for the area (packers need some slack) and the largest
        // rectangle, grown by 6 % steps until everything fits; then cut to the rows used.
        int side = std::max({16, widest, roundUp4(std::sqrt(area * 1.08))});
        int w = std::min(roundUp4(side), maxSize), h = std::min(std::max(w, roundUp4(tallest)), maxSize);
        while (widest <= maxSize && tallest <= maxSize) {
            if (widest <= w && tallest <= h && tryPack(sizes, w, h, layout.placements)) {
                int used = 0;
                for (const ChartPlacement& p : layout.placements)
                    used = std::max(used, p.offset.y + p.size.y);
                layout.width = w;
                layout.height = std::max(16, roundUp4(used));
                return layout;
            }
            if (w == maxSize && h == maxSize) break;
            w = std::min(maxSize, roundUp4(w * 1.06));
            h = std::min(maxSize, roundUp4(h * 1.06));
        }
        layout.texelSize *= 1.15f; // does not fit the cap: coarser texels
    }
    layout.placements.assign(charts.size(), {});
    layout.width = layout.height = 0; // cannot happen for a finite chart set; caller checks
    return layout;
}

} // namespace hlod
