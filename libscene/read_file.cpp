#include "scenefile/read_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <optional>
#include <system_error>
#include <thread>

#include "libscene/core/populate_pages.h"

namespace scene {

namespace {

// Files from this size on have the later half of their buffer's pages
// faulted in on a thread of their own while the reading fills the first.
constexpr std::size_t kPrefaultFrom = std::size_t{16} << 20;

// The whole pages of [begin, end) faulted in, ready to be written, on a
// thread of its own, which the destructor waits for. A fresh page's first
// touch costs more than the copy into it on these machines
// (docs/history/PERFORMANCE.md, "Huge pages dropped"), and a read on one
// thread paid every one: the 119 MB of a 1,000,000-object scene file took
// 70 ms (docs/history/PERFORMANCE.md, "Big scenes: memory kept, and fewer
// passes").
class PrefaultedPages {
 public:
  PrefaultedPages(const char* begin, const char* end) {
    try {
      thread_ = std::thread([begin, end] { populatePagesForWriting(begin, end); });
    } catch (const std::system_error&) {
      // No thread: the reading faults the pages in itself.
    }
  }
  ~PrefaultedPages() {
    if (thread_.joinable()) thread_.join();
  }
  PrefaultedPages(const PrefaultedPages&) = delete;
  PrefaultedPages& operator=(const PrefaultedPages&) = delete;

 private:
  std::thread thread_;
};

FileBytes cannotRead(std::error_code code, std::string why = {}) {
  if (why.empty()) why = std::strerror(code.value());
  return {std::nullopt, std::move(why), code};
}

SourceText unreadable(std::string name, FileBytes why, const ReadOptions& options) {
  SourceText source{std::nullopt, std::move(why.error), why.code,
                    DiagnosticList(name, options.errorLimit)};
  source.diagnostics.error(DiagnosticCode::CannotReadFile, {},
                           "cannot read the file: " + source.readError);
  return source;
}

// `bytes` as the text of input `name`, refused when above the limit:
// whatever was read past it says only that the input is longer.
SourceText withinLimit(std::string bytes, std::string name, const ReadOptions& options) {
  SourceText source{std::nullopt, {}, {}, DiagnosticList(std::move(name), options.errorLimit)};
  if (checkFileSize(bytes.size(), options, source.diagnostics, "the input", false)) {
    source.text = std::move(bytes);
  }
  return source;
}

}  // namespace

FileBytes readFileBytes(const std::filesystem::path& path, std::uint64_t maxBytes) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    return cannotRead(std::make_error_code(std::errc::is_a_directory), "it is a directory");
  }
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return cannotRead(std::error_code(errno, std::generic_category()));
  std::string content;
  struct stat info {};
  if (::fstat(fd, &info) == 0 && S_ISREG(info.st_mode)) {
    content.reserve(static_cast<std::size_t>(
        std::min<std::uint64_t>(static_cast<std::uint64_t>(info.st_size), maxBytes)));
  }
  std::optional<PrefaultedPages> laterHalf;
  if (content.capacity() >= kPrefaultFrom) {
    laterHalf.emplace(content.data() + content.capacity() / 2, content.data() + content.capacity());
  }
  char buffer[1 << 16];
  for (;;) {
    ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0) {
      if (errno == EINTR) continue;
      std::error_code failure(errno, std::generic_category());
      ::close(fd);
      return cannotRead(failure);
    }
    if (n == 0) break;
    content.append(buffer, static_cast<std::size_t>(n));
    if (content.size() > maxBytes) {
      content.resize(static_cast<std::size_t>(maxBytes) + 1);
      break;
    }
  }
  ::close(fd);
  return {std::move(content), {}, {}};
}

SourceText readSourceFile(const std::filesystem::path& path, const ReadOptions& options,
                          std::string name) {
  if (name.empty()) name = path.string();
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode)) {
    SourceText refused{std::nullopt, {}, {}, DiagnosticList(name, options.errorLimit)};
    if (!checkFileSize(static_cast<std::uint64_t>(info.st_size), options, refused.diagnostics)) {
      return refused;
    }
  }
  FileBytes file = readFileBytes(path, options.maxFileSize);
  if (!file.bytes) return unreadable(std::move(name), std::move(file), options);
  // Not a regular file, or one that grew: its whole size is unknown.
  return withinLimit(std::move(*file.bytes), std::move(name), options);
}

SourceText readSourceStream(std::istream& in, std::string name, const ReadOptions& options) {
  std::string text;
  char chunk[1 << 16];
  int readError = 0;
  while (text.size() <= options.maxFileSize) {
    std::uint64_t room = options.maxFileSize + 1 - text.size();
    errno = 0;
    in.read(chunk, static_cast<std::streamsize>(std::min<std::uint64_t>(sizeof chunk, room)));
    readError = errno;
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (!in) break;
  }
  // std::cin takes a read that failed (standard input a folder, EISDIR, or
  // a failing disk, EIO) for the end of the input: the C stream under it
  // keeps the error, which an empty input would otherwise hide.
  if (in.bad() || (&in == &std::cin && std::ferror(stdin))) {
    return unreadable(
        std::move(name),
        readError != 0 ? cannotRead(std::error_code(readError, std::generic_category()))
                       : cannotRead(std::make_error_code(std::errc::io_error), "the read failed"),
        options);
  }
  return withinLimit(std::move(text), std::move(name), options);
}

ReadResult readSceneFile(const std::filesystem::path& path, const ReadOptions& options,
                         SourceExcerpts* quotes) {
  SourceText source = readSourceFile(path, options);
  if (!source.text) return {Scene{}, std::move(source.diagnostics)};
  std::string name = path.string();
  ReadResult result = parseScene(*source.text, name, options);
  if (quotes) quotes->capture(name, *source.text, result.diagnostics);
  return result;
}

}  // namespace scene
