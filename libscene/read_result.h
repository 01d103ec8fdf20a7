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
};

// The scene and everything found while reading it. The scene is complete
// only when ok(); otherwise it holds the records that were read cleanly.
struct ReadResult {
  Scene scene;
  DiagnosticList diagnostics;

  bool ok() const { return !diagnostics.hasErrors(); }
};

}  // namespace scene
