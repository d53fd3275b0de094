// Mean texture colour of any image ImageDecode reads (SGI included). Averaging happens in
// linear space (sRGB decoded), as a renderer blending the texels at a far distance would do.
#include "pipeline/io/TextureMean.h"

#include <fstream>
#include <vector>

#include "pipeline/io/ImageDecode.h"

namespace hlod {

std::optional<glm::vec4> meanColorOfImage(const unsigned char* bytes, std::size_t size) {
    if (bytes == nullptr || size == 0) return std::nullopt;
    std::string why;
    const std::optional<RgbaImage> image = decodeImage({bytes, size}, why);
    if (!image) return std::nullopt;
    return meanLinearColor(*image);
}

std::optional<glm::vec4> meanColorOfImageFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    std::vector<unsigned char> data((std::istreambuf_iterator<char>(in)),
                                    std::istreambuf_iterator<char>());
    return meanColorOfImage(data.data(), data.size());
}

} // namespace hlod
