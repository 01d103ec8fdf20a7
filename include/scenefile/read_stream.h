/// @file
/// Reading a scene file without holding it whole: its text in windows of
/// bounded size, its objects handed over batch by batch, so that a caller
/// that compiles them as they come (a renderer) never holds the file's text
/// or a model of all its objects.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>

#include "scenefile/format.h"
#include "scenefile/read.h"
#include "scenefile/source_excerpt.h"

namespace scene {

/// Called with each batch of objects in file order; the batch's storage is
/// reused after the call returns (the callee copies what it keeps).
using ObjectBatchSink = std::function<void(std::span<const Object> batch)>;

/// Told, before the first batch, about how many objects the file holds (a
/// file read in windows: its size by its first window's bytes an object),
/// so that a caller can make room for them at once.
using ObjectCountEstimate = std::function<void(std::uint64_t objects)>;

/// What a streamed read held at most at once, for a memory report.
struct StreamReadMemory {
  std::uint64_t textBytes = 0;   ///< the file's text, in bytes of buffer
  std::uint64_t modelBytes = 0;  ///< scene::Object batches, in bytes of room
};

/// What streamSceneFile read.
struct StreamReadResult {
  /// The diagnostics, and a scene of the camera, lights, view and
  /// OUTPUT_FILE, without objects: those went to the sink.
  ReadResult read;
  /// The format read, or nothing where the file was not read (or is in no
  /// known format).
  std::optional<Format> format;
  std::uint64_t objectCount = 0;  ///< objects handed to the sink
  StreamReadMemory memory;
  /// The file was read whole after all (SceneFileReadOptions::windowBytes).
  bool readWhole = false;
};

/// Reads the scene in the file at `path`, as readSceneFile does, and hands
/// its objects to `sink` in file order, each once. A scene file (.sf) larger
/// than one window is read a window at a time (SceneFileReadOptions::
/// windowBytes on each of options.threads threads), each cut at a record's
/// first line and parsed in parts on those threads, while the next window
/// is read: the text is never held whole (two windows at most), and the
/// objects only a window's at a time. Where a window holds a
/// diagnostic of any kind, the file is read again, whole, by readSceneFile,
/// so that the diagnostics are exactly its (the whole-file reader recovers
/// from an error across windows), and the objects the sink has not had yet
/// follow. Any other format, a file of one window and anything that is not
/// a regular file are read whole and handed over in batches. The limits
/// (maxFileSize, from the size on disk, and maxObjects) hold as for
/// readSceneFile. `quotes` keeps the lines the diagnostics point at.
StreamReadResult streamSceneFile(const std::filesystem::path& path, const ReadOptions& options,
                                 const ObjectBatchSink& sink, SourceExcerpts* quotes = nullptr,
                                 const ObjectCountEstimate& estimate = {});

}  // namespace scene
