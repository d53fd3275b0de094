// See ImageDecode.h: SGI by magic number, the rest through stb_image.
#include "pipeline/io/ImageDecode.h"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <vector>

#include <stb_image.h>

#include "pipeline/io/SgiImage.h"

namespace hlod {

namespace {

// Width and height from the header, without decoding: SGI by its header fields (dimension 1 is
// one row), everything else by stb_image's info. False when no reader recognises the bytes.
bool imageSize(std::span<const std::uint8_t> bytes, std::uint64_t& w, std::uint64_t& h) {
    if (isSgiImage(bytes)) {
        if (bytes.size() < 512) return false; // decodeSgi reports the truncated header
        const auto be16 = [&](std::size_t at) {
            return (unsigned(bytes[at]) << 8) | bytes[at + 1];
        };
        w = be16(6);
        h = be16(4) == 1 ? 1 : be16(8);
        return true;
    }
    // PNG: the IHDR chunk's size, read here because stb_image's info refuses sizes over its own
    // 1 GB limit without saying which size it saw (PNG specification 11.2.2: IHDR comes first).
    static const std::uint8_t png[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
    if (bytes.size() >= 24 && std::equal(png, png + 8, bytes.begin()) &&
        std::equal(bytes.begin() + 12, bytes.begin() + 16, "IHDR")) {
        const auto be32 = [&](std::size_t at) {
            return (std::uint64_t(bytes[at]) << 24) | (std::uint64_t(bytes[at + 1]) << 16) |
                   (std::uint64_t(bytes[at + 2]) << 8) | bytes[at + 3];
        };
        w = be32(16);
        h = be32(20);
        return true;
    }
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) return false;
    int iw = 0, ih = 0, comp = 0;
    if (!stbi_info_from_memory(bytes.data(), static_cast<int>(bytes.size()), &iw, &ih, &comp))
        return false;
    w = static_cast<std::uint64_t>(std::max(iw, 0));
    h = static_cast<std::uint64_t>(std::max(ih, 0));
    return true;
}

std::optional<RgbaImage> decodeWithStb(std::span<const std::uint8_t> bytes, std::string& why) {
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) {
        why = "image too large";
        return std::nullopt;
    }
    const int size = static_cast<int>(bytes.size());
    int w = 0, h = 0, comp = 0;
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

bool TexelBudget::charge(std::uint64_t width, std::uint64_t height, std::string& why) {
    const std::uint64_t texels =
        width != 0 && height > UINT64_MAX / width ? UINT64_MAX : width * height;
    const std::string size = std::to_string(width) + " x " + std::to_string(height);
    if (texels > imageLimit) {
        why = "image too large (" + size + " texels, over the import limit of " +
              std::to_string(imageLimit) + " texels per image); not decoded";
        return false;
    }
    if (texels > fileLimit - std::min(used, fileLimit)) {
        why = "image of " + size +
              " texels not decoded: the scene's textures would pass the "
              "import limit of " +
              std::to_string(fileLimit) + " texels (--max-texels raises it)";
        return false;
    }
    used += texels;
    return true;
}

std::optional<RgbaImage> decodeImage(std::span<const std::uint8_t> bytes, std::string& why,
                                     TexelBudget* budget) {
    why.clear();
    if (bytes.empty()) {
        why = "empty image";
        return std::nullopt;
    }
    std::uint64_t w = 0, h = 0;
    const bool sized = imageSize(bytes, w, h);
    if (!sized && !isSgiImage(bytes)) {
        why = "not an image format HLOD Studio reads";
        return std::nullopt;
    }
    // An SGI header too short or with an empty size: its reader says what is wrong.
    if (sized && w > 0 && h > 0) {
        TexelBudget unlimitedFile;
        unlimitedFile.fileLimit = UINT64_MAX;
        if (!(budget != nullptr ? *budget : unlimitedFile).charge(w, h, why)) return std::nullopt;
    }
    if (isSgiImage(bytes)) return decodeSgi(bytes, why);
    if (w == 0 || h == 0) {
        why = "image has an empty size";
        return std::nullopt;
    }
    return decodeWithStb(bytes, why);
}

Texture loadTexture(const std::filesystem::path& file, TexelBudget* budget) {
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
    if (auto image = decodeImage(bytes, why, budget))
        t.image = std::make_shared<const RgbaImage>(std::move(*image));
    else
        t.error = file.string() + ": " + why;
    return t;
}

Texture textureFromBytes(std::span<const std::uint8_t> bytes, const std::string& name,
                         TexelBudget* budget) {
    Texture t;
    t.name = name;
    std::string why;
    if (auto image = decodeImage(bytes, why, budget))
        t.image = std::make_shared<const RgbaImage>(std::move(*image));
    else
        t.error = name + ": " + why;
    return t;
}

} // namespace hlod
