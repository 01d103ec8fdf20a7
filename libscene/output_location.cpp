#include "libscene/output_location.h"

#include <algorithm>
#include <system_error>

namespace scene {

bool outputStaysInFolder(const std::filesystem::path& folder, const std::string& name) {
  namespace fs = std::filesystem;
  fs::path relative(name);
  if (relative.empty() || relative.is_absolute() || relative.has_root_name()) return false;
  // Textually: no component may climb above the folder.
  int depth = 0;
  for (const fs::path& part : relative) {
    if (part == "..") {
      if (--depth < 0) return false;
    } else if (part != "." && !part.empty()) {
      ++depth;
    }
  }
  // Through links: resolve the path as a write would and compare.
  std::error_code ec;
  fs::path base = fs::weakly_canonical(folder.empty() ? fs::path(".") : folder, ec);
  if (ec) return false;
  std::optional<fs::path> target = followLinks(base / relative);
  if (!target) return false;
  auto [baseEnd, targetIt] =
      std::mismatch(base.begin(), base.end(), target->begin(), target->end());
  return baseEnd == base.end();
}

std::optional<std::filesystem::path> followLinks(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  // weakly_canonical resolves every link that leads somewhere, but takes a
  // link to nothing for a plain name, so the last one is followed by hand.
  constexpr int kMaxLinks = 40;  // Linux's own limit on a chain of links
  std::error_code ec;
  fs::path current = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) return std::nullopt;
  for (int hops = 0; fs::is_symlink(fs::symlink_status(current, ec)); ++hops) {
    if (hops == kMaxLinks) return std::nullopt;
    fs::path next = fs::read_symlink(current, ec);
    if (ec) return std::nullopt;
    current = fs::weakly_canonical(current.parent_path() / next, ec);
    if (ec) return std::nullopt;
  }
  return current;
}

void checkOutputLocation(const Scene& scene, const std::filesystem::path& folder,
                         Severity severity, DiagnosticList& out) {
  if (!scene.outputFile || outputStaysInFolder(folder, *scene.outputFile)) return;
  out.report(severity, DiagnosticCode::OutputFileEscapes, scene.outputFileSpan,
             "OUTPUT_FILE '" + *scene.outputFile + "' leaves the instruction file's folder")
      .hint = "sfrender writes there only when the output is named with -o";
}

}  // namespace scene
