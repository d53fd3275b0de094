// See TextureImage.h. PNG/JPEG are recognised by their signatures (PNG: 89 50 4E 47 0D 0A 1A 0A,
// ISO/IEC 15948; JPEG: FF D8 FF, ITU T.81 SOI marker followed by a marker). PNG chunks (ISO/IEC
// 15948 5.3): 4-byte big-endian data length, 4-byte type, data, 4-byte CRC of type and data;
// bit 5 of the type's first byte (lower case) marks an ancillary chunk.
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

std::uint32_t bigEndian32(const std::uint8_t* p) {
    return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) |
           std::uint32_t(p[3]);
}

} // namespace

std::optional<std::vector<std::uint8_t>> pngWithoutMetadata(std::span<const std::uint8_t> png) {
    if (!isPng(png)) return std::nullopt;
    std::vector<std::uint8_t> out(png.begin(), png.begin() + 8);
    std::size_t p = 8;
    while (p + 12 <= png.size()) {
        const std::size_t length = bigEndian32(&png[p]);
        if (length > png.size() - p - 12) return std::nullopt;
        const std::uint8_t* type = &png[p + 4];
        const bool ancillary = (type[0] & 0x20) != 0;
        const bool keep = !ancillary || std::memcmp(type, "tRNS", 4) == 0;
        if (keep) out.insert(out.end(), png.begin() + p, png.begin() + p + 12 + length);
        p += 12 + length;
        if (std::memcmp(type, "IEND", 4) == 0) return out;
    }
    return std::nullopt;
}

bool passesThroughForGltf(std::span<const std::uint8_t> bytes) {
    return isPng(bytes) || isJpeg(bytes);
}

std::optional<EncodedImage> encodeForGltf(std::span<const std::uint8_t> bytes) {
    if (bytes.empty() || bytes.size() > static_cast<std::size_t>(INT32_MAX)) return std::nullopt;
    const int size = static_cast<int>(bytes.size());
    if (isPng(bytes) || isJpeg(bytes)) {
        int w = 0, h = 0, comp = 0;
        // Pass-through formats must still be decodable: a corrupt PNG would fail the validator.
        if (!stbi_info_from_memory(bytes.data(), size, &w, &h, &comp) || w <= 0 || h <= 0) {
            return std::nullopt;
        }
        if (isJpeg(bytes)) return EncodedImage{{bytes.begin(), bytes.end()}, "image/jpeg"};
        if (auto clean = pngWithoutMetadata(bytes)) return EncodedImage{*clean, "image/png"};
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

std::optional<std::vector<std::uint8_t>> readImageFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    return std::vector<std::uint8_t>((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
}

std::optional<EncodedImage> loadTextureForGltf(const std::filesystem::path& file) {
    const std::optional<std::vector<std::uint8_t>> bytes = readImageFile(file);
    return bytes ? encodeForGltf(*bytes) : std::nullopt;
}

} // namespace hlod
