/// @file
/// What reading a scene file (.sf) can be told beyond the common options.
#pragma once

namespace scene {

/// Options of the scene file reader.
struct SceneFileReadOptions {
  /// Read each 4x4 column by column: the repair for files written transposed
  /// (Setting::TransposedMatrices).
  bool transposedMatrices = false;

  friend bool operator==(const SceneFileReadOptions&, const SceneFileReadOptions&) = default;
};

}  // namespace scene
