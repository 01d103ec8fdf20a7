// The registry's rows, one function per format, each defined in its format's
// folder (libscene/formats/FOLDER/FOLDER_format.cpp) beside its reader and
// writer, and named in scenefile/formats.def. Only
// libscene/format_registry.cpp calls them.
#pragma once

#include "scenefile/format.h"

namespace scene {

#define SCENEFILE_FORMAT(enumerator, name, folder, row) FormatInfo row();
#include "scenefile/formats.def"
#undef SCENEFILE_FORMAT

}  // namespace scene
