#include "TestFiles.h"

#include <stb_image.h>

namespace hlod::test {

std::string webScript(const char* name) {
    return std::string(HLOD_TEST_SOURCE_DIR) + "/web/" + name;
}

RgbImage readPng(const std::filesystem::path& file) {
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(file.string().c_str(), &w, &h, &n, 3);
    RgbImage img;
    if (!data) return img;
    img.width = w;
    img.height = h;
    img.pixels.assign(data, data + static_cast<std::size_t>(w) * h * 3);
    stbi_image_free(data);
    return img;
}

} // namespace hlod::test
