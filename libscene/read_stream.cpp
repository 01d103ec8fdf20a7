// Reading a scene file in windows (scenefile/read_stream.h).
#include "scenefile/read_stream.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "libscene/core/finite_check.h"
#include "libscene/core/populate_pages.h"
#include "libscene/formats/sf/sf_reader.h"
#include "scenefile/read_file.h"
#include "scenefile/validation.h"

namespace scene {

namespace {

// The batches a scene read whole is handed over in: 1 MiB of objects.
constexpr std::size_t kWholeReadBatch = (std::size_t{1} << 20) / sizeof(Object);

// Hands `objects` from `from` on to the sink in batches; the count handed.
std::uint64_t handOver(const std::vector<Object>& objects, std::size_t from,
                       const ObjectBatchSink& sink) {
  std::span<const Object> all(objects);
  for (std::size_t at = from; at < all.size(); at += kWholeReadBatch) {
    sink(all.subspan(at, std::min(kWholeReadBatch, all.size() - at)));
  }
  return all.size() > from ? all.size() - from : 0;
}

// The file read whole (readSceneFile), the objects past the first `handed`
// handed over: a file in another format, one window long, or whose windows
// held a diagnostic.
StreamReadResult readWhole(const std::filesystem::path& path, const ReadOptions& options,
                           const ObjectBatchSink& sink, SourceExcerpts* quotes,
                           const ObjectCountEstimate& estimate, std::uint64_t handed,
                           StreamReadMemory memory) {
  StreamReadResult result;
  result.readWhole = true;
  SourceText source = readSourceFile(path, options);
  if (!source.text) {
    result.read = ReadResult{Scene{}, std::move(source.diagnostics)};
    return result;
  }
  std::string name = path.string();
  result.format = detectFormat(*source.text, name);
  result.read = parseScene(*source.text, name, options);
  if (quotes) quotes->capture(name, *source.text, result.read.diagnostics);
  std::vector<Object>& objects = result.read.scene.objects;
  memory.textBytes = std::max<std::uint64_t>(memory.textBytes, source.text->capacity());
  memory.modelBytes =
      std::max<std::uint64_t>(memory.modelBytes, objects.capacity() * sizeof(Object));
  source.text.reset();
  if (handed == 0 && estimate) estimate(objects.size());
  result.objectCount = handed + handOver(objects, static_cast<std::size_t>(handed), sink);
  std::vector<Object>().swap(objects);
  result.memory = memory;
  return result;
}

// Room for a window's bytes, in whole 2 MiB pages advised huge
// (adviseHugePages) and left unset until read into: a vector of chars
// zeroes its room first, a 4 KiB page at a time, and the first window's
// buffers were most of the 40 ms before the first parse at 1,000,000
// objects.
class WindowBytes {
 public:
  static constexpr std::size_t kPage = std::size_t{1} << 21;

  char* data() const { return bytes_.get(); }
  std::size_t size() const { return size_; }
  std::size_t room() const { return room_; }
  // `size` bytes, the first `kept` of the old ones kept where the room
  // grows.
  void resize(std::size_t size, std::size_t kept) {
    if (size > room_) {
      // Small windows (tests, mostly) in room of their own size.
      const std::size_t unit = size >= kPage ? kPage : 64;
      std::size_t room = (size + unit - 1) / unit * unit;
      std::unique_ptr<char, Free> grown(static_cast<char*>(std::aligned_alloc(unit, room)));
      if (!grown) throw std::bad_alloc();
      adviseHugePages(grown.get(), grown.get() + room);
      if (kept > 0) std::memcpy(grown.get(), bytes_.get(), kept);
      bytes_ = std::move(grown);
      room_ = room;
    }
    size_ = size;
  }

 private:
  struct Free {
    void operator()(char* bytes) const { std::free(bytes); }
  };
  std::unique_ptr<char, Free> bytes_;
  std::size_t size_ = 0;
  std::size_t room_ = 0;
};

// The bytes of an open file, read into a buffer that holds one window and
// the start of the next. While a window is parsed, the next one is read into
// a second buffer on a thread of its own (readAhead, takeAhead).
class WindowBuffer {
 public:
  WindowBuffer(int fd, std::size_t window) : fd_(fd), window_(window) {}
  WindowBuffer(const WindowBuffer&) = delete;
  WindowBuffer& operator=(const WindowBuffer&) = delete;
  ~WindowBuffer() { takeAhead(); }

  // Fills the buffer up to the window's size, the start of the next window
  // that it holds included (so that its room is made once); false where the
  // read failed.
  bool fill() {
    if (bytes_.size() < window_) bytes_.resize(window_, held_);
    if (failed_ || !readInto(bytes_, held_)) {
      failed_ = true;
      return false;
    }
    return true;
  }

