// The one translation unit that compiles the header-only third-party implementations
// (tinygltf, and the stb_image / stb_image_write it uses). Nobody else may define these macros.
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <tiny_gltf.h>
