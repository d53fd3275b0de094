// Texture decoding for every importer: SGI images with our own reader (SgiImage.h) and
// everything stb_image reads (PNG, JPEG, BMP, TGA, GIF, PSD, PNM, HDR), recognised by content,
// not by file name. Output: 8-bit RGBA (RgbaImage.h), top row first.
//
// Safety: images above 64 M texels are refused before decoding allocates.
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

#include "pipeline/scene/RgbaImage.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

std::optional<RgbaImage> decodeImage(std::span<const std::uint8_t> bytes, std::string& why);

// Reads and decodes `file` into a Texture (name = the file name, file = `file`).
Texture loadTexture(const std::filesystem::path& file);

// Decodes image bytes embedded in a scene file; `name` identifies it in messages.
Texture textureFromBytes(std::span<const std::uint8_t> bytes, const std::string& name);

} // namespace hlod
