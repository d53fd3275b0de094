// See ImageDecode.h: SGI by magic number, the rest through stb_image.
#include "pipeline/io/ImageDecode.h"

#include <climits>
#include <fstream>
#include <iterator>
#include <vector>

#include <stb_image.h>

#include "pipeline/io/SgiImage.h"

namespace hlod {

namespace {

constexpr long long kMaxTexels = 64ll * 1024 * 1024;

std::optional<RgbaImage> decodeWithStb(std::span<const std::uint8_t> bytes, std::string& why) {
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) {
        why = "image too large";
        return std::nullopt;
    }
    const int size = static_cast<int>(bytes.size());
    int w = 0, h = 0, comp = 0;
    if (!stbi_info_from_memory(bytes.data(), size, &w, &h, &comp)) {
        why = "not an image format HLOD Studio reads";
        return std::nullopt;
    }
    if (w <= 0 || h <= 0 || static_cast<long long>(w) * h > kMaxTexels) {
        why = "image too large (" + std::to_string(w) + " x " + std::to_string(h) + ")";
        return std::nullopt;
    }
    unsigned char* px = stbi_load_from_memory(bytes.data(), size, &w, &h, &comp, 4);
    if (!px) {
        const char* reason = stbi_failure_reason();
        why = std::string("corrupt image data (") + (reason ? reason : "undecodable") + ")";
        return std::nullopt;
    }
    RgbaImage image;
    image.width = w;
    image.height = h;
    image.pixels.assign(px, px + static_cast<std::size_t>(w) * h * 4);
    stbi_image_free(px);
    return image;
}

} // namespace

std::optional<RgbaImage> decodeImage(std::span<const std::uint8_t> bytes, std::string& why) {
    why.clear();
    if (bytes.empty()) {
        why = "empty image";
        return std::nullopt;
    }
    if (isSgiImage(bytes)) return decodeSgi(bytes, why);
    return decodeWithStb(bytes, why);
}

Texture loadTexture(const std::filesystem::path& file) {
    Texture t;
    t.name = file.filename().string();
    t.file = file;
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        t.error = file.string() + ": texture file missing or unreadable";
        return t;
    }
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                          std::istreambuf_iterator<char>());
    std::string why;
    if (auto image = decodeImage(bytes, why))
        t.image = std::make_shared<const RgbaImage>(std::move(*image));
    else
        t.error = file.string() + ": " + why;
    return t;
}

Texture textureFromBytes(std::span<const std::uint8_t> bytes, const std::string& name) {
    Texture t;
    t.name = name;
    std::string why;
    if (auto image = decodeImage(bytes, why))
        t.image = std::make_shared<const RgbaImage>(std::move(*image));
    else
        t.error = name + ": " + why;
    return t;
}

} // namespace hlod
