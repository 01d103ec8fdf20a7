#include "tools/sfcheck/sfcheck.h"

#include <filesystem>
#include <string>
#include <vector>

#include "tools/common/output_location.h"
#include "scenefile/read.h"
#include "tools/common/command_line.h"
#include "tools/common/diagnostic_printer.h"
#include "tools/common/input_limits.h"
#include "tools/common/output_file_format.h"
#include "tools/common/resource_guard.h"
#include "tools/common/standard_streams.h"

namespace tools {

namespace {

// The names of sfcheck's JSON report, which predate the registry's --to
// names and are kept, since scripts read them.
std::string formatName(std::optional<scene::Format> detected) {
  if (!detected) return "unknown";
  scene::Format format = *detected;
  switch (format) {
    case scene::Format::SceneFile:
      return "scene-file";
    case scene::Format::InstructionFile:
      return "instruction-file";
    case scene::Format::Gltf:
      return "gltf";
    case scene::Format::Glb:
      return "glb";
    case scene::Format::Pov:
      return "pov";
  }
  return "unknown";
}

std::string count(std::size_t n, const char* word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

int checkFiles(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
               Stage& stage) {
  CLI::App app{"Checks " + scene::describeFormats() + " and reports every problem", "sfcheck"};
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
  scene::ReadOptions readOptions;
  addReadLimitOptions(app, readOptions);
  if (auto stop = parseCommandLine(app, argc, argv, out, err)) return toInt(*stop);

  bool json = format == "json";
  nlohmann::json report = {{"files", nlohmann::json::array()}};
  std::size_t errors = 0;
  std::size_t warnings = 0;
  // A file that cannot be read is a failed check, counted as an error: a
  // summary of "0 errors" must mean that every file was read and is valid.
  std::size_t unreadable = 0;
  for (const std::string& file : files) {
    stage.set("reading " + printableText(file));
    InputText input = readInputText(file, readOptions);
    if (input.tooLarge()) {
      errors += input.refused.errorCount();
      if (json) {
        report["files"].push_back({{"file", printableText(file)},
                                   {"diagnostics", diagnosticsToJson(input.refused, werror)}});
      } else {
        printDiagnostics(input.refused, err, werror);
      }
      continue;
    }
    if (!input.text) {
      ++unreadable;
      ++errors;
      if (json) {
        report["files"].push_back(
            {{"file", printableText(file)}, {"readError", printableText(input.readError)}});
      } else {
        err << printableText(file) << ": error: cannot read the file: "
            << printableText(input.readError) << "\n";
      }
      continue;
    }
    const std::string& text = *input.text;
    stage.set("checking " + printableText(file));
    std::optional<scene::Format> detected = scene::detectFormat(text, file);
    scene::ReadResult result = scene::parseScene(text, file, readOptions);
    if (detected == scene::Format::InstructionFile) {
      scene::checkOutputLocation(result.scene, std::filesystem::path(file).parent_path(),
                                 scene::Severity::Warning, result.diagnostics);
    }
    // Whatever the format: sfrender writes the OUTPUT_FILE of each.
    checkOutputFileFormat(result.scene, scene::Severity::Warning, result.diagnostics);
    errors += result.diagnostics.errorCount();
    warnings += result.diagnostics.warningCount();
    if (json) {
      report["files"].push_back({{"file", printableText(file)},
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
  stage.set("writing the report");
  if (json) {
    report["summary"] = {{"files", files.size()},
                         {"errors", errors},
                         {"warnings", warnings},
                         {"unreadable", unreadable}};
    out << report.dump(2) << "\n";
    if (!flushStandardOutput("sfcheck", out, err)) return toInt(ExitCode::IoError);
  } else {
    err << "sfcheck: " << count(files.size(), "file") << " checked, " << count(errors, "error")
        << ", " << count(warnings, "warning");
    if (unreadable) err << " (" << count(unreadable, "file") << " could not be read)";
    err << "\n";
  }
  if (unreadable) return toInt(ExitCode::IoError);
  return toInt(errors ? ExitCode::InvalidInput : ExitCode::Success);
}

}  // namespace

int runSfcheck(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  Stage stage;
  return runGuarded("sfcheck", err, stage, [&] { return checkFiles(argc, argv, out, err, stage); });
}

}  // namespace tools
