#include "pipeline/eval/Image.h"

#include "pipeline/core/AtomicFile.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <system_error>

#include <stb_easy_font.h>
#include <stb_image_write.h>

#include "pipeline/core/Error.h"

namespace hlod {

RgbImage::RgbImage(int w, int h, Rgb fill) : width(std::max(w, 0)), height(std::max(h, 0)) {
    pixels.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
    for (std::size_t i = 0; i < pixels.size(); i += 3) {
        pixels[i] = fill.r;
        pixels[i + 1] = fill.g;
        pixels[i + 2] = fill.b;
    }
}

Rgb RgbImage::at(int x, int y) const {
    const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
    return Rgb(pixels[i], pixels[i + 1], pixels[i + 2]);
}

void RgbImage::set(int x, int y, Rgb c) {
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
    pixels[i] = c.r;
    pixels[i + 1] = c.g;
    pixels[i + 2] = c.b;
}

void RgbImage::fillRect(int x0, int y0, int x1, int y1, Rgb c) {
    x0 = std::max(x0, 0);
    y0 = std::max(y0, 0);
    x1 = std::min(x1, width);
    y1 = std::min(y1, height);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            set(x, y, c);
}

void RgbImage::blit(const RgbImage& src, int x, int y) {
    for (int sy = 0; sy < src.height; ++sy) {
        const int dy = y + sy;
        if (dy < 0 || dy >= height) continue;
        for (int sx = 0; sx < src.width; ++sx)
            set(x + sx, dy, src.at(sx, sy));
    }
}

namespace {

// stb_easy_font indexes its glyph table with (c - 32): keep to printable ASCII.
std::string printable(const std::string& text) {
    std::string s = text;
    for (char& c : s) {
        if (c != '\n' &&
            (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126))
            c = '?';
    }
    return s;
}

} // namespace

int textWidth(const std::string& text, int scale) {
    std::string s = printable(text);
    return stb_easy_font_width(s.data()) * scale;
}

int textHeight(int scale) { return 7 * scale; }

void drawText(RgbImage& image, const std::string& text, int x, int y, int scale, Rgb color,
              bool vertical) {
    std::string s = printable(text);
    if (s.empty()) return;
    std::vector<char> buffer(s.size() * 1024 + 1024); // up to 16 segments of 64 bytes per glyph
    const int quads = stb_easy_font_print(0.0f, 0.0f, s.data(), nullptr, buffer.data(),
                                          static_cast<int>(buffer.size()));
    for (int q = 0; q < quads; ++q) {
        const char* v = buffer.data() + static_cast<std::size_t>(q) * 64;
        float qx0, qy0, qx1, qy1;
        std::memcpy(&qx0, v, 4);
        std::memcpy(&qy0, v + 4, 4);
        std::memcpy(&qx1, v + 32 + 0, 4); // vertex 2: opposite corner
        std::memcpy(&qy1, v + 32 + 4, 4);
        const int gx0 = static_cast<int>(std::lround(std::min(qx0, qx1))) * scale;
        const int gy0 = static_cast<int>(std::lround(std::min(qy0, qy1))) * scale;
        const int gx1 = static_cast<int>(std::lround(std::max(qx0, qx1))) * scale;
        const int gy1 = static_cast<int>(std::lround(std::max(qy0, qy1))) * scale;
        if (!vertical) {
            image.fillRect(x + gx0, y + gy0, x + gx1, y + gy1, color);
        } else {
            // Rotate 90° counter-clockwise around (x, y): (gx, gy) -> (gy, -gx).
            image.fillRect(x + gy0, y - gx1, x + gy1, y - gx0, color);
        }
    }
}

void drawLine(RgbImage& image, double x0, double y0, double x1, double y1, Rgb color,
              int thickness) {
    const double len = std::max(std::abs(x1 - x0), std::abs(y1 - y0));
    const int steps = std::max(1, static_cast<int>(std::ceil(len)));
    const int lo = -(thickness - 1) / 2, hi = thickness / 2;
    for (int i = 0; i <= steps; ++i) {
        const double t = static_cast<double>(i) / steps;
        const int px = static_cast<int>(std::lround(x0 + (x1 - x0) * t));
        const int py = static_cast<int>(std::lround(y0 + (y1 - y0) * t));
        for (int dy = lo; dy <= hi; ++dy)
            for (int dx = lo; dx <= hi; ++dx)
                image.set(px + dx, py + dy, color);
    }
}

RgbImage composeGrid(const std::vector<RgbImage>& tiles, const std::vector<std::string>& captions,
                     int columns, Rgb background, int captionScale) {
    if (tiles.empty()) return RgbImage(1, 1, background);
    columns = std::clamp(columns, 1, static_cast<int>(tiles.size()));
    const int rows = (static_cast<int>(tiles.size()) + columns - 1) / columns;
    int cellW = 0, cellH = 0, captionLines = 1;
    for (const RgbImage& t : tiles) {
        cellW = std::max(cellW, t.width);
        cellH = std::max(cellH, t.height);
    }
    for (const std::string& c : captions)
        captionLines =
            std::max(captionLines, 1 + static_cast<int>(std::count(c.begin(), c.end(), '\n')));
    const int pad = 8;
    const int lineH = 12 * captionScale; // stb_easy_font's line advance
    const int captionH = captionLines * lineH + pad / 2;
    RgbImage out(columns * (cellW + pad) + pad, rows * (cellH + captionH + pad) + pad, background);
    for (std::size_t i = 0; i < tiles.size(); ++i) {
        const int col = static_cast<int>(i) % columns, row = static_cast<int>(i) / columns;
        const int x = pad + col * (cellW + pad);
        const int y = pad + row * (cellH + captionH + pad);
        if (i < captions.size()) {
            int ly = y;
            std::size_t start = 0;
            while (start <= captions[i].size()) {
                const std::size_t end = captions[i].find('\n', start);
                const std::string line = captions[i].substr(
                    start, end == std::string::npos ? std::string::npos : end - start);
                drawText(out, line, x, ly, captionScale, Rgb(20));
                ly += lineH;
                if (end == std::string::npos) break;
                start = end + 1;
            }
        }
        out.blit(tiles[i], x, y + captionH);
    }
    return out;
}

namespace {

void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    const auto* p = static_cast<const unsigned char*>(data);
    out->insert(out->end(), p, p + size);
}

} // namespace

void writePng(const std::filesystem::path& path, const RgbImage& image) {
    if (image.empty()) throw Error(ErrorCode::InvalidArgument, path, "empty image");
    std::vector<unsigned char> bytes;
    if (!stbi_write_png_to_func(appendBytes, &bytes, image.width, image.height, 3,
                                image.pixels.data(), image.width * 3))
        throw Error(ErrorCode::Io, path, "PNG encoding failed");
    writeFileAtomic(path,
                    std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

} // namespace hlod
