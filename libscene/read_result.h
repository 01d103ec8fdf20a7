// What every reader takes and gives back.
#pragma once

#include <cstddef>

#include "libscene/diagnostic.h"
#include "libscene/scene.h"

namespace scene {

struct ReadOptions {
  // Read each 4x4 of a scene file column by column: the repair for files
  // written transposed (sfconvert --transpose-matrices).
  bool transposedMatrices = false;
  std::size_t errorLimit = DiagnosticList::kDefaultErrorLimit;
  // What a reader cannot carry over into the scene (a glTF mesh that is no
  // primitive, a spot light made a point light) is an error, not a warning.
  bool noLoss = false;
  // POV-Ray: constructs outside the subset are warnings and are skipped
  // (sfconvert --skip-unsupported).
  bool skipUnsupported = false;
  // POV-Ray: the image size that image_width and image_height stand for;
  // 0 for sfrender's default, 640 x 480.
  int imageWidth = 0;
  int imageHeight = 0;
};

// The scene and everything found while reading it. The scene is complete
// only when ok(); otherwise it holds the records that were read cleanly.
struct ReadResult {
  Scene scene;
  DiagnosticList diagnostics;

  bool ok() const { return !diagnostics.hasErrors(); }
};

}  // namespace scene
