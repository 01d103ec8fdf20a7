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

#include "scenefile/read.h"

namespace scene {

inline constexpr std::size_t kMaxPovBytes = std::size_t{256} << 20;
inline constexpr std::size_t kMaxPovTokens = 50'000'000;
inline constexpr int kMaxPovNesting = 64;  // braces, parentheses and vectors inside each other
inline constexpr std::size_t kMaxPovDeclarations = 100'000;


// What POV-Ray's camera shows beyond what the scene's camera matrix holds.
struct PovCameraView {
  double verticalFovDegrees = 60.0;  // the field of view to render the scene with
  double aspectRatio = 4.0 / 3.0;    // the image's width over its height
  // POV-Ray's world is left-handed: with a left-handed camera (POV-Ray's
  // default) the scene was mirrored (z negated) so that sfrender's
  // right-handed camera sees the same picture.
  bool mirrored = false;
};

struct PovImport {
  ReadResult read;
  PovCameraView view;
  // For each object of the scene, the offset in the text of the brace that
  // closes its statement: where a test can add to it.
  std::vector<std::size_t> objectEnds;
};

// Reads a POV-Ray scene from memory. The camera's field of view is reported
// as a note [camera-fov] and given in `view`.
PovImport importPov(std::string_view text, std::string fileName,
                    const ReadOptions& options = {});

// Whether the text reads as POV-Ray's language rather than a scene or an
// instruction file: a block comment, a POV-Ray directive (#version,
// #include, #declare, ...), or a lower-case statement keyword followed by a
// brace, before anything else but blanks and // comments.
bool looksLikePov(std::string_view text);

}  // namespace scene
