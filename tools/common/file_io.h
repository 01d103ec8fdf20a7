// Whole-file reads and writes that never leave a half-written file behind.
//
// Every tool writes its outputs the same way: into a temporary file beside
// the target, named `.NAME.tmp-XXXXXX` (NAME the target's file name, cut
// short where the whole would be longer than the file system allows a name
// to be; XXXXXX six characters chosen by mkstemp; then NAME's extension again
// where the caller asks for it), flushed to disk, then renamed over the
// target. rename() replaces a name in one step, so a reader, or a run killed
// at any moment (even by SIGKILL), finds the old file or the new one, never a
// part; a killed run leaves at most its temporary. Two runs never share a
// temporary: mkstemp creates it exclusively.
//
// A failure here is a ToolFailure with the status of a file that cannot be
// read or written (ExitCode::IoError), the file's name in `file` and the
// reason alone in `message` ("it is a directory"), which each caller puts
// in its own sentence.
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tools/common/tool_failure.h"

namespace tools {

// The file's bytes, or why they could not be read. Reading stops after
// `maxBytes` + 1 bytes, which tells a caller with a limit that the file (a
// pipe, or a file that grew since its size was looked at) is over it
// without reading it all.
Outcome<std::string> readWholeFile(
    const std::filesystem::path& path,
    std::uint64_t maxBytes = std::numeric_limits<std::uint64_t>::max());

// A file being written under a temporary name beside its target, which gets
// the target's name only on commit(); destroyed before that, it removes the
// temporary. When `target` is a symbolic link, the file at the end of the
// link is replaced (or created) and the link stays, as `cp` and the shell's
// `>` do. A directory, a device or a pipe is refused. The new file keeps the
// permissions of the file it replaces, or gets those of a new file (0666
// less the umask).
class StagedFile {
 public:
  StagedFile() = default;
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;
  ~StagedFile();

  // Creates the temporary; `keepExtension` ends its name with the target's
  // extension, for a writer that opens it by name and chooses the format by
  // the extension (sfrender's images no longer do: they are made in memory
  // first, image_file.h).
  MaybeFailure open(const std::filesystem::path& target, bool keepExtension);
  // The temporary, open for writing, for writers that take a descriptor.
  int descriptor() const { return fd_; }
  // The temporary's name, for writers that open the file themselves.
  const std::filesystem::path& temporaryPath() const { return temporary_; }

  MaybeFailure write(std::string_view content);
  // Flushes the temporary to disk, whoever wrote it, and closes it: a crash
  // after the rename must not leave a renamed but empty file.
  MaybeFailure finish();
  // Renames the finished temporary over the target. With `replace` false
  // (--no-clobber), an existing target is kept and commit fails, decided
  // in the same step as the rename (RENAME_NOREPLACE), so that a file
  // made meanwhile by another program is not replaced either.
  MaybeFailure commit(bool replace = true);

 private:
  void discard();

  int fd_ = -1;
  bool finished_ = false;
  bool committed_ = false;
  unsigned mode_ = 0;
  std::filesystem::path target_;
  std::filesystem::path temporary_;
};

// Writes `content` to `path` through a StagedFile: a reader sees the old file
// or the new one, never a part. On failure, no file is left over.
MaybeFailure writeFileAtomically(const std::filesystem::path& path, std::string_view content);

// Writes `content` over `path` as writeFileAtomically does, if the file
// still holds `expected` (what was read from it) when the new file is ready
// to take its name: a file an editor or another run changed meanwhile is
// left as it is, and the write fails (sfcheck --fix). The file is compared
// by its bytes, which also catches a change that keeps its size and time.
MaybeFailure replaceFileIfUnchanged(const std::filesystem::path& path, std::string_view expected,
                                    std::string_view content);

// The message for a file that changed since it was read.
inline constexpr const char* kChangedSinceReadMessage =
    "the file changed since it was read, so it is left as it is";

struct FileToWrite {
  std::filesystem::path path;
  std::string_view content;
};

// Writes several files that belong together (a .gltf and its .bin): every
// temporary is written and flushed first, and only then are they renamed,
// one right after the other in the given order, so that the moment in which
// a kill leaves the new first file beside the old second one is that of one
// rename() call, not that of a whole write.
// A failure names the file that could not be written, as given.
// With `replace` false (--no-clobber), none is written over an existing file.
MaybeFailure writeFilesAtomically(const std::vector<FileToWrite>& files, bool replace = true);

// Whether something is at `path` (a file, a folder, a link even to nothing),
// which --no-clobber keeps.
bool pathExists(const std::filesystem::path& path);

// The message for an output that --no-clobber keeps.
inline constexpr const char* kNoClobberMessage = "the file exists, and --no-clobber keeps it";

// Whether `target` can be written, found out the way the write itself will
// go: a StagedFile is opened (the temporary created) and discarded. For a
// long job (a render) to learn before it starts that its output has no
// folder, a read-only one, or is a folder or a device. With `bytes` > 0,
// also whether the file system has that much room left (for root, the
// blocks kept for root count).
MaybeFailure checkCanWrite(const std::filesystem::path& target, bool keepExtension,
                           std::uint64_t bytes);

// Why `path` cannot be read as a file: it does not exist, or it (the end of
// its links) is a folder, a device, a pipe or a socket, which could never
// end (/dev/zero) or block (a pipe) a reader; nothing when it is a regular
// file. The rule of every file a tool reads by a name it was given, as the
// glTF reader's for a buffer's file.
MaybeFailure regularFileProblem(const std::filesystem::path& path);

}  // namespace tools
