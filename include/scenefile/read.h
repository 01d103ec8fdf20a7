/// @file
/// Reading a scene in any format: the options every reader takes, what it
/// gives back, and the entry points that detect the format or are told it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <stop_token>
#include <string_view>

#include "scenefile/diagnostic.h"
#include "scenefile/format.h"
#include "scenefile/options/gltf.h"
#include "scenefile/options/obj.h"
#include "scenefile/options/pov.h"
#include "scenefile/options/scene_file.h"
#include "scenefile/scene.h"

namespace scene {

/// The default limit on the size of one input (docs/FORMATS.md, "Limits"):
/// 1 GiB. Each limit bounds the memory and time a hostile or mistaken file
/// can take, and each has a flag on the tools that raises it.
inline constexpr std::uint64_t kDefaultMaxFileSize = std::uint64_t{1} << 30;
/// The default limit on objects and lights together: each costs memory when
/// read and time when rendered (every light at every shading point).
inline constexpr std::size_t kDefaultMaxObjects = 5'000'000;

/// What a reader is told. The fields here apply to every format; each
/// format's own settings are in its member, and only its reader reads them.
struct ReadOptions {
  /// The list takes no more errors past this many (DiagnosticList).
  std::size_t errorLimit = DiagnosticList::kDefaultErrorLimit;
  /// What a reader cannot carry over into the scene (a glTF mesh that is no
  /// primitive, a spot light made a point light) is an error, not a warning.
  bool noLoss = false;
  /// A larger input is refused unread (file-too-large); the tools check the
  /// size before reading, and so do the readers of a glTF's external buffers.
  std::uint64_t maxFileSize = kDefaultMaxFileSize;
  /// Reading stops at the first object or light past this (too-many-objects).
  std::size_t maxObjects = kDefaultMaxObjects;
  /// The threads a reader may use: 0, every core; 1, the caller's alone.
  /// Only the scene file reader uses more than one, on files of 4 MiB and
  /// more; the result is the same at any count.
  unsigned threads = 0;
  /// Scene files (.sf).
  SceneFileReadOptions sceneFile;
  /// glTF 2.0 (.gltf, .glb).
  GltfReadOptions gltf;
  /// Wavefront OBJ (.obj).
  ObjReadOptions obj;
  /// POV-Ray (.pov).
  PovReadOptions pov;
  /// Asks a read to stop early: the readers of scene files and instruction
  /// files look at it every few thousand lines and, once it is requested,
  /// return what they have read so far, unchecked as a whole. Such a
  /// result is incomplete even where ok(), so that only a caller that no
  /// longer wants it (an editor whose text has changed again) should stop
  /// a read. The other readers read to the end.
  std::stop_token stop;

  friend bool operator==(const ReadOptions&, const ReadOptions&) = default;
};

/// The scene and everything found while reading it. The scene is complete
/// only when ok(); otherwise it holds the records that were read cleanly.
struct ReadResult {
  Scene scene;
  DiagnosticList diagnostics;

  /// No error was found.
  bool ok() const { return !diagnostics.hasErrors(); }
};

/// The format of `text`, recognised from its content (FormatInfo::claims, in
/// the order of formats()); `fileName`'s extension decides only what the
/// content leaves open. Nothing when the text is in no known format.
std::optional<Format> detectFormat(std::string_view text, std::string_view fileName = {});

/// Reports file-too-large when an input of `bytes` bytes is above
/// options.maxFileSize; true when it is within the limit. The tools call it
/// with the size on disk before reading; parseScene checks the text's size.
/// `subject` names the input in the message; `sizeKnown` false says that
/// `bytes` is only what was read of a longer input (a pipe).
bool checkFileSize(std::uint64_t bytes, const ReadOptions& options, DiagnosticList& out,
                   std::string_view subject = "the file", bool sizeKnown = true);

/// Detects the format and reads `text` with its reader. Text in no known
/// format gets an unknown-format error, text above options.maxFileSize
/// file-too-large. A glTF file's external buffers are looked for in the
/// folder of `fileName`, and nowhere else. Every accepted scene holds only
/// finite numbers and has passed the rules of scenefile/validation.h that
/// its reader applies.
ReadResult parseScene(std::string_view text, std::string fileName, const ReadOptions& options = {});

/// Reads `text` as `format`, whatever its content says.
ReadResult parseSceneAs(Format format, std::string_view text, std::string fileName,
                        const ReadOptions& options = {});

}  // namespace scene
