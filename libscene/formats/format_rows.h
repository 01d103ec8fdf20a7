// The registry's rows, one function per format, each defined in its format's
// folder (libscene/formats/NAME/NAME_format.cpp) beside its reader and
// writer. Only libscene/format_registry.cpp calls them.
#pragma once

#include "scenefile/format.h"

namespace scene {

FormatInfo sceneFileFormat();        // formats/sf
FormatInfo instructionFileFormat();  // formats/instruction
FormatInfo gltfFormat();             // formats/gltf
FormatInfo glbFormat();              // formats/gltf
FormatInfo povFormat();              // formats/pov

}  // namespace scene
