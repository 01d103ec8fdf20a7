/// @file
/// The canonical layout of the line formats: what an editor's "format
/// document" gives.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "scenefile/format.h"

namespace scene {

/// `text` laid out as the writers lay out a file, with every word kept as
/// written but a keyword, which is written in upper case: words on a line
/// separated by one space, no blanks at the ends of lines, instruction file
/// blocks indented two spaces a level, one blank line between records and
/// between OUTPUT_FILE and the blocks at the top level and none inside
/// them, and one newline at the end. The line ending (LF or CRLF, that of
/// the first line) and a byte-order mark are kept. Laying out the result
/// again gives it back unchanged, and a writer's output is laid out
/// already. Scene files and instruction files only: nothing for any other
/// format, or for a text with a line of more than sixteen words, a carriage
/// return before a line ending or a first word that begins with a byte-order
/// mark (no valid text has any). The caller lays out only a text that reads
/// without errors, since a broken text's structure is a guess.
std::optional<std::string> canonicalLayout(std::string_view text, Format format);

}  // namespace scene
