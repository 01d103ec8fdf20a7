/// @file
/// What reading and writing POV-Ray's scene language (.pov) can be told
/// beyond the common options.
#pragma once

#include <optional>

namespace scene {

/// Options of the POV-Ray reader.
struct PovReadOptions {
  /// Constructs outside the subset are warnings and are skipped
  /// (Setting::SkipUnsupported), instead of errors.
  bool skipUnsupported = false;
  /// The image size that POV-Ray's image_width and image_height stand for.
  int imageWidth = 640;
  int imageHeight = 480;

  friend bool operator==(const PovReadOptions&, const PovReadOptions&) = default;
};

/// Options of the POV-Ray writer: the render settings whose picture the
/// file reproduces.
struct PovWriteOptions {
  /// The vertical field of view in degrees; unset takes the scene's View,
  /// and 60 for a scene without one.
  std::optional<double> verticalFovDegrees;
  /// The image size, for the aspect ratio; 0 x 0 takes the scene's View
  /// (480 rows at its aspect ratio), and 640 x 480 for a scene without one.
  int width = 0;
  int height = 0;
  /// The bounces (max_trace_level).
  int maxDepth = 5;
  /// Every object unlit in a colour of its own, no lights: an
  /// object-identity picture for geometry cross-checks.
  bool flat = false;

  friend bool operator==(const PovWriteOptions&, const PovWriteOptions&) = default;
};

}  // namespace scene
