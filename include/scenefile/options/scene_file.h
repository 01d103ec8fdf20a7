/// @file
/// What reading a scene file (.sf) can be told beyond the common options.
#pragma once

#include <cstddef>

namespace scene {

/// Options of the scene file reader.
struct SceneFileReadOptions {
  /// Read each 4x4 column by column: the repair for files written transposed
  /// (Setting::TransposedMatrices).
  bool transposedMatrices = false;
  /// A file streamed (scenefile/read_stream.h) is read this many bytes a
  /// thread at a time: 2 MiB, some 17,000 records, whose objects take twice
  /// that while they are handed over. A window grows where one record is
  /// longer.
  std::size_t windowBytes = std::size_t{2} << 20;

  friend bool operator==(const SceneFileReadOptions&, const SceneFileReadOptions&) = default;
};

}  // namespace scene
