// The POV-Ray scene language reader: the part of POV-Ray 3.7's language that
// maps to the scene model (docs/POVRAY.md lists it), read as POV-Ray reads it.
//
// Everything else is named with its line [pov-unsupported]. The reader never
// runs a loop or a macro and never opens a file: a scene that would make
// POV-Ray read another file is refused [pov-refused], and hard limits on the
// size, the tokens, the nesting and the declarations bound the time and
// memory any input can cost [pov-limit].
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "libscene/formats/pov/pov_import.h"
#include "libscene/formats/pov/pov_limits.h"
#include "scenefile/read.h"

namespace scene {

// Reads a POV-Ray scene from memory. The camera's field of view is reported
// as a note [camera-fov] and given in `view`.
PovImport importPov(std::string_view text, std::string fileName, const ReadOptions& options = {});

// Whether the text reads as POV-Ray's language rather than a scene or an
// instruction file: a block comment, a POV-Ray directive (#version,
// #include, #declare, ...), or a lower-case statement keyword followed by a
// brace, before anything else but blanks and // comments.
bool looksLikePov(std::string_view text);

}  // namespace scene
