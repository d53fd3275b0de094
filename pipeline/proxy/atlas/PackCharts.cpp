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
        // The smallest power-of-two sizes with room for the area (packers need some slack)
        // and the largest rectangle, width >= height, growing one side at a time.
        int w = 16, h = 16;
        while ((w < widest || static_cast<double>(w) * h < area * 1.1) && w < maxSize) {
            if (w <= h) w *= 2;
            else h *= 2;
        }
        while (h < tallest && h < maxSize)
            h *= 2;
        while (true) {
            if (widest <= w && tallest <= h && tryPack(sizes, w, h, layout.placements)) {
                layout.width = w;
                layout.height = h;
                return layout;
            }
            if (w == maxSize && h == maxSize) break;
            if (h < w) h *= 2;
            else w *= 2;
        }
        layout.texelSize *= 1.15f; // does not fit the cap: coarser texels
    }
    layout.placements.assign(charts.size(), {});
    layout.width = layout.height = 0; // cannot happen for a finite chart set; caller checks
    return layout;
}

} // namespace hlod
