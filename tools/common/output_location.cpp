#include "tools/common/output_location.h"

#include <algorithm>
#include <system_error>

namespace scene {

namespace {

namespace fs = std::filesystem;

bool isWithin(const fs::path& base, const fs::path& path) {
  auto [baseEnd, pathIt] = std::mismatch(base.begin(), base.end(), path.begin(), path.end());
  return baseEnd == base.end();
}

// `path` with its folder's links resolved and its last component kept as
// it is, or nothing (with the error) when the folder cannot be resolved.
std::optional<fs::path> resolveFolder(const fs::path& path, std::error_code& ec) {
  fs::path normal = path.lexically_normal();
  if (!normal.has_filename()) {
    fs::path whole = fs::weakly_canonical(normal, ec);
    return ec ? std::nullopt : std::optional<fs::path>(whole);
  }
  fs::path folder = fs::weakly_canonical(normal.parent_path(), ec);
  if (ec) return std::nullopt;
  return folder / normal.filename();
}

// followLinks(), and whether a failure was a loop (ELOOP, or more than 40
// links) rather than a link that could not be read. Each link of the last
// component is followed by hand, one hop at a time, so that `visited`
// holds every place on the way; weakly_canonical resolves the folders
// (a link to nothing would be taken for a plain name by it).
std::optional<fs::path> followLinkChain(const fs::path& path, std::vector<fs::path>* visited,
                                        bool& loop) {
  constexpr int kMaxLinks = 40;  // Linux's own limit on a chain of links
  std::error_code ec;
  fs::path next = fs::absolute(path, ec);
  for (int hops = 0;; ++hops) {
    std::optional<fs::path> current = resolveFolder(next, ec);
    if (!current) {
      // A loop among the folders: the place it names is the path as given.
      loop = ec == std::errc::too_many_symbolic_link_levels;
      if (visited && loop) visited->push_back(next.lexically_normal());
      return std::nullopt;
    }
    if (visited) visited->push_back(*current);
    if (!fs::is_symlink(fs::symlink_status(*current, ec))) return current;
    if (hops == kMaxLinks) {
      loop = true;
      return std::nullopt;
    }
    fs::path link = fs::read_symlink(*current, ec);
    if (ec) return std::nullopt;
    next = link.is_absolute() ? link : current->parent_path() / link;
  }
}

}  // namespace

OutputPlace outputPlace(const std::filesystem::path& folder, const std::string& name) {
  fs::path relative(name);
  if (relative.empty() || relative.is_absolute() || relative.has_root_name()) {
    return OutputPlace::Outside;
  }
  // Textually: no component may climb above the folder.
  int depth = 0;
  for (const fs::path& part : relative) {
    if (part == "..") {
      if (--depth < 0) return OutputPlace::Outside;
    } else if (part != "." && !part.empty()) {
      ++depth;
    }
  }
  // Through links: resolve the path as a write would, and look at every
  // place on the way. A chain that never ends is a loop only when all of it
  // lies inside; one step out is leaving, wherever the chain goes next.
  std::error_code ec;
  fs::path base = fs::weakly_canonical(folder.empty() ? fs::path(".") : folder, ec);
  if (ec) return OutputPlace::Outside;
  std::vector<fs::path> visited;
  bool loop = false;
  std::optional<fs::path> target = followLinkChain(base / relative, &visited, loop);
  for (const fs::path& place : visited) {
    if (!isWithin(base, place)) return OutputPlace::Outside;
  }
  if (!target) return loop ? OutputPlace::LinkLoop : OutputPlace::Outside;
  return OutputPlace::Inside;
}

std::optional<std::filesystem::path> followLinks(const std::filesystem::path& path,
                                                 std::vector<std::filesystem::path>* visited) {
  bool loop = false;
  return followLinkChain(path, visited, loop);
}

void checkOutputLocation(const Scene& scene, const std::filesystem::path& folder, Severity severity,
                         DiagnosticList& out) {
  if (!scene.outputFile) return;
  OutputPlace place = outputPlace(folder, *scene.outputFile);
  if (place == OutputPlace::Inside) return;
  if (place == OutputPlace::LinkLoop) {
    out.report(severity, DiagnosticCode::OutputFileLinkLoop, scene.outputFileSpan,
               "OUTPUT_FILE '" + *scene.outputFile +
                   "' leads into a loop of symbolic links (or a chain of more than 40)")
        .hint = "nothing can be written there until a link of the loop is replaced";
    return;
  }
  out.report(severity, DiagnosticCode::OutputFileEscapes, scene.outputFileSpan,
             "OUTPUT_FILE '" + *scene.outputFile + "' leaves the instruction file's folder")
      .hint = "sfrender writes there only when the output is named with -o";
}

}  // namespace scene
