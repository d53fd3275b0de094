// Base colour textures as glTF can carry them: glTF 2.0 core allows PNG and JPEG images only
// (specification 3.8.4.1). PNG and JPEG bytes pass through unchanged (no recompression loss);
// any other format ImageDecode.h decodes (SGI, BMP, TGA, GIF, PSD, PNM, HDR...) is decoded and
// written as PNG (8-bit RGBA).
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

// A decoded image as PNG (lossless, alpha kept) or JPEG (`quality` 1-100, alpha dropped).
// Empty bytes when the image is empty or stb_image_write fails. Deterministic.
EncodedImage encodePng(const RgbaImage& image);
EncodedImage encodeJpeg(const RgbaImage& image, int quality = 90);

// Reads `file` and encodes it as above; nullopt when missing, unreadable or undecodable.
std::optional<EncodedImage> loadTextureForGltf(const std::filesystem::path& file);

} // namespace hlod
