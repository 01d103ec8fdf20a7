// An editor's view of an instruction file: its blocks (outlineOf) and the
// block around a position (placeAt), from the text alone.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "scenefile/outline.h"

namespace scene {

// OUTPUT_FILE, and each START ... END block, keywords in any case, as the
// reader nests them: MATERIAL and TRANSFORMATION inside an OBJECT; a START
// that cannot nest where it stands ends the blocks open there, as does the
// end of the text; an END closes the innermost open block of its name.
Outline instructionFileOutline(std::string_view text);

// The blocks around line `line`, back to their START lines and on to their
// END lines, a few thousand lines at most each way. A START line is in the
// block around it, where its block's name is completed.
TextPlace instructionFilePlace(std::string_view text, std::size_t lineStart, std::uint32_t line,
                               std::uint32_t column);

}  // namespace scene
