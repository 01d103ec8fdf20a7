#include "tools/common/file_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>
#include <vector>

#include "libscene/output_location.h"

namespace tools {

std::optional<std::string> readWholeFile(const std::filesystem::path& path, std::string& error,
                                         std::uint64_t maxBytes) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    error = "it is a directory";
    return std::nullopt;
  }
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    error = std::strerror(errno);
    return std::nullopt;
  }
  std::string content;
  struct stat info {};
  if (::fstat(fd, &info) == 0 && S_ISREG(info.st_mode)) {
    content.reserve(static_cast<std::size_t>(
        std::min<std::uint64_t>(static_cast<std::uint64_t>(info.st_size), maxBytes)));
  }
  char buffer[1 << 16];
  for (;;) {
    ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0) {
      if (errno == EINTR) continue;
      error = std::strerror(errno);
      ::close(fd);
      return std::nullopt;
    }
    if (n == 0) break;
    content.append(buffer, static_cast<std::size_t>(n));
    if (content.size() > maxBytes) {
      content.resize(static_cast<std::size_t>(maxBytes) + 1);
      break;
    }
  }
  ::close(fd);
  return content;
}

namespace {

namespace fs = std::filesystem;

// The permissions of a new file: 0666 less the umask. umask() can only be
// read by setting it, so it is set back at once.
unsigned newFileMode() {
  mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666u & ~static_cast<unsigned>(mask);
}

// Flushes a folder's entries, so that a rename in it survives a crash too.
// Only a power loss needs this, so a failure is not an error.
void syncFolder(const fs::path& folder) {
  int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

StagedFile::~StagedFile() {
  discard();
}

void StagedFile::discard() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (!temporary_.empty() && !committed_) ::unlink(temporary_.c_str());
  temporary_.clear();
}

bool StagedFile::open(const fs::path& target, bool keepExtension, std::string& error) {
  discard();
  finished_ = committed_ = false;
  // Through a link, the file it leads to is replaced (or created) and the
  // link stays.
  target_ = target;
  std::error_code ec;
  if (fs::is_symlink(fs::symlink_status(target, ec))) {
    std::optional<fs::path> end = scene::followLinks(target);
    if (!end) {
      error = "its symbolic links cannot be followed (a loop, or more than 40)";
      return false;
    }
    target_ = *end;
  }
  fs::file_status file = fs::status(target_, ec);
  if (fs::is_directory(file)) {
    error = "it is a directory";
    return false;
  }
  if (fs::exists(file) && !fs::is_regular_file(file)) {
    error = "it is not a regular file";
    return false;
  }
  mode_ =
      fs::exists(file) ? static_cast<unsigned>(file.permissions() & fs::perms::all) : newFileMode();

  std::string name = "." + target_.filename().string() + ".tmp-XXXXXX";
  std::string extension = keepExtension ? target_.extension().string() : std::string();
  std::string pattern = (target_.parent_path() / (name + extension)).string();
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  fd_ = ::mkostemps(buffer.data(), static_cast<int>(extension.size()), O_CLOEXEC);
  if (fd_ < 0) {
    error = std::strerror(errno);
    return false;
  }
  temporary_ = buffer.data();
  return true;
}

bool StagedFile::write(std::string_view content, std::string& error) {
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    ssize_t n = ::write(fd_, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      error = std::strerror(errno);
      return false;
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

bool StagedFile::finish(std::string& error) {
  // mkstemp made the file private; give it the mode the target had or a
  // new file would get. fsync flushes the file, whichever descriptor wrote it.
  if (::fchmod(fd_, static_cast<mode_t>(mode_)) != 0 || ::fsync(fd_) != 0) {
    error = std::strerror(errno);
    return false;
  }
  int status = ::close(fd_);
  fd_ = -1;
  if (status != 0) {
    error = std::strerror(errno);
    return false;
  }
  finished_ = true;
  return true;
}

bool StagedFile::commit(std::string& error) {
  if (!finished_ && !finish(error)) return false;
  if (::rename(temporary_.c_str(), target_.c_str()) != 0) {
    error = std::strerror(errno);
    return false;
  }
  committed_ = true;
  syncFolder(target_.parent_path());
  return true;
}

bool writeFileAtomically(const fs::path& path, std::string_view content, std::string& error) {
  return writeFilesAtomically({FileToWrite{path, content}}, error);
}

bool writeFilesAtomically(const std::vector<FileToWrite>& files, std::string& error,
                          fs::path* failed) {
  std::vector<StagedFile> staged(files.size());
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (!staged[i].open(files[i].path, false, error) || !staged[i].write(files[i].content, error) ||
        !staged[i].finish(error)) {
      if (failed) *failed = files[i].path;
      return false;
    }
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (!staged[i].commit(error)) {
      if (failed) *failed = files[i].path;
      return false;
    }
  }
  return true;
}

bool isSameFile(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code ec;
  return std::filesystem::exists(a, ec) && std::filesystem::exists(b, ec) &&
         std::filesystem::equivalent(a, b, ec);
}

}  // namespace tools
