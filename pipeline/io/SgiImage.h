// Reader for SGI image files (.rgb, .rgba, .bw, .sgi), after "The SGI Image File Format,
// Version 1.00" (Paul Haeberli, Silicon Graphics, 1988). TORCS and other games of its era ship
// their textures in it; stb_image does not read it.
//
// Supported: magic 474, storage verbatim (0) or RLE (1), 1 byte per channel, dimension 1-3,
// 1-4 channels (grey, grey + alpha, RGB, RGBA; channels beyond the fourth are ignored),
// colormap 0 (normal). Output: 8-bit RGBA, top row first (the file stores the bottom row
// first), grey replicated to RGB, alpha 255 when the file has none.
// Not supported (refused with a reason): 2 bytes per channel, dithered/screen/colormap files.
//
// Safety: every offset and length is checked against the buffer (RLE start and length tables
// included), runs may not overflow their row and a row must fill it exactly; sizes above 16384
// texels per side are refused before allocating.
// Failure: nullopt with `why` set to one line ("RLE row 7 of channel 2 runs past its end").
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "pipeline/scene/RgbaImage.h"

namespace hlod {

// True when the bytes start with the SGI magic number (474, big-endian).
bool isSgiImage(std::span<const std::uint8_t> bytes);

std::optional<RgbaImage> decodeSgi(std::span<const std::uint8_t> bytes, std::string& why);

} // namespace hlod
