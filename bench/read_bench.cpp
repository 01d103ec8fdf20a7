// read_bench: how fast scene::parseSceneFile reads (and validates) a scene
// file held in memory, and how much memory one parse needs.
//
// The file is read into a std::string first; only parseSceneFile is timed,
// on this one thread, and the result is destroyed after the clock stops.
// With --once the process parses once and reports its peak resident memory,
// so that the figure belongs to a single parse in a fresh process: the file
// buffer, the scene, and whatever the parser holds while it runs.
//
// Output is one "key: value" line per figure, for people and for run.sh.
// MB means 10^6 bytes throughout.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "scenefile/read.h"
#include "scenefile/scene.h"
#include "libscene/formats/sf/sf_reader.h"

namespace {

constexpr double kMB = 1e6;

// A field of /proc/self/status in bytes ("VmHWM", "VmRSS"), if present.
std::optional<std::uint64_t> procStatusBytes(const std::string& field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.starts_with(field + ":")) {
      return std::strtoull(line.c_str() + field.size() + 1, nullptr, 10) * 1024;
    }
  }
  return std::nullopt;
}

std::uint64_t maxRssBytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<std::uint64_t>(usage.ru_maxrss) * 1024;  // kB on Linux
}

bool readFile(const std::string& path, std::string& content, std::string& error) {
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    error = std::strerror(errno);
    return false;
  }
  struct stat info {};
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    error = "not a regular file";
    ::close(fd);
    return false;
  }
  content.resize(static_cast<std::size_t>(info.st_size));
  std::size_t done = 0;
  while (done < content.size()) {
    ssize_t n = ::read(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error = n < 0 ? std::strerror(errno) : "the file shrank while being read";
      ::close(fd);
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  ::close(fd);
  return true;
}

// The bytes the scene model occupies: the Scene itself, one Object per
// object and one Light per light (their sizeof, which holds the matrix,
// colour, material and span inline), plus the heap blocks those own (an
// instruction file's transform lists, a long OUTPUT_FILE name). `used` counts
// the elements (size()), the other figure the vectors' capacity().
struct ModelSize {
  std::uint64_t used = 0;
  std::uint64_t allocated = 0;
};

ModelSize modelSize(const scene::Scene& s) {
  ModelSize m;
  m.used = sizeof(scene::Scene) + sizeof(scene::Object) * s.objects.size() +
           sizeof(scene::Light) * s.lights.size();
  m.allocated = sizeof(scene::Scene) + sizeof(scene::Object) * s.objects.capacity() +
                sizeof(scene::Light) * s.lights.capacity();
  for (const scene::Object& object : s.objects) {
    if (object.transforms) {
      m.used += sizeof(scene::TransformOp) * object.transforms->size();
      m.allocated += sizeof(scene::TransformOp) * object.transforms->capacity();
    }
  }
  if (s.outputFile && s.outputFile->capacity() > std::string().capacity()) {
    m.used += s.outputFile->size() + 1;
    m.allocated += s.outputFile->capacity() + 1;
  }
  return m;
}

// Prints the first diagnostics of a result that is not clean.
void printDiagnostics(const scene::ReadResult& result) {
  int shown = 0;
  for (const scene::Diagnostic& d : result.diagnostics.items()) {
    if (++shown > 5) break;
    std::cerr << result.diagnostics.file() << ':' << d.span.line << ':' << d.span.column << ": "
              << scene::severityName(d.severity) << ": " << d.message << " ["
              << scene::codeName(d.code) << "]\n";
  }
}

template <typename T>
void print(const char* key, const T& value) {
  std::cout << key << ": " << value << '\n';
}

void printFixed(const char* key, double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  print(key, buffer);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Times scene::parseSceneFile on a scene file held in memory."};
  std::string path;
  int runs = 5;
  bool once = false;
  app.add_option("file", path, "the .sf file to read")->required();
  app.add_option("-r,--runs", runs, "how many timed parses (median, min and max are reported)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  app.add_flag("--once", once,
               "parse once and report the peak memory of this process (run it in a fresh "
               "process for a figure that belongs to one parse)");
  CLI11_PARSE(app, argc, argv);
  if (once) runs = 1;

  std::uint64_t rssAtStart = procStatusBytes("VmRSS").value_or(0);
  std::string text;
  std::string error;
  if (!readFile(path, text, error)) {
    std::cerr << "read_bench: cannot read " << path << ": " << error << '\n';
    return 1;
  }
  std::uint64_t rssWithFile = procStatusBytes("VmRSS").value_or(0);

  std::vector<double> seconds;
  std::size_t objects = 0;
  std::size_t lights = 0;
  ModelSize model;
  std::uint64_t rssWithScene = 0;
  for (int run = 0; run < runs; ++run) {
    auto start = std::chrono::steady_clock::now();
    scene::ReadResult result = scene::parseSceneFile(text, path);
    auto stop = std::chrono::steady_clock::now();
    seconds.push_back(std::chrono::duration<double>(stop - start).count());
    if (!result.ok() || !result.diagnostics.empty()) {
      std::cerr << "read_bench: " << path << " is not a clean scene file ("
                << result.diagnostics.errorCount() << " errors, "
                << result.diagnostics.warningCount() << " warnings); the benchmark needs one\n";
      printDiagnostics(result);
      return 1;
    }
    objects = result.scene.objects.size();
    lights = result.scene.lights.size();
    model = modelSize(result.scene);
    if (run == 0) rssWithScene = procStatusBytes("VmRSS").value_or(0);
  }

  std::vector<double> sorted = seconds;
  std::sort(sorted.begin(), sorted.end());
  // The median of an even count is the mean of the two middle values.
  double median = sorted.size() % 2
                      ? sorted[sorted.size() / 2]
                      : (sorted[sorted.size() / 2 - 1] + sorted[sorted.size() / 2]) / 2;
  double fileMB = static_cast<double>(text.size()) / kMB;

  print("file", path);
  print("file_bytes", text.size());
  print("objects", objects);
  print("lights", lights);
  print("sizeof_object_bytes", sizeof(scene::Object));
  print("sizeof_light_bytes", sizeof(scene::Light));
  print("model_bytes", model.used);
  print("model_allocated_bytes", model.allocated);
  print("runs", runs);
  printFixed("median_s", median, 4);
  printFixed("min_s", sorted.front(), 4);
  printFixed("max_s", sorted.back(), 4);
  printFixed("median_mb_per_s", fileMB / median, 1);
  if (once) {
    // The kernel updates VmHWM (and ru_maxrss, which is the same counter)
    // from per-thread RSS counts that it folds in now and then, so it can lag
    // a VmRSS sampled a moment before by a few pages: the peak is the largest
    // of the three.
    std::uint64_t hwm = procStatusBytes("VmHWM").value_or(0);
    std::uint64_t maxRss = maxRssBytes();
    std::uint64_t peak = std::max({hwm, maxRss, rssWithFile, rssWithScene});
    print("rss_at_start_bytes", rssAtStart);
    print("rss_with_file_bytes", rssWithFile);
    print("rss_with_scene_bytes", rssWithScene);
    print("vm_hwm_bytes", hwm);
    print("ru_maxrss_bytes", maxRss);
    print("peak_rss_bytes", peak);
    printFixed("peak_over_model", static_cast<double>(peak) / static_cast<double>(model.used), 2);
  }
  return 0;
}
