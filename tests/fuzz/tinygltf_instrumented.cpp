// tinygltf's implementation, compiled from Debian's header into the fuzz
// targets so that its JSON and buffer handling is instrumented (coverage,
// AddressSanitizer) like our own code. Its definitions take the place of
// those in Debian's shared library, which is built without either. The
// reader never decodes images (libscene/formats/gltf/gltf_files.cpp), so
// stb_image is left out.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <tiny_gltf.h>
