// Hand-built SGI image files for the tests (format: Haeberli 1988, see pipeline/io/SgiImage.h).
#pragma once

#include <cstdint>
#include <vector>

namespace hlod::test {

// A 512-byte header: magic 474, storage (0 verbatim, 1 RLE), 1 byte per channel, dimension 3
// (2 for one channel), sizes, pixmin 0, pixmax 255.
inline std::vector<std::uint8_t> sgiHeader(int storage, int x, int y, int z, int bpc = 1) {
    std::vector<std::uint8_t> h(512, 0);
    auto put16 = [&](std::size_t at, int v) {
        h[at] = static_cast<std::uint8_t>(v >> 8);
        h[at + 1] = static_cast<std::uint8_t>(v);
    };
    put16(0, 474);
    h[2] = static_cast<std::uint8_t>(storage);
    h[3] = static_cast<std::uint8_t>(bpc);
    put16(4, z == 1 ? 2 : 3);
    put16(6, x);
    put16(8, y);
    put16(10, z);
    h[19] = 255; // pixmax
    return h;
}

inline void putBe32(std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v) {
    b[at] = static_cast<std::uint8_t>(v >> 24);
    b[at + 1] = static_cast<std::uint8_t>(v >> 16);
    b[at + 2] = static_cast<std::uint8_t>(v >> 8);
    b[at + 3] = static_cast<std::uint8_t>(v);
}

// An RLE file whose rows are given as packet bytes, rows[z][y] (y = 0 the bottom row).
inline std::vector<std::uint8_t>
sgiRle(int x, int y, const std::vector<std::vector<std::vector<std::uint8_t>>>& rows) {
    const int z = static_cast<int>(rows.size());
    std::vector<std::uint8_t> b = sgiHeader(1, x, y, z);
    const std::size_t entries = static_cast<std::size_t>(y) * z;
    b.resize(512 + entries * 8, 0);
    for (int c = 0; c < z; ++c) {
        for (int r = 0; r < y; ++r) {
            const std::size_t e = static_cast<std::size_t>(r) + static_cast<std::size_t>(c) * y;
            const auto& row = rows[static_cast<std::size_t>(c)][static_cast<std::size_t>(r)];
            putBe32(b, 512 + e * 4, static_cast<std::uint32_t>(b.size()));
            putBe32(b, 512 + (entries + e) * 4, static_cast<std::uint32_t>(row.size()));
            b.insert(b.end(), row.begin(), row.end());
        }
    }
    return b;
}

} // namespace hlod::test
