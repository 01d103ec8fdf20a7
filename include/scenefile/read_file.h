/// @file
/// Reading a scene from a file by its path, within the limits of
/// ReadOptions, as the tools read their inputs: the size is checked before
/// a byte is read, and a file that cannot be read is a diagnostic.
#pragma once

#include <cstdint>
#include <filesystem>
#include <istream>
#include <limits>
#include <optional>
#include <string>
#include <system_error>

#include "scenefile/diagnostic.h"
#include "scenefile/read.h"
#include "scenefile/source_excerpt.h"

namespace scene {

/// The bytes of a file, or why it could not be read.
struct FileBytes {
  /// The bytes read: the whole file, or one byte past the limit asked for.
  std::optional<std::string> bytes;
  /// Why there are none, in the system's words ("No such file or
  /// directory", "it is a directory").
  std::string error;
  /// The system's error behind `error` (std::errc::is_a_directory for a
  /// folder), for a caller that tells the causes apart.
  std::error_code code;
};

/// The bytes of the file at `path`, up to one byte past `maxBytes`, so that a
/// caller can tell a file longer than that from one as long.
FileBytes readFileBytes(const std::filesystem::path& path,
                        std::uint64_t maxBytes = std::numeric_limits<std::uint64_t>::max());

/// An input's text, read whole within ReadOptions::maxFileSize.
struct SourceText {
  /// The bytes, when they were read and are within the limit.
  std::optional<std::string> text;
  /// Why the input could not be read (FileBytes::error), or empty; the
  /// cannot-read-file diagnostic says it too.
  std::string readError;
  /// The system's error behind `readError` (FileBytes::code).
  std::error_code readErrorCode;
  /// file-too-large or cannot-read-file, about the input's name.
  DiagnosticList diagnostics;

  /// The input was refused for its size (file-too-large).
  bool tooLarge() const { return !text && readError.empty(); }
};

/// The file at `path` as text: a regular file above options.maxFileSize is
/// refused by its size, unread; anything else (a pipe, a device) is read up
/// to one byte past the limit, and refused when it holds more. A folder, a
/// missing or an unreadable file gets cannot-read-file. The diagnostics name
/// the input `name`, or the path as given when it is empty.
SourceText readSourceFile(const std::filesystem::path& path, const ReadOptions& options = {},
                          std::string name = {});

/// A stream (standard input) as text, read up to one byte past
/// options.maxFileSize; the diagnostics name it `name`.
SourceText readSourceStream(std::istream& in, std::string name, const ReadOptions& options = {});

/// Reads the scene in the file at `path` (readSourceFile, then parseScene,
/// which detects the format from the text and the path's extension). With
/// `quotes`, the source lines its diagnostics point at are kept there for
/// formatDiagnostics (scenefile/diagnostic_format.h), and the text itself is
/// not kept.
ReadResult readSceneFile(const std::filesystem::path& path, const ReadOptions& options = {},
                         SourceExcerpts* quotes = nullptr);

}  // namespace scene
