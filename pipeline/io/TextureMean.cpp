// Mean texture colour with stb_image. Averaging happens in linear space (sRGB decoded),
// as a renderer blending the texels at a far distance would do, then converted back.
#include "pipeline/io/TextureMean.h"

#include <cmath>
#include <fstream>
#include <vector>

#include <stb_image.h>

namespace hlod {

namespace {

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

} // namespace

std::optional<glm::vec4> meanColorOfImage(const unsigned char* bytes, std::size_t size) {
    if (bytes == nullptr || size == 0 || size > 0x7fffffff) return std::nullopt;
    int w = 0, h = 0, comp = 0;
    if (!stbi_info_from_memory(bytes, static_cast<int>(size), &w, &h, &comp)) return std::nullopt;
    // Refuse absurd dimensions before stb allocates (a 16k x 16k RGBA image is 1 GiB).
    if (w <= 0 || h <= 0 || static_cast<long long>(w) * h > 64ll * 1024 * 1024) return std::nullopt;
    unsigned char* px = stbi_load_from_memory(bytes, static_cast<int>(size), &w, &h, &comp, 4);
    if (px == nullptr) return std::nullopt;
    // Sum in double; sample every texel up to 4M, strided beyond (the mean barely moves).
    const std::size_t count = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
    const std::size_t stride = count > (1u << 22) ? count / (1u << 22) : 1;
    double sum[4] = {0, 0, 0, 0};
    std::size_t n = 0;
    for (std::size_t i = 0; i < count; i += stride, ++n) {
        for (int c = 0; c < 3; ++c)
            sum[c] += srgbToLinear(px[i * 4 + c] / 255.0f);
        sum[3] += px[i * 4 + 3] / 255.0;
    }
    stbi_image_free(px);
    return glm::vec4(static_cast<float>(sum[0] / n), static_cast<float>(sum[1] / n),
                     static_cast<float>(sum[2] / n), static_cast<float>(sum[3] / n));
}

std::optional<glm::vec4> meanColorOfImageFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    std::vector<unsigned char> data((std::istreambuf_iterator<char>(in)),
                                    std::istreambuf_iterator<char>());
    return meanColorOfImage(data.data(), data.size());
}

} // namespace hlod
