#include "tools/common/file_io.h"

#include <fcntl.h>
#include <stdio.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <system_error>
#include <vector>

#include "scenefile/read_file.h"
#include "tools/common/output_location.h"

namespace tools {

namespace {

ToolFailure cannotRead(const std::filesystem::path& path, std::string why) {
  return fileFailure(ExitCode::IoError, path.string(), std::move(why));
}

ToolFailure cannotWrite(const std::filesystem::path& path, std::string why) {
  return fileFailure(ExitCode::IoError, path.string(), std::move(why));
}

}  // namespace

Outcome<std::string> readWholeFile(const std::filesystem::path& path, std::uint64_t maxBytes) {
  scene::FileBytes file = scene::readFileBytes(path, maxBytes);
  if (!file.bytes) return cannotRead(path, std::move(file.error));
  return std::move(*file.bytes);
}

namespace {

namespace fs = std::filesystem;

// rename() that fails with EEXIST instead of replacing the target. Where
// the file system has no RENAME_NOREPLACE (EINVAL), a hard link does the
// same (link() never replaces), and the temporary's name goes after.
MaybeFailure renameWithoutReplacing(const fs::path& from, const fs::path& to) {
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) {
    return std::nullopt;
  }
  int failure = errno;
  if (failure == EINVAL || failure == ENOSYS) {
    if (::link(from.c_str(), to.c_str()) == 0) {
      ::unlink(from.c_str());
      return std::nullopt;
    }
    failure = errno;
  }
  return cannotWrite(to, failure == EEXIST ? kNoClobberMessage : std::strerror(failure));
}

// The permissions of a new file: 0666 less the umask. umask() can only be
// read by setting it, so it is set back at once.
unsigned newFileMode() {
  mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666u & ~static_cast<unsigned>(mask);
}

constexpr const char* kLinkLoop = "its symbolic links cannot be followed (a loop, or more than 40)";

// What a file that is no regular file is, for the message that refuses it.
std::string fileKind(mode_t mode) {
  if (S_ISFIFO(mode)) return "a pipe";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "a special file";
}

// Why no file could be created in `folder`, in the words of the folder.
std::string folderProblem(const fs::path& folder, int error) {
  std::string name = folder.empty() ? std::string(".") : folder.string();
  switch (error) {
    case ENOENT:
      return "its folder '" + name + "' does not exist";
    case ENOTDIR:
      return "its folder '" + name + "' is not a folder";
    case EACCES:
    case EPERM:
    case EROFS:
      return "its folder '" + name + "' cannot be written: " + std::strerror(error);
    default:
      return std::strerror(error);
  }
}

// The temporary's file name in `folder`: `.NAME.tmp-XXXXXX`, then `extension`
// where it is kept. A target's name may be as long as the file system allows
// (NAME_MAX, 255 bytes on most), and its temporary's is 12 bytes longer (and
// the extension's more): where the whole would be too long, NAME is cut
// short, at the first byte of a character so that the name stays UTF-8 (and
// the extension too, should it alone leave no room). mkstemp keeps it unique
// whatever is cut.
struct TemporaryName {
  std::string name;
  std::size_t suffix;  // the bytes after XXXXXX: the extension kept
};
TemporaryName temporaryName(const fs::path& folder, const std::string& name,
                            std::string extension) {
  long limit = ::pathconf(folder.empty() ? "." : folder.c_str(), _PC_NAME_MAX);
  std::size_t longest = limit > 0 ? static_cast<std::size_t>(limit) : std::size_t{NAME_MAX};
  const std::string mark = ".tmp-XXXXXX";
  auto characterStart = [](const std::string& text, std::size_t at) {
    while (at > 0 && at < text.size() && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80) {
      --at;
    }
    return at;
  };
  std::size_t fixed = 1 + mark.size();
  if (fixed + extension.size() > longest) {
    extension.resize(characterStart(extension, longest > fixed ? longest - fixed : 0));
  }
  std::size_t room = longest > fixed + extension.size() ? longest - fixed - extension.size() : 0;
  std::size_t kept = name.size() <= room ? name.size() : characterStart(name, room);
  return {"." + name.substr(0, kept) + mark + extension, extension.size()};
}

// Why a file of `mode` is none the tools read or replace: a folder, a
// device, a pipe, a socket; nothing for a regular file.
std::optional<std::string> notRegularFile(mode_t mode) {
  if (S_ISDIR(mode)) return "it is a directory";
  if (!S_ISREG(mode)) return "it is " + fileKind(mode) + ", not a regular file";
  return std::nullopt;
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

MaybeFailure StagedFile::open(const fs::path& target, bool keepExtension) {
  discard();
  finished_ = committed_ = false;
  target_ = target;
  // What the name leads to, as the kernel sees it: this follows every link,
  // the /proc/self/fd ones of /dev/stdout included, which lead to a pipe or
  // a terminal that no path names.
  struct stat info {};
  if (::stat(target.c_str(), &info) == 0) {
    if (std::optional<std::string> problem = notRegularFile(info.st_mode)) {
      return cannotWrite(target, *problem);
    }
  } else if (errno == ELOOP) {
    return cannotWrite(target, kLinkLoop);
  }
  // Through a link, the file it leads to is replaced (or created) and the
  // link stays.
  std::error_code ec;
  if (fs::is_symlink(fs::symlink_status(target, ec))) {
    std::optional<fs::path> end = scene::followLinks(target);
    if (!end) {
      return cannotWrite(target, kLinkLoop);
    }
    target_ = *end;
  }
  fs::file_status file = fs::status(target_, ec);
  if (fs::is_directory(file)) {
    return cannotWrite(target, "it is a directory");
  }
  if (fs::exists(file) && !fs::is_regular_file(file)) {
    return cannotWrite(target, "it is not a regular file");
  }
  mode_ =
      fs::exists(file) ? static_cast<unsigned>(file.permissions() & fs::perms::all) : newFileMode();

  std::string extension = keepExtension ? target_.extension().string() : std::string();
  TemporaryName name = temporaryName(target_.parent_path(), target_.filename().string(), extension);
  std::string pattern = (target_.parent_path() / name.name).string();
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  fd_ = ::mkostemps(buffer.data(), static_cast<int>(name.suffix), O_CLOEXEC);
  if (fd_ < 0) {
    return cannotWrite(target, folderProblem(target_.parent_path(), errno));
  }
  // Keeping the name allocates: if that fails, the file just created must
  // not outlive the exception (discard() knows it only by this name).
  try {
    temporary_ = buffer.data();
  } catch (...) {
    ::unlink(buffer.data());
    ::close(fd_);
    fd_ = -1;
    throw;
  }
  return std::nullopt;
}

MaybeFailure StagedFile::write(std::string_view content) {
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    ssize_t n = ::write(fd_, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return cannotWrite(target_, std::strerror(errno));
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  return std::nullopt;
}

MaybeFailure StagedFile::finish() {
  // mkstemp made the file private; give it the mode the target had or a
  // new file would get. fsync flushes the file, whichever descriptor wrote it.
  if (::fchmod(fd_, static_cast<mode_t>(mode_)) != 0 || ::fsync(fd_) != 0) {
    return cannotWrite(target_, std::strerror(errno));
  }
  int status = ::close(fd_);
  fd_ = -1;
  if (status != 0) return cannotWrite(target_, std::strerror(errno));
  finished_ = true;
  return std::nullopt;
}

MaybeFailure StagedFile::commit(bool replace) {
  if (!finished_) {
    if (MaybeFailure failure = finish()) return failure;
  }
  if (!replace) {
    if (MaybeFailure failure = renameWithoutReplacing(temporary_, target_)) return failure;
  } else if (::rename(temporary_.c_str(), target_.c_str()) != 0) {
    return cannotWrite(target_, std::strerror(errno));
  }
  committed_ = true;
  syncFolder(target_.parent_path());
  return std::nullopt;
}

MaybeFailure writeFileAtomically(const fs::path& path, std::string_view content) {
  return writeFilesAtomically({FileToWrite{path, content}});
}

MaybeFailure replaceFileIfUnchanged(const fs::path& path, std::string_view expected,
                                    std::string_view content) {
  StagedFile staged;
  MaybeFailure failure = staged.open(path, false);
  if (!failure) failure = staged.write(content);
  if (!failure) failure = staged.finish();
  if (failure) return cannotWrite(path, failure->message);
  // As late as it can be: between this read and the rename, a change is
  // lost, as with any editor's save.
  Outcome<std::string> now = readWholeFile(path, expected.size());
  if (!now || *now != expected) return cannotWrite(path, kChangedSinceReadMessage);
  if (MaybeFailure committed = staged.commit()) return cannotWrite(path, committed->message);
  return std::nullopt;
}

MaybeFailure writeFilesAtomically(const std::vector<FileToWrite>& files, bool replace) {
  if (!replace) {
    // Refused before any is written, so that none of a set lands.
    for (const FileToWrite& file : files) {
      if (pathExists(file.path)) return cannotWrite(file.path, kNoClobberMessage);
    }
  }
  std::vector<StagedFile> staged(files.size());
  for (std::size_t i = 0; i < files.size(); ++i) {
    MaybeFailure failure = staged[i].open(files[i].path, false);
    if (!failure) failure = staged[i].write(files[i].content);
    if (!failure) failure = staged[i].finish();
    // Named as given, not as the end of its links.
    if (failure) return cannotWrite(files[i].path, failure->message);
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (MaybeFailure failure = staged[i].commit(replace)) {
      return cannotWrite(files[i].path, failure->message);
    }
  }
  return std::nullopt;
}

bool pathExists(const fs::path& path) {
  std::error_code ec;
  return fs::symlink_status(path, ec).type() != fs::file_type::not_found && !ec;
}

MaybeFailure checkCanWrite(const fs::path& target, bool keepExtension, std::uint64_t bytes) {
  StagedFile probe;
  if (MaybeFailure failure = probe.open(target, keepExtension)) return failure;
  struct statvfs room {};
  if (bytes > 0 && ::fstatvfs(probe.descriptor(), &room) == 0) {
    std::uint64_t blocks = ::geteuid() == 0 ? room.f_bfree : room.f_bavail;
    std::uint64_t free = blocks * room.f_frsize;
    if (free < bytes) {
      return cannotWrite(target, "it needs " + std::to_string(bytes) +
                                     " bytes but the file system has " + std::to_string(free) +
                                     " free");
    }
  }
  return std::nullopt;  // the probe's temporary goes with it
}

MaybeFailure regularFileProblem(const fs::path& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    return cannotRead(path, errno == ELOOP ? kLinkLoop : std::strerror(errno));
  }
  if (std::optional<std::string> problem = notRegularFile(info.st_mode)) {
    return cannotRead(path, *problem);
  }
  return std::nullopt;
}

}  // namespace tools
