// The plot rasteriser and image helpers of `hlod bench`: a PNG of the expected size with
// non-background pixels where the lines, axes and labels are.
#include <gtest/gtest.h>

#include <cstring>

#include <stb_image.h>

#include "TestUtil.h"
#include "pipeline/core/Error.h"
#include "pipeline/eval/Plot.h"

using namespace hlod;

namespace {

std::size_t countColor(const RgbImage& img, Rgb c) {
    std::size_t n = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            n += img.at(x, y) == c;
    return n;
}

} // namespace

TEST(Plot, NiceTicks) {
    EXPECT_DOUBLE_EQ(niceTickStep(30.0, 8), 5.0);
    EXPECT_DOUBLE_EQ(niceTickStep(1.0, 5), 0.2);
    EXPECT_DOUBLE_EQ(niceTickStep(4500.0, 6), 1000.0);
    EXPECT_EQ(formatTick(5.0, 5.0), "5");
    EXPECT_EQ(formatTick(0.4, 0.2), "0.4");
    EXPECT_EQ(formatTick(20000.0, 5000.0), "20k");
}

TEST(Plot, PngHasTheSizeAndDrawnLines) {
    PlotSeries a{"Original", {0, 1, 2, 3}, {10, 20, 15, 30}, Rgb(230, 120, 0)};
    PlotSeries b{"HLOD, sphere", {0, 1, 2, 3}, {2, 3, 2, 4}, Rgb(0, 114, 178)};
    PlotOptions o;
    o.width = 800;
    o.height = 450;
    o.title = "Draw calls";
    o.xLabel = "Time (s)";
    o.yLabel = "Draw calls";
    const RgbImage img = renderLinePlot({a, b}, o);
    ASSERT_EQ(img.width, 800);
    ASSERT_EQ(img.height, 450);
    EXPECT_GT(countColor(img, a.color), 100u); // a line plus its legend swatch
    EXPECT_GT(countColor(img, b.color), 100u);
    EXPECT_GT(countColor(img, Rgb(30)), 200u);                       // text
    EXPECT_GT(countColor(img, Rgb(255)), img.pixels.size() / 3 / 2); // mostly background

    hlod::test::TempDir dir;
    const auto file = dir / "plot.png";
    writePng(file, img);
    int w = 0, h = 0, n = 0;
    unsigned char* px = stbi_load(file.string().c_str(), &w, &h, &n, 3);
    ASSERT_NE(px, nullptr);
    EXPECT_EQ(w, 800);
    EXPECT_EQ(h, 450);
    EXPECT_EQ(std::memcmp(px, img.pixels.data(), img.pixels.size()), 0);
    stbi_image_free(px);
    EXPECT_FALSE(std::filesystem::exists(dir / "plot.png.tmp"));
}

TEST(Plot, EmptyAndDegenerateSeriesStillDrawAxes) {
    PlotOptions o;
    const RgbImage empty = renderLinePlot({}, o);
    EXPECT_EQ(empty.width, o.width);
    EXPECT_GT(countColor(empty, Rgb(40)), 100u); // axes
    PlotSeries flat{"flat", {0, 1}, {5, 5}, Rgb(0, 158, 115)};
    EXPECT_GT(countColor(renderLinePlot({flat}, o), flat.color), 50u);
    PlotSeries bad{"bad", {0, 1}, {5}, Rgb(0)};
    EXPECT_THROW(renderLinePlot({bad}, o), Error);
    o.width = 100;
    EXPECT_THROW(renderLinePlot({}, o), Error);
}

TEST(Plot, TextAndGrid) {
    RgbImage img(200, 100);
    drawText(img, "PSNR 38.5 dB", 5, 5, 2, Rgb(0));
    EXPECT_GT(countColor(img, Rgb(0)), 50u);
    EXPECT_EQ(textWidth("ab", 2), 2 * textWidth("ab", 1));
    const RgbImage grid =
        composeGrid({RgbImage(40, 30, Rgb(255, 0, 0)), RgbImage(40, 30, Rgb(0, 0, 255)),
                     RgbImage(40, 30, Rgb(0, 255, 0))},
                    {"a", "b\nc", "d"}, 2);
    EXPECT_EQ(countColor(grid, Rgb(255, 0, 0)), 40u * 30u);
    EXPECT_EQ(countColor(grid, Rgb(0, 255, 0)), 40u * 30u);
    EXPECT_GT(grid.width, 80);
    EXPECT_GT(grid.height, 60);
}
