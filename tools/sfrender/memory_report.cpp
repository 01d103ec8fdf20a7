#include "tools/sfrender/memory_report.h"

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>

namespace tools {

namespace {

std::string figure(std::uint64_t bytes, std::uint64_t objects) {
  char text[64];
  std::snprintf(
      text, sizeof text, "%.1f MB (%.0f B/object)", static_cast<double>(bytes) / 1e6,
      static_cast<double>(bytes) / static_cast<double>(std::max<std::uint64_t>(objects, 1)));
  return text;
}

}  // namespace

std::string memoryReportText(std::span<const StageMemory> stages, std::uint64_t peakBytes,
                             std::uint64_t objects) {
  std::string text = "held at most:";
  for (std::size_t i = 0; i < stages.size(); ++i) {
    text += (i == 0 ? " " : ", ") + std::string(stages[i].stage) + " " +
            figure(stages[i].bytes, objects);
  }
  return text + "; peak resident " + figure(peakBytes, objects);
}

std::uint64_t peakResidentBytes() {
  struct rusage usage {};
  if (::getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return static_cast<std::uint64_t>(usage.ru_maxrss) * 1024;  // kilobytes on Linux
}

}  // namespace tools
