// Texture decoding for every importer: SGI images with our own reader (SgiImage.h) and
// everything stb_image reads (PNG, JPEG, BMP, TGA, GIF, PSD, PNM, HDR), recognised by content,
// not by file name. Output: 8-bit RGBA (RgbaImage.h), top row first.
//
// Safety: an image's size is read from its header before decoding allocates: images above
// the per-image limit are refused, and with a TexelBudget so is every image past the file's
// total (ImportLimits.h: maxImageTexels, maxTexels); the reason names the limit.
// Failure: decodeImage returns nullopt with a one-line reason; loadTexture never throws, it
// returns a Texture whose `error` names the file ("<file>: <why>") and whose image is null, so
// a missing or corrupt texture falls back to the material's colour instead of failing the
// import (the documented fallback, see Scene.h Texture).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include "pipeline/io/ImportLimits.h"
#include "pipeline/scene/RgbaImage.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

// The texels the images of one scene file may decode (ImportLimits.h); `used` grows with each
// decoded image. Not thread-safe: one per file being imported.
struct TexelBudget {
    std::uint64_t imageLimit = ImportLimits{}.maxImageTexels;
    std::uint64_t fileLimit = ImportLimits{}.maxTexels;
    std::uint64_t used = 0;

    TexelBudget() = default;
    explicit TexelBudget(const ImportLimits& limits)
        : imageLimit(limits.maxImageTexels), fileLimit(limits.maxTexels) {}
    // Charges `texels`; false with `why` when the image or the file's total is over its limit.
    bool charge(std::uint64_t width, std::uint64_t height, std::string& why);
};

// Without a budget, only the default per-image limit applies.
std::optional<RgbaImage> decodeImage(std::span<const std::uint8_t> bytes, std::string& why,
                                     TexelBudget* budget = nullptr);

// Reads and decodes `file` into a Texture (name = the file name, file = `file`).
Texture loadTexture(const std::filesystem::path& file, TexelBudget* budget = nullptr);

// Decodes image bytes embedded in a scene file; `name` identifies it in messages.
Texture textureFromBytes(std::span<const std::uint8_t> bytes, const std::string& name,
                         TexelBudget* budget = nullptr);

} // namespace hlod
