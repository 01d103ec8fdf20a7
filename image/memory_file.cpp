#include "image/memory_file.h"

#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace image {

MemoryFile::~MemoryFile() {
  if (map_) ::munmap(map_, mapped_);
  if (fd_ >= 0) ::close(fd_);
}

namespace {

tools::ToolFailure inMemoryFailure(std::string why) {
  return tools::toolFailure(tools::ExitCode::IoError, std::move(why));
}

}  // namespace

tools::MaybeFailure MemoryFile::create() {
  fd_ = ::memfd_create("sfrender-image", MFD_CLOEXEC);
  if (fd_ < 0) {
    return inMemoryFailure(std::string("no file in memory could be made: ") + std::strerror(errno));
  }
  return std::nullopt;
}

std::string MemoryFile::name() const {
  return "/proc/self/fd/" + std::to_string(fd_);
}

tools::Outcome<std::string_view> MemoryFile::bytes() {
  struct stat info {};
  if (::fstat(fd_, &info) != 0) return inMemoryFailure(std::strerror(errno));
  if (map_) ::munmap(map_, mapped_);
  map_ = nullptr;
  mapped_ = static_cast<std::size_t>(info.st_size);
  if (mapped_ == 0) return std::string_view();
  void* map = ::mmap(nullptr, mapped_, PROT_READ, MAP_SHARED, fd_, 0);
  if (map == MAP_FAILED) {
    return inMemoryFailure(std::string("the image in memory cannot be read: ") +
                           std::strerror(errno));
  }
  map_ = map;
  return std::string_view(static_cast<const char*>(map_), mapped_);
}

}  // namespace image
