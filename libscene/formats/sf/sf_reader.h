// The scene file (.sf) reader: six-line records, CAMERA first.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "scenefile/read.h"

namespace scene {

// Reads a whole scene file from memory and reports every problem it finds,
// recovering at the next record. `fileName` goes into the diagnostics.
// Files of kMinBytesInParts bytes or more are read in parts on
// options.threads threads (parseSceneFileInParts) where that gives the
// whole-file reader's result; the others, and the files it does not give,
// by the whole-file reader.
ReadResult parseSceneFile(std::string_view text, std::string fileName,
                          const ReadOptions& options = {});

// The record names: CAMERA, LIGHT and each object kind's, in the order of
// scenefile/object_kinds.def.
std::span<const std::string_view> sceneFileRecordNames();

// The smallest file read in parts: 4 MiB, some 30,000 records, a few
// milliseconds of reading on one core.
inline constexpr std::size_t kMinBytesInParts = std::size_t{4} << 20;

// Reads `text` in up to `parts` parts on as many threads, each part from
// the start of a record name line, and joins them: the result of
// parseSceneFile's whole-file reader, bit for bit, for a file that holds
// no diagnostic but the whole-file checks' (SceneFileParser::finish). For
// any other file, or one with no place to cut, nothing: the caller reads
// it whole.
std::optional<ReadResult> parseSceneFileInParts(std::string_view text, std::string fileName,
                                                const ReadOptions& options, unsigned parts);

}  // namespace scene
