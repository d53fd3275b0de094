#include "pipeline/eval/Plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "pipeline/core/Error.h"

namespace hlod {

Rgb seriesColor(std::size_t index) {
    static const Rgb kColors[] = {{0, 0, 0},      {230, 120, 0},  {0, 114, 178},
                                  {0, 158, 115},  {204, 50, 50},  {150, 80, 170},
                                  {140, 110, 20}, {86, 180, 233}, {120, 120, 120}};
    return kColors[index % (sizeof(kColors) / sizeof(kColors[0]))];
}

double niceTickStep(double range, int targetTicks) {
    if (!(range > 0.0) || !std::isfinite(range)) return 1.0;
    const double raw = range / std::max(targetTicks, 1);
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    const double m = raw / p;
    const double nice = m <= 1.0 ? 1.0 : m <= 2.0 ? 2.0 : m <= 5.0 ? 5.0 : 10.0;
    return nice * p;
}

std::string formatTick(double value, double step) {
    char buf[64];
    if (std::abs(value) < step * 1e-9) value = 0.0;
    int decimals = 0;
    if (step < 1.0) decimals = std::min(9, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
    if (std::abs(value) >= 1e6 && decimals == 0) {
        std::snprintf(buf, sizeof(buf), "%gM", value / 1e6);
    } else if (std::abs(value) >= 1e4 && decimals == 0 && std::fmod(value, 1000.0) == 0.0) {
        std::snprintf(buf, sizeof(buf), "%gk", value / 1e3);
    } else {
        std::snprintf(buf, sizeof(buf), "%.*f", decimals, value);
    }
    return buf;
}

RgbImage renderLinePlot(const std::vector<PlotSeries>& series, const PlotOptions& o) {
    if (o.width < 200 || o.height < 150)
        throw Error(ErrorCode::InvalidArgument, "plot: size under 200x150");
    for (const PlotSeries& s : series) {
        if (s.x.size() != s.y.size())
            throw Error(ErrorCode::InvalidArgument,
                        "plot: series '" + s.name + "' has x and y of different lengths");
    }
    auto ty = [&](double v) { return o.logY ? std::log10(v) : v; };
    auto usable = [&](double x, double y) {
        return std::isfinite(x) && std::isfinite(y) && (!o.logY || y > 0.0);
    };
    double x0 = std::numeric_limits<double>::max(), x1 = std::numeric_limits<double>::lowest();
    double y0 = x0, y1 = x1;
    for (const PlotSeries& s : series) {
        for (std::size_t i = 0; i < s.x.size(); ++i) {
            if (!usable(s.x[i], s.y[i])) continue;
            x0 = std::min(x0, s.x[i]);
            x1 = std::max(x1, s.x[i]);
            y0 = std::min(y0, ty(s.y[i]));
            y1 = std::max(y1, ty(s.y[i]));
        }
    }
    if (x0 > x1) {
        x0 = 0.0;
        x1 = 1.0;
        y0 = 0.0;
        y1 = 1.0;
    }
    if (o.yFromZero && !o.logY) y0 = std::min(0.0, y0);
    if (x1 - x0 <= 0.0) x1 = x0 + 1.0;
    if (y1 - y0 <= 0.0) {
        y1 = y0 + (y0 == 0.0 ? 1.0 : std::abs(y0) * 0.1);
    }
    // Round the y range out to whole ticks.
    const double yStep = o.logY ? 1.0 : niceTickStep(y1 - y0, 6);
    y0 = std::floor(y0 / yStep + 1e-9) * yStep;
    y1 = std::ceil(y1 / yStep - 1e-9) * yStep;
    if (y1 <= y0) y1 = y0 + yStep;
    const double xStep = niceTickStep(x1 - x0, 8);

    const Rgb white(255), axis(40), grid(225), text(30);
    RgbImage img(o.width, o.height, white);
    const int scale = 2;
    const int left = 30 + textWidth(formatTick(-y1 * 10.0, yStep), scale) + textHeight(scale);
    const int top = 20 + (o.title.empty() ? 0 : textHeight(3) + 16);
    const int legendRowH = textHeight(scale) + 10;
    const int legendW = [&] {
        int w = 0;
        for (const PlotSeries& s : series)
            w = std::max(w, textWidth(s.name, scale));
        return series.empty() ? 0 : w + 60;
    }();
    const int right = o.width - 20 - legendW;
    const int bottom = o.height - (30 + 2 * textHeight(scale) + 12);
    if (right - left < 40 || bottom - top < 40)
        throw Error(ErrorCode::InvalidArgument, "plot: too small for its labels");
    auto px = [&](double x) { return left + (x - x0) / (x1 - x0) * (right - left); };
    auto py = [&](double y) { return bottom - (ty(y) - y0) / (y1 - y0) * (bottom - top); };
    auto pyRaw = [&](double yt) { return bottom - (yt - y0) / (y1 - y0) * (bottom - top); };

    if (!o.title.empty())
        drawText(img, o.title, (left + right - textWidth(o.title, 3)) / 2, 16, 3, text);
    // Grid and y ticks.
    for (double v = y0; v <= y1 + yStep * 1e-6; v += yStep) {
        const int y = static_cast<int>(std::lround(pyRaw(v)));
        drawLine(img, left, y, right, y, grid);
        drawLine(img, left - 6, y, left, y, axis);
        const std::string label =
            o.logY ? formatTick(std::pow(10.0, v), std::pow(10.0, v)) : formatTick(v, yStep);
        drawText(img, label, left - 10 - textWidth(label, scale), y - textHeight(scale) / 2, scale,
                 text);
    }
    // X ticks.
    for (double v = std::ceil(x0 / xStep - 1e-9) * xStep; v <= x1 + xStep * 1e-6; v += xStep) {
        const int x = static_cast<int>(std::lround(px(v)));
        drawLine(img, x, top, x, bottom, grid);
        drawLine(img, x, bottom, x, bottom + 6, axis);
        const std::string label = formatTick(v, xStep);
        drawText(img, label, x - textWidth(label, scale) / 2, bottom + 12, scale, text);
    }
    // Axes.
    drawLine(img, left, top, left, bottom, axis, 2);
    drawLine(img, left, bottom, right, bottom, axis, 2);
    if (!o.xLabel.empty())
        drawText(img, o.xLabel, (left + right - textWidth(o.xLabel, scale)) / 2,
                 bottom + 20 + textHeight(scale), scale, text);
    if (!o.yLabel.empty())
        drawText(img, o.yLabel, 12, (top + bottom + textWidth(o.yLabel, scale)) / 2, scale, text,
                 true);
    // Lines (drawn in order; later series on top).
    for (const PlotSeries& s : series) {
        bool have = false;
        double lx = 0.0, ly = 0.0;
        for (std::size_t i = 0; i < s.x.size(); ++i) {
            if (!usable(s.x[i], s.y[i])) {
                have = false;
                continue;
            }
            const double cx = px(s.x[i]), cy = py(s.y[i]);
            if (have)
                drawLine(img, lx, ly, cx, cy, s.color, 2);
            else
                drawLine(img, cx, cy, cx, cy, s.color, 2);
            lx = cx;
            ly = cy;
            have = true;
        }
    }
    // Legend, right of the plot area.
    int ly = top;
    for (const PlotSeries& s : series) {
        const int lx = right + 16;
        img.fillRect(lx, ly + textHeight(scale) / 2 - 2, lx + 30, ly + textHeight(scale) / 2 + 2,
                     s.color);
        drawText(img, s.name, lx + 38, ly, scale, text);
        ly += legendRowH;
    }
    return img;
}

} // namespace hlod
