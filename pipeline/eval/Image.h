// 8-bit RGB images for the evaluation (`hlod bench`): rendered frames, plots and side-by-side
// comparisons, with a small text rasteriser (stb_easy_font's 7-pixel-high glyphs, scaled by an
// integer factor) and an atomic PNG writer.
//
// Layout: row-major, top row first, 3 bytes (R, G, B) per pixel.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace hlod {

using Rgb = glm::u8vec3;

struct RgbImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels; // width * height * 3

    RgbImage() = default;
    RgbImage(int w, int h, Rgb fill = Rgb(255));

    bool empty() const { return width <= 0 || height <= 0; }
    Rgb at(int x, int y) const;
    // Writes one pixel; coordinates outside the image are ignored.
    void set(int x, int y, Rgb c);
    // Fills [x0, x1) x [y0, y1), clipped to the image.
    void fillRect(int x0, int y0, int x1, int y1, Rgb c);
    // Copies `src` with its top-left corner at (x, y), clipped.
    void blit(const RgbImage& src, int x, int y);
};

// Text: stb_easy_font glyphs (about 6 px wide, 7 px high at scale 1, ASCII 32-126).
int textWidth(const std::string& text, int scale);
int textHeight(int scale); // height of one line
// Draws `text` with its top-left corner at (x, y); `vertical` turns it 90° counter-clockwise
// (reading bottom to top, for a y-axis label) with (x, y) then its bottom-left corner.
void drawText(RgbImage& image, const std::string& text, int x, int y, int scale, Rgb color,
              bool vertical = false);

// A line `thickness` pixels wide (square brush), endpoints included.
void drawLine(RgbImage& image, double x0, double y0, double x1, double y1, Rgb color,
              int thickness = 1);

// Tiles laid out in a grid of `columns`, each with its caption line above it (captions may
// hold several lines separated by '\n'). Tiles may differ in size; cells take the largest.
RgbImage composeGrid(const std::vector<RgbImage>& tiles, const std::vector<std::string>& captions,
                     int columns, Rgb background = Rgb(255), int captionScale = 2);

// PNG via stb_image_write, written to a temporary file beside `path` and renamed over it.
// Throws Error(Io) naming the file when it cannot be written.
void writePng(const std::filesystem::path& path, const RgbImage& image);

} // namespace hlod
