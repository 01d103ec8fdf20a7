// The canonical layout of an instruction file (scenefile/layout.h).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace scene {

// The blocks as the writer lays them out: keywords in upper case, each line
// indented two spaces for each block it stands in (START and END at their
// block's own level), blank lines dropped but one before each OUTPUT_FILE
// and top-level START after the first line. The level comes from the names
// alone (a CAMERA, LIGHT or OBJECT line is at the top, a MATERIAL or
// TRANSFORMATION line inside an OBJECT), so no text indents deeper than the
// format nests. Nothing for a line of more words than any line has room
// for.
std::optional<std::string> instructionFileLayout(std::string_view text);

}  // namespace scene
