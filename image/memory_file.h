// A file that lives in memory only, for a library that writes a file by its
// name: what it writes is read back whole, then written to the target by
// code that checks every write (file_io.h).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "tools/common/tool_failure.h"

namespace image {

// A file made by memfd_create, which a library opens by its name
// (/proc/self/fd/N) or is handed the descriptor of. Writing to it fails
// only where memory does; nothing of it ever reaches a folder.
class MemoryFile {
 public:
  MemoryFile() = default;
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;
  ~MemoryFile();

  // Makes the file. A failure is a write's (ExitCode::IoError).
  tools::MaybeFailure create();
  int descriptor() const { return fd_; }
  // The name a library opens it by.
  std::string name() const;
  // Everything written to it, mapped (valid while the MemoryFile lives), or
  // why it cannot be mapped.
  tools::Outcome<std::string_view> bytes();

 private:
  int fd_ = -1;
  void* map_ = nullptr;
  std::size_t mapped_ = 0;
};

}  // namespace image
