#include "libscene/output_location.h"

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
  // Through links: resolve what exists of the path and compare.
  std::error_code ec;
  fs::path base = fs::weakly_canonical(folder.empty() ? fs::path(".") : folder, ec);
  if (ec) return false;
  fs::path target = fs::weakly_canonical(base / relative, ec);
  if (ec) return false;
  auto [baseEnd, targetIt] = std::mismatch(base.begin(), base.end(), target.begin(), target.end());
  return baseEnd == base.end();
}

void checkOutputLocation(const Scene& scene, const std::filesystem::path& folder,
                         Severity severity, DiagnosticList& out) {
  if (!scene.outputFile || outputStaysInFolder(folder, *scene.outputFile)) return;
  out.report(severity, DiagnosticCode::OutputFileEscapes, scene.outputFileSpan,
             "OUTPUT_FILE '" + *scene.outputFile + "' leaves the instruction file's folder")
      .hint = "sfrender writes there only when the output is named with -o";
}

}  // namespace scene
