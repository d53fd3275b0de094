// The one translation unit that compiles the header-only third-party implementations
// (tinygltf, the stb_image / stb_image_write it uses, and stb_rect_pack). Nobody else may define these macros.
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <tiny_gltf.h>
// stb_rect_pack: the atlas packer (pipeline/proxy/atlas/PackCharts.cpp).
#define STB_RECT_PACK_IMPLEMENTATION
#include <stb_rect_pack.h>
