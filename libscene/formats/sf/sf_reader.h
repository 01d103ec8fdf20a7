// The scene file (.sf) reader: six-line records, CAMERA first.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

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

// What the parse of one part of a file found that the whole-file checks
// need.
struct SceneFilePartFacts {
  bool anyRecord = false;
  bool firstIsCamera = false;
  bool cameraNamed = false;
  std::size_t objectsSeen = 0;  // objects and lights named, read or not
  // Every object read is finite (objectsFinite), where the part was asked
  // to check; unchecked counts as finite.
  bool finite = true;
};

// A window of a scene file read as it streams in (streamSceneFile): from
// the file's start or a line that starts with a capital letter, to the end
// of the line before such a line or to the file's end.
struct SceneFileWindow {
  std::string_view text;
  std::uint32_t firstLine = 1;    // the number of its first line in the file
  bool first = true;              // the file's first window: the CAMERA starts it
  std::size_t objectsBefore = 0;  // objects and lights named in the windows before
};

// A window's records, part by part in file order; kept from window to
// window, so that the parts' room for objects is made once.
struct SceneFileWindowRead {
  std::vector<ReadResult> parts;
  std::size_t objectsSeen = 0;  // objects and lights the window named
  std::uint32_t lines = 0;      // the window's newlines
  // The parse's scratch.
  std::vector<SceneFilePartFacts> facts;
  std::vector<std::uint32_t> partLines;
};

// Reads `window` in up to `parts` parts on as many threads, as
// parseSceneFileInParts reads a whole file, without the whole-file checks:
// true where each part read cleanly, the CAMERA came first in the file's
// first window and nowhere else, the objects are within
// options.maxObjects, and every object is finite (parseScene's last check,
// made by each part's thread as it ends, on objects still in its cache). Then `read` holds what the
// whole-file reader would have read from those lines, bit for bit; otherwise the caller reads the
// file whole, for its diagnostics.
bool parseSceneFileWindow(const SceneFileWindow& window, const ReadOptions& options, unsigned parts,
                          SceneFileWindowRead& read);

}  // namespace scene