  // Where the window ends: at the last line in the buffer that starts with
  // a capital letter (a record's name, in a valid file), or the file's end;
  // 0 where the buffer holds no such line past its first.
  std::size_t windowEnd() const {
    if (atEnd_) return held_;
    const char* bytes = bytes_.data();
    for (std::size_t at = held_; at > 1; --at) {
      if (bytes[at - 1] == '\n' && at < held_ && bytes[at] >= 'A' && bytes[at] <= 'Z') {
        return at;
      }
    }
    return 0;
  }

  // Starts reading what follows the window's `end` bytes into the second
  // buffer, after the bytes the buffer holds past `end`: on a thread of its
  // own, so that the reading overlaps the window's parse (where no thread
  // can start, here and now). The window's text stays as it is until
  // takeAhead.
  void readAhead(std::size_t end) {
    ahead_.resize(std::max(window_, held_ - end), 0);
    std::memcpy(ahead_.data(), bytes_.data() + end, held_ - end);
    aheadHeld_ = held_ - end;
    readingAhead_ = true;
    auto read = [this] { aheadRead_ = readInto(ahead_, aheadHeld_); };
    try {
      reader_ = std::thread(read);
    } catch (const std::system_error&) {
      read();
    }
  }

  // Waits for readAhead's reading, whose buffer then becomes this one: the
  // window is dropped, what followed it kept.
  void takeAhead() {
    if (reader_.joinable()) reader_.join();
    if (!readingAhead_) return;
    readingAhead_ = false;
    std::swap(bytes_, ahead_);
    held_ = aheadHeld_;
    failed_ = failed_ || !aheadRead_;
  }

  // A buffer of one more window, for a record longer than the window.
  void grow() { window_ *= 2; }

  std::string_view text(std::size_t end) const { return {bytes_.data(), end}; }
  std::string_view held() const { return {bytes_.data(), held_}; }
  bool empty() const { return held_ == 0; }
  std::uint64_t total() const { return total_; }
  std::uint64_t capacity() const { return bytes_.room() + ahead_.room(); }

 private:
  // Reads the file into `bytes` from `held` on, until it is full or the
  // file ends; false where the read failed.
  bool readInto(WindowBytes& bytes, std::size_t& held) {
    while (!atEnd_ && held < bytes.size()) {
      ssize_t n = ::read(fd_, bytes.data() + held, bytes.size() - held);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) return false;
      if (n == 0) atEnd_ = true;
      held += static_cast<std::size_t>(n);
      total_ += static_cast<std::uint64_t>(n);
    }
    return true;
  }

