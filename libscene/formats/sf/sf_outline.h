// An editor's view of a scene file: its records (outlineOf) and the record
// around a position (placeAt), from the text alone.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "scenefile/outline.h"

namespace scene {

// Each record: a line whose first word is a record name, in any case, starts
// one, and its next five lines that are neither blank nor a comment nor a
// record name (as written) are its colour and matrix rows, as the reader
// reads them. A line of another word starts a record of no kind, which gets
// no item but keeps its lines from being taken for a record.
Outline sceneFileOutline(std::string_view text);

// The record around line `line`, from at most its five lines before.
TextPlace sceneFilePlace(std::string_view text, std::size_t lineStart, std::uint32_t line,
                         std::uint32_t column);

}  // namespace scene
