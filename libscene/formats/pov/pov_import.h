// What the POV-Ray reader (pov_reader.h) gives: the scene read, and what
// POV-Ray's camera shows beyond the scene's camera matrix.
#pragma once

#include <cstddef>
#include <vector>

#include "scenefile/read.h"

namespace scene {

// What POV-Ray's camera shows beyond what the scene's camera matrix holds.
struct PovCameraView {
  double verticalFovDegrees = 60.0;  // the field of view to render the scene with
  double aspectRatio = 4.0 / 3.0;    // the image's width over its height
  // POV-Ray's world is left-handed: with a left-handed camera (POV-Ray's
  // default) the scene was mirrored (z negated) so that the renderer's
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

}  // namespace scene