  int fd_;
  std::size_t window_;
  WindowBytes bytes_;
  std::size_t held_ = 0;
  std::uint64_t total_ = 0;
  bool atEnd_ = false;
  bool failed_ = false;
  // The next window's buffer, while readAhead's thread fills it.
  WindowBytes ahead_;
  std::size_t aheadHeld_ = 0;
  bool readingAhead_ = false;
  bool aheadRead_ = true;
  std::thread reader_;
};

// What the windows read so far made of the file.
struct StreamedScene {
  std::uint64_t fileBytes = 0;
  // Whether to keep headerText: the first window's lines up to its last
  // CAMERA or LIGHT record's, what the quotes of the whole-file checks
  // (finishStream) may show. A copy of the whole first window cost 10 ms
  // at 1,000,000 objects, a quarter of the time before the first parse.
  bool keepHeaderText = false;
  std::string headerText;
  const ObjectCountEstimate* estimate = nullptr;
  Scene header;
  std::uint64_t handed = 0;
  std::size_t objectsSeen = 0;
  std::uint32_t nextLine = 1;
  StreamReadMemory memory;
};

// The first `count` lines of `text`, each with its line break.
std::string_view leadingLines(std::string_view text, std::uint32_t count) {
  std::size_t end = 0;
  for (std::uint32_t line = 0; line < count && end < text.size(); ++line) {
    std::size_t newline = text.find('\n', end);
    end = newline == std::string_view::npos ? text.size() : newline + 1;
  }
  return text.substr(0, end);
}

// One window: read, checked and handed over; false where it sends the file
// to the whole-file reader.
bool readWindow(std::string_view text, const ReadOptions& options, unsigned threads,
                SceneFileWindowRead& read, StreamedScene& done, const ObjectBatchSink& sink) {
  SceneFileWindow window{text, done.nextLine, done.nextLine == 1, done.objectsSeen};
  // Its objects are checked finite there (parseScene's last check).
  if (!parseSceneFileWindow(window, options, threads, read)) return false;
  std::uint64_t model = 0;
  for (const ReadResult& part : read.parts) {
    model += part.scene.objects.capacity() * sizeof(Object);
  }
  done.memory.modelBytes = std::max(done.memory.modelBytes, model);
  if (window.first) {
    done.header.camera = read.parts.front().scene.camera;
    if (*done.estimate) {
      // A little over: room that falls short is doubled, where room to
      // spare is never touched. The floor of 1,000,000 objects was
      // estimated at 999,879.
      double perByte = static_cast<double>(read.objectsSeen) / static_cast<double>(text.size());
      (*done.estimate)(
          static_cast<std::uint64_t>(static_cast<double>(done.fileBytes) * perByte * 1.02) + 1024);
    }
  }
  for (const ReadResult& part : read.parts) {
    const Scene& scene = part.scene;
    done.header.lights.insert(done.header.lights.end(), scene.lights.begin(), scene.lights.end());
    if (!scene.objects.empty()) sink(scene.objects);
    done.handed += scene.objects.size();
  }
  if (window.first && done.keepHeaderText) {
    std::uint32_t lastLine = done.header.camera.span.line;
    for (const Light& light : done.header.lights) lastLine = std::max(lastLine, light.span.line);
    done.headerText = std::string(leadingLines(text, lastLine));
  }
  done.objectsSeen += read.objectsSeen;
  done.nextLine += read.lines;
  return true;
}

// The windows of an open scene file, into `done`; false where the file goes
// to the whole-file reader.
bool readWindows(WindowBuffer& buffer, const ReadOptions& options, unsigned threads,
                 const ObjectBatchSink& sink, StreamedScene& done) {
  SceneFileWindowRead windowRead;
  while (!buffer.empty()) {
    std::size_t end = buffer.windowEnd();
    if (end == 0) {
      buffer.grow();
    } else {
      buffer.readAhead(end);
      bool read = readWindow(buffer.text(end), options, threads, windowRead, done, sink);
      buffer.takeAhead();
      if (!read) return false;
    }
    done.memory.textBytes = std::max(done.memory.textBytes, buffer.capacity());
    if (options.stop.stop_requested()) return true;
    // A file that grew past the limit while read is the whole reader's.
    if (!buffer.fill() || buffer.total() > options.maxFileSize) return false;
  }
  return true;
}

unsigned threadCount(const ReadOptions& options) {
  unsigned threads = options.threads > 0 ? options.threads : std::thread::hardware_concurrency();
  return std::max(threads, 1u);
}

// The streamed file's result: its header's whole-file checks (as
// SceneFileParser::finish and parseScene's last check make them), the
// quotes taken from its first window's header (StreamedScene::headerText).
StreamReadResult finishStream(StreamedScene done, const std::filesystem::path& path,
                              const ReadOptions& options, SourceExcerpts* quotes) {
  StreamReadResult result;
  result.format = Format::SceneFile;
  result.objectCount = done.handed;
  result.memory = done.memory;
  result.read =
      ReadResult{std::move(done.header), DiagnosticList(path.string(), options.errorLimit)};
  if (!options.stop.stop_requested()) {
    checkSceneLevel(result.read.scene, result.read.diagnostics);
    checkFramingFinite(result.read.scene, result.read.diagnostics);
  }
  if (quotes) quotes->capture(path.string(), done.headerText, result.read.diagnostics);
  return result;
}

}  // namespace

StreamReadResult streamSceneFile(const std::filesystem::path& path, const ReadOptions& options,
                                 const ObjectBatchSink& sink, SourceExcerpts* quotes,
                                 const ObjectCountEstimate& estimate) {
  const unsigned threads = threadCount(options);
  const std::size_t window = std::max<std::size_t>(options.sceneFile.windowBytes, 1) * threads;
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode) ||
      static_cast<std::uint64_t>(info.st_size) <= window ||
      static_cast<std::uint64_t>(info.st_size) > options.maxFileSize) {
    return readWhole(path, options, sink, quotes, estimate, 0, {});
  }
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return readWhole(path, options, sink, quotes, estimate, 0, {});
  bool streamed = false;
  StreamedScene done;
  done.keepHeaderText = quotes != nullptr;
  done.fileBytes = static_cast<std::uint64_t>(info.st_size);
  done.estimate = &estimate;
  {
    // Closed on every way out, a sink's exception included, after the
    // buffer's reading thread has stopped (locals go in reverse order).
    struct ClosedAtEnd {
      int fd;
      ~ClosedAtEnd() { ::close(fd); }
    } file{fd};
    WindowBuffer buffer(file.fd, window);
    if (buffer.fill() && detectFormat(buffer.held(), path.string()) == Format::SceneFile) {
      streamed = readWindows(buffer, options, threads, sink, done);
    }
  }
  if (!streamed) return readWhole(path, options, sink, quotes, estimate, done.handed, done.memory);
  return finishStream(std::move(done), path, options, quotes);
}

}  // namespace scene
