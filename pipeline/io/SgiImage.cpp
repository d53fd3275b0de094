// SGI image decoding after Haeberli's format description (1988), see SgiImage.h.
// Header (512 bytes, big-endian): MAGIC short 474, STORAGE byte, BPC byte, DIMENSION ushort,
// XSIZE/YSIZE/ZSIZE ushort, PIXMIN/PIXMAX long, 4 dummy bytes, IMAGENAME 80 bytes, COLORMAP
// long, 404 dummy bytes. Verbatim data: channel planes one after another, each ysize rows of
// xsize bytes, bottom row first. RLE data: a table of ysize*zsize row start offsets, then one of
// row lengths (both longs, row y of channel z at y + z*ysize), then the packets: a count byte
// whose low 7 bits are n; n = 0 ends the row; high bit set = n literal bytes follow, clear =
// the next byte repeats n times.
#include "pipeline/io/SgiImage.h"

#include <algorithm>
#include <vector>

namespace hlod {

namespace {

constexpr std::size_t kHeaderBytes = 512;
constexpr int kMaxSide = 16384;

std::uint32_t be16(std::span<const std::uint8_t> b, std::size_t at) {
    return (std::uint32_t(b[at]) << 8) | b[at + 1];
}

std::uint32_t be32(std::span<const std::uint8_t> b, std::size_t at) {
    return (std::uint32_t(b[at]) << 24) | (std::uint32_t(b[at + 1]) << 16) |
           (std::uint32_t(b[at + 2]) << 8) | b[at + 3];
}

struct Header {
    int storage = 0, bpc = 0, dimension = 0;
    int xsize = 0, ysize = 0, zsize = 0;
    std::uint32_t colormap = 0;
};

bool readHeader(std::span<const std::uint8_t> b, Header& h, std::string& why) {
    if (b.size() < kHeaderBytes) {
        why = "SGI header truncated (" + std::to_string(b.size()) + " of 512 bytes)";
        return false;
    }
    h.storage = b[2];
    h.bpc = b[3];
    h.dimension = static_cast<int>(be16(b, 4));
    h.xsize = static_cast<int>(be16(b, 6));
    h.ysize = static_cast<int>(be16(b, 8));
    h.zsize = static_cast<int>(be16(b, 10));
    h.colormap = be32(b, 104);
    // Dimension 1 is one row, dimension 2 one channel: the sizes the header leaves unused.
    if (h.dimension == 1) h.ysize = 1;
    if (h.dimension <= 2) h.zsize = 1;
    if (h.storage > 1) why = "unknown SGI storage " + std::to_string(h.storage);
    else if (h.bpc == 2) why = "16-bit SGI images are not supported";
    else if (h.bpc != 1) why = "bad SGI bytes per channel " + std::to_string(h.bpc);
    else if (h.dimension < 1 || h.dimension > 3) why = "bad SGI dimension " + std::to_string(h.dimension);
    else if (h.colormap != 0) why = "SGI colormap images are not supported";
    else if (h.xsize < 1 || h.ysize < 1 || h.zsize < 1) why = "SGI image has an empty size";
    else if (h.xsize > kMaxSide || h.ysize > kMaxSide)
        why = "SGI image too large (" + std::to_string(h.xsize) + " x " + std::to_string(h.ysize) + ")";
    return why.empty();
}

// Decodes one RLE row into `row` (xsize bytes); false with `why` on any inconsistency.
bool decodeRleRow(std::span<const std::uint8_t> b, std::size_t start, std::size_t length,
                  std::uint8_t* row, int xsize, std::string& why) {
    if (start < kHeaderBytes || start > b.size() || length > b.size() - start) {
        why = "RLE row outside the file (offset " + std::to_string(start) + ", " +
              std::to_string(length) + " bytes)";
        return false;
    }
    std::size_t in = start;
    const std::size_t end = start + length;
    int out = 0;
    while (in < end) {
        const std::uint8_t packet = b[in++];
        const int n = packet & 0x7f;
        if (n == 0) break;
        if (out + n > xsize) {
            why = "RLE row runs past its end";
            return false;
        }
        if (packet & 0x80) {
            if (end - in < static_cast<std::size_t>(n)) {
                why = "RLE literal run truncated";
                return false;
            }
            std::copy_n(b.begin() + static_cast<std::ptrdiff_t>(in), n, row + out);
            in += static_cast<std::size_t>(n);
        } else {
            if (in >= end) {
                why = "RLE repeat run truncated";
                return false;
            }
            std::fill_n(row + out, n, b[in++]);
        }
        out += n;
    }
    if (out != xsize) {
        why = "RLE row has " + std::to_string(out) + " of " + std::to_string(xsize) + " texels";
        return false;
    }
    return true;
}

// Fills planes[z][y * xsize + x] (file row order: y = 0 is the bottom row).
bool readPlanes(std::span<const std::uint8_t> b, const Header& h, int channels,
                std::vector<std::vector<std::uint8_t>>& planes, std::string& why) {
    const auto rowBytes = static_cast<std::size_t>(h.xsize);
    const auto rows = static_cast<std::size_t>(h.ysize);
    planes.assign(static_cast<std::size_t>(channels), std::vector<std::uint8_t>(rowBytes * rows));
    if (h.storage == 0) {
        const std::size_t need = rowBytes * rows * static_cast<std::size_t>(channels);
        if (b.size() - kHeaderBytes < need) {
            why = "verbatim SGI data truncated (" + std::to_string(b.size() - kHeaderBytes) +
                  " of " + std::to_string(need) + " bytes)";
            return false;
        }
        for (int z = 0; z < channels; ++z)
            std::copy_n(b.begin() + static_cast<std::ptrdiff_t>(kHeaderBytes + z * rows * rowBytes),
                        rows * rowBytes, planes[static_cast<std::size_t>(z)].begin());
        return true;
    }
    const std::size_t tableEntries = rows * static_cast<std::size_t>(h.zsize);
    if ((b.size() - kHeaderBytes) / 8 < tableEntries) {
        why = "RLE offset tables truncated";
        return false;
    }
    for (int z = 0; z < channels; ++z) {
        for (std::size_t y = 0; y < rows; ++y) {
            const std::size_t entry = y + static_cast<std::size_t>(z) * rows;
            const std::size_t start = be32(b, kHeaderBytes + entry * 4);
            const std::size_t length = be32(b, kHeaderBytes + (tableEntries + entry) * 4);
            std::uint8_t* row = planes[static_cast<std::size_t>(z)].data() + y * rowBytes;
            if (!decodeRleRow(b, start, length, row, h.xsize, why)) {
                why = why + " (row " + std::to_string(y) + " of channel " + std::to_string(z) + ")";
                return false;
            }
        }
    }
    return true;
}

} // namespace

bool isSgiImage(std::span<const std::uint8_t> bytes) {
    return bytes.size() >= 2 && be16(bytes, 0) == 474;
}

std::optional<RgbaImage> decodeSgi(std::span<const std::uint8_t> bytes, std::string& why) {
    why.clear();
    if (!isSgiImage(bytes)) {
        why = "not an SGI image (magic number is not 474)";
        return std::nullopt;
    }
    Header h;
    if (!readHeader(bytes, h, why)) return std::nullopt;
    const int channels = std::min(h.zsize, 4);
    std::vector<std::vector<std::uint8_t>> planes;
    if (!readPlanes(bytes, h, channels, planes, why)) return std::nullopt;
    RgbaImage image(h.xsize, h.ysize, glm::u8vec4(0, 0, 0, 255));
    for (int y = 0; y < h.ysize; ++y) {
        const std::size_t src = static_cast<std::size_t>(h.ysize - 1 - y) * h.xsize;
        for (int x = 0; x < h.xsize; ++x) {
            const std::size_t i = src + static_cast<std::size_t>(x);
            glm::u8vec4 c(0, 0, 0, 255);
            if (channels <= 2) {
                c.r = c.g = c.b = planes[0][i];
                if (channels == 2) c.a = planes[1][i];
            } else {
                c.r = planes[0][i];
                c.g = planes[1][i];
                c.b = planes[2][i];
                if (channels == 4) c.a = planes[3][i];
            }
            image.set(x, y, c);
        }
    }
    return image;
}

} // namespace hlod
