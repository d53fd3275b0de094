// See TextureImage.h. PNG/JPEG are recognised by their signatures (PNG: 89 50 4E 47 0D 0A 1A 0A,
// ISO/IEC 15948; JPEG: FF D8 FF, ITU T.81 SOI marker followed by a marker).
#include "pipeline/io/TextureImage.h"

#include <cstring>
#include <fstream>
#include <iterator>

#include <stb_image.h>
#include <stb_image_write.h>

#include "pipeline/io/ImageDecode.h"

namespace hlod {

namespace {

bool isPng(std::span<const std::uint8_t> b) {
    static const std::uint8_t sig[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
    return b.size() >= 8 && std::memcmp(b.data(), sig, 8) == 0;
}

bool isJpeg(std::span<const std::uint8_t> b) {
    return b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF;
}

void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* p = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), p, p + size);
}

} // namespace

std::optional<EncodedImage> encodeForGltf(std::span<const std::uint8_t> bytes) {
    if (bytes.empty() || bytes.size() > static_cast<std::size_t>(INT32_MAX)) return std::nullopt;
    const int size = static_cast<int>(bytes.size());
    if (isPng(bytes) || isJpeg(bytes)) {
        int w = 0, h = 0, comp = 0;
        // Pass-through formats must still be decodable: a corrupt PNG would fail the validator.
        if (!stbi_info_from_memory(bytes.data(), size, &w, &h, &comp) || w <= 0 || h <= 0) {
            return std::nullopt;
        }
        return EncodedImage{{bytes.begin(), bytes.end()}, isPng(bytes) ? "image/png" : "image/jpeg"};
    }
    std::string why;
    const std::optional<RgbaImage> image = decodeImage(bytes, why); // SGI, BMP, TGA, ...
    if (!image) return std::nullopt;
    EncodedImage out = encodePng(*image);
    if (out.bytes.empty()) return std::nullopt;
    return out;
}

EncodedImage encodePng(const RgbaImage& image) {
    EncodedImage out;
    out.mimeType = "image/png";
    if (image.empty()) return out;
    if (!stbi_write_png_to_func(&appendBytes, &out.bytes, image.width, image.height, 4,
                                image.pixels.data(), image.width * 4))
        out.bytes.clear();
    return out;
}

EncodedImage encodeJpeg(const RgbaImage& image, int quality) {
    EncodedImage out;
    out.mimeType = "image/jpeg";
    if (image.empty()) return out;
    // stb writes the first three channels of a 4-channel image (alpha is dropped).
    if (!stbi_write_jpg_to_func(&appendBytes, &out.bytes, image.width, image.height, 4,
                                image.pixels.data(), quality))
        out.bytes.clear();
    return out;
}

std::optional<EncodedImage> loadTextureForGltf(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                          std::istreambuf_iterator<char>());
    return encodeForGltf(bytes);
}

} // namespace hlod
