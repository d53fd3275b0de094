// Line plots rasterised into an RGB image (no plotting library): frame time and draw calls over
// the camera path, one line per configuration, with axes, "nice" tick values (1, 2, 5 x 10^n),
// axis labels, a title and a legend.
#pragma once

#include <string>
#include <vector>

#include "pipeline/eval/Image.h"

namespace hlod {

struct PlotSeries {
    std::string name;
    std::vector<double> x;
    std::vector<double> y; // same length as x; non-finite points break the line
    Rgb color{0, 0, 0};
};

struct PlotOptions {
    int width = 1100;
    int height = 600;
    std::string title;
    std::string xLabel;
    std::string yLabel;
    bool yFromZero = true; // the y axis starts at 0 (else at the data minimum)
    bool logY = false;     // log10 y axis (values <= 0 are skipped)
};

// The colours given to series 0, 1, 2, ... (distinct, readable on white).
Rgb seriesColor(std::size_t index);

// Step of about range / target ticks, rounded to 1, 2 or 5 times a power of ten.
double niceTickStep(double range, int targetTicks);
// Tick label: integers without decimals, else as few decimals as the step needs.
std::string formatTick(double value, double step);

// Throws Error(InvalidArgument) for a size under 200x150 or a series whose x and y differ in
// length. Empty series (or no finite point at all) give axes over [0, 1].
RgbImage renderLinePlot(const std::vector<PlotSeries>& series, const PlotOptions& options);

} // namespace hlod
