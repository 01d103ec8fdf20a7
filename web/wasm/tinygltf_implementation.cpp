// tinygltf's code, compiled once, as Debian's libtinygltf.so is built (its
// README.Debian): the stb image reader and writer and nlohmann's JSON. The
// glTF reader sets its own image loader, so no image is ever decoded.
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <tiny_gltf.h>
