#include "tools/sfcheck/sfcheck.h"

#include <filesystem>
#include <string>
#include <vector>

#include "libscene/output_location.h"
#include "libscene/scene_reader.h"
#include "tools/common/command_line.h"
#include "tools/common/diagnostic_printer.h"
#include "tools/common/file_io.h"

namespace tools {

namespace {

std::string formatName(scene::SceneFormat format) {
  switch (format) {
    case scene::SceneFormat::SceneFile:
      return "scene-file";
    case scene::SceneFormat::InstructionFile:
      return "instruction-file";
    case scene::SceneFormat::Gltf:
      return "gltf";
    case scene::SceneFormat::Glb:
      return "glb";
    case scene::SceneFormat::Pov:
      return "pov";
    case scene::SceneFormat::Unknown:
      break;
  }
  return "unknown";
}

std::string count(std::size_t n, const char* word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

}  // namespace

int runSfcheck(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{
      "Checks scene files, instruction files and POV-Ray scenes (the subset sfconvert reads) and "
      "reports every problem",
      "sfcheck"};
  app.set_version_flag("--version", SCENEFILE_VERSION);
  std::vector<std::string> files;
  bool werror = false;
  std::string format = "text";
  app.add_option("files", files,
                 "scene files (.sf), instruction files or POV-Ray scenes (.pov) to check")
      ->required();
  app.add_flag("--werror", werror, "treat warnings as errors");
  app.add_option("--format", format, "how to print diagnostics")
      ->check(CLI::IsMember({"text", "json"}));
  if (auto stop = parseCommandLine(app, argc, argv, out, err)) return toInt(*stop);

  bool json = format == "json";
  nlohmann::json report = {{"files", nlohmann::json::array()}};
  std::size_t errors = 0;
  std::size_t warnings = 0;
  bool unreadable = false;
  for (const std::string& file : files) {
    std::string readError;
    std::optional<std::string> text = readWholeFile(file, readError);
    if (!text) {
      unreadable = true;
      if (json) {
        report["files"].push_back({{"file", file}, {"readError", readError}});
      } else {
        err << file << ": error: cannot read the file: " << readError << "\n";
      }
      continue;
    }
    scene::SceneFormat detected = scene::detectFormat(*text, file);
    scene::ReadResult result = scene::parseScene(*text, file);
    if (detected == scene::SceneFormat::InstructionFile) {
      scene::checkOutputLocation(result.scene, std::filesystem::path(file).parent_path(),
                                 scene::Severity::Warning, result.diagnostics);
    }
    errors += result.diagnostics.errorCount();
    warnings += result.diagnostics.warningCount();
    if (json) {
      report["files"].push_back({{"file", file},
                                 {"format", formatName(detected)},
                                 {"diagnostics", diagnosticsToJson(result.diagnostics, werror)}});
    } else {
      printDiagnostics(result.diagnostics, err, werror);
    }
  }
  if (werror) {
    errors += warnings;
    warnings = 0;
  }
  if (json) {
    report["summary"] = {{"files", files.size()}, {"errors", errors}, {"warnings", warnings}};
    out << report.dump(2) << "\n";
  } else {
    err << "sfcheck: " << count(files.size(), "file") << " checked, " << count(errors, "error")
        << ", " << count(warnings, "warning") << "\n";
  }
  if (unreadable) return toInt(ExitCode::IoError);
  return toInt(errors ? ExitCode::InvalidInput : ExitCode::Success);
}

}  // namespace tools
