// What each stage of a render held (sfrender -v): the text and the model
// the read held at most, the compiled scene's parts, the image, and the
// process's peak, in MB and in bytes an object.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace tools {

struct StageMemory {
  std::string_view stage;  // "text", "model", "records", ...
  std::uint64_t bytes = 0;
};

// "held: text 8.4 MB (8 B/object), ...; peak 290.1 MB (290 B/object)":
// each stage's bytes and the peak, by `objects` (at least 1).
std::string memoryReportText(std::span<const StageMemory> stages, std::uint64_t peakBytes,
                             std::uint64_t objects);

// The process's peak resident set so far (getrusage's ru_maxrss), in bytes.
std::uint64_t peakResidentBytes();

}  // namespace tools
