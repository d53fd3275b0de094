// Base colour textures as glTF can carry them: glTF 2.0 core allows PNG and JPEG images only
// (specification 3.8.4.1). JPEG bytes pass through unchanged and PNG pixels too (no
// recompression loss); any other format ImageDecode.h decodes (SGI, BMP, TGA, GIF, PSD, PNM,
// HDR...) is decoded and written as PNG (8-bit RGBA).
// PNG metadata: glTF says runtimes must ignore colour-space information in images (gamma, ICC
// profiles, chromaticities: the texels are sRGB), and the Khronos validator warns about PNGs
// carrying it ("Image contains unsupported features like non-default colorspace information,
// non-square pixels, or animation": iCCP, gAMA other than 1/2.2, cHRM other than sRGB, pHYs
// with unequal axes, APNG frames). So PNGs are copied with their critical chunks (IHDR, PLTE,
// IDAT, IEND) and tRNS only (PNG spec 5.4: ancillary chunks, the lower-case ones, never change
// the stored samples), byte for byte otherwise: the decoded pixels are the same.
//
// Contract: nullopt when the bytes are not an image stb_image can decode (the caller falls back
// to the material's mean colour). Deterministic: the same input gives the same bytes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "pipeline/scene/RgbaImage.h"

namespace hlod {

struct EncodedImage {
    std::vector<std::uint8_t> bytes;
    std::string mimeType; // "image/png" or "image/jpeg"
};

std::optional<EncodedImage> encodeForGltf(std::span<const std::uint8_t> bytes);

// Whether encodeForGltf passes these bytes through (PNG or JPEG by signature) rather than
// decoding and re-encoding them.
bool passesThroughForGltf(std::span<const std::uint8_t> bytes);

// A PNG without its ancillary chunks but tRNS (see above); nullopt when the chunk structure is
// broken (a length past the end, no IEND), which the caller then re-encodes.
std::optional<std::vector<std::uint8_t>> pngWithoutMetadata(std::span<const std::uint8_t> png);

// A decoded image as PNG (lossless, alpha kept) or JPEG (`quality` 1-100, alpha dropped).
// Empty bytes when the image is empty or stb_image_write fails. Deterministic.
EncodedImage encodePng(const RgbaImage& image);
EncodedImage encodeJpeg(const RgbaImage& image, int quality = 90);

// The bytes of `file`; nullopt when it is missing or unreadable.
std::optional<std::vector<std::uint8_t>> readImageFile(const std::filesystem::path& file);

// Reads `file` and encodes it as above; nullopt when missing, unreadable or undecodable.
std::optional<EncodedImage> loadTextureForGltf(const std::filesystem::path& file);

} // namespace hlod
