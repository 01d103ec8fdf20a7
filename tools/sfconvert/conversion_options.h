// What sfconvert's flags ask of the conversion, for sfconvert and for every
// front end that converts as it does (the web module).
#pragma once

#include <string>

#include "scenefile/convert.h"
#include "tools/sfconvert/sfconvert_options.h"

namespace tools {

// The options scene::convertSceneToFiles gets from `o`: `toStdout` when the
// output is standard output (an instruction file then names no OUTPUT_FILE
// from it), `bufferFile` the name of a .gltf's separate buffer (empty: the
// buffer embedded) or of an .obj's MTL file (empty: none).
scene::ConversionOptions conversionOptionsFor(const SfconvertOptions& o, bool toStdout,
                                              const std::string& bufferFile);

}  // namespace tools
