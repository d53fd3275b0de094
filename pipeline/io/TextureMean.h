// Mean colour of an image (PNG, JPEG, BMP, TGA, SGI... whatever ImageDecode.h decodes).
// Proxies replace textured materials by vertex colours: the mean is what survives.
#pragma once

#include <filesystem>
#include <optional>

#include <glm/glm.hpp>

namespace hlod {

// RGBA in [0,1], linear average of the sRGB-decoded texels. nullopt when undecodable.
std::optional<glm::vec4> meanColorOfImage(const unsigned char* bytes, std::size_t size);
std::optional<glm::vec4> meanColorOfImageFile(const std::filesystem::path& file);

} // namespace hlod
