#include "tools/sfcheck/sfcheck.h"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "scenefile/read.h"
#include "tools/common/diagnostic_printer.h"
#include "tools/common/document_check.h"
#include "tools/common/input_limits.h"
#include "tools/common/option_checks.h"
#include "tools/common/resource_guard.h"
#include "tools/common/standard_streams.h"
#include "tools/common/tool_output.h"

namespace tools {

namespace {

// The names of sfcheck's JSON report, which predate the registry's --to
// names and are kept, since scripts read them.
std::string formatName(std::optional<scene::Format> detected) {
  if (!detected) return "unknown";
  switch (*detected) {
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

// What the checks of all files add up to.
struct Tally {
  std::size_t errors = 0;
  std::size_t warnings = 0;
  // A file that cannot be read is a failed check, counted as an error: a
  // summary of "0 errors" must mean that every file was read and is valid.
  std::size_t unreadable = 0;
};

class Checker {
 public:
  Checker(const SfcheckOptions& options, ToolOutput& output, Stage& stage)
      : options_(options),
        output_(output),
        stage_(stage),
        format_(diagnosticFormatFromName(options.format).value_or(DiagnosticFormat::Text)) {}

  void check(const std::string& file);
  int finish();

 private:
  void report(const std::string& shown, std::optional<scene::Format> detected,
              const scene::DiagnosticList& diagnostics, const SourceExcerpts* sources);

  const SfcheckOptions& options_;
  ToolOutput& output_;
  Stage& stage_;
  DiagnosticFormat format_;
  Tally tally_;
  nlohmann::json report_ = {{"files", nlohmann::json::array()}};
};

// Every file's entry in the JSON report has the same keys, whatever
// happened to it: file, format and diagnostics; an unreadable file also
// has readError.
void Checker::report(const std::string& shown, std::optional<scene::Format> detected,
                     const scene::DiagnosticList& diagnostics, const SourceExcerpts* sources) {
  tally_.errors += diagnostics.errorCount();
  tally_.warnings += diagnostics.warningCount();
  if (format_ == DiagnosticFormat::Json) {
    report_["files"].push_back({{"file", printableText(shown)},
                                {"format", formatName(detected)},
                                {"diagnostics", diagnosticsToJson(diagnostics, options_.werror)}});
    return;
  }
  DiagnosticPrinter(output_.err(), output_.diagnosticStyle(format_, options_.werror), sources)
      .print(diagnostics);
}

void Checker::check(const std::string& file) {
  std::string shown = inputDisplayName(file);
  stage_.set("reading " + printableText(shown));
  InputText input = readInputText(file, options_.read, &output_.streams().in);
  if (input.tooLarge()) {
    report(shown, std::nullopt, input.refused, nullptr);
    return;
  }
  if (!input.text) {
    ++tally_.unreadable;
    ++tally_.errors;
    if (format_ == DiagnosticFormat::Json) {
      report_["files"].push_back({{"file", printableText(shown)},
                                  {"format", formatName(std::nullopt)},
                                  {"diagnostics", nlohmann::json::array()},
                                  {"readError", printableText(input.readError)}});
    } else {
      output_.fileError(shown, "cannot read the file: " + printableText(input.readError));
    }
    return;
  }
  const std::string& text = *input.text;
  stage_.set("checking " + printableText(shown));
  // Standard input's OUTPUT_FILE is taken in the current folder.
  std::filesystem::path folder =
      isStandardStream(file) ? std::filesystem::path() : std::filesystem::path(file).parent_path();
  DocumentCheck checked = checkDocument(text, shown, folder, options_.read);
  const std::optional<scene::Format>& detected = checked.format;
  scene::ReadResult& result = checked.result;
  if (detected) {
    output_.detail(printableText(shown) + ": " + formatName(detected) + ", " +
                   sceneContents(result.scene));
  }
  SourceExcerpts sources;
  if (format_ == DiagnosticFormat::Text) sources.capture(shown, text, result.diagnostics);
  report(shown, detected, result.diagnostics, &sources);
}

int Checker::finish() {
  if (options_.werror) {
    tally_.errors += tally_.warnings;
    tally_.warnings = 0;
  }
  stage_.set("writing the report");
  if (format_ == DiagnosticFormat::Json) {
    report_["summary"] = {{"files", options_.files.size()},
                          {"errors", tally_.errors},
                          {"warnings", tally_.warnings},
                          {"unreadable", tally_.unreadable}};
    output_.streams().out << report_.dump(2) << "\n";
    if (!flushStandardOutput("sfcheck", output_.streams().out, output_.err())) {
      return toInt(ExitCode::IoError);
    }
  } else {
    std::string summary = countOf(options_.files.size(), "file") + " checked, " +
                          countOf(tally_.errors, "error") + ", " +
                          countOf(tally_.warnings, "warning");
    if (tally_.unreadable)
      summary += " (" + countOf(tally_.unreadable, "file") + " could not be read)";
    output_.info(summary);
  }
  if (tally_.unreadable) return toInt(ExitCode::IoError);
  return toInt(tally_.errors ? ExitCode::InvalidInput : ExitCode::Success);
}

int checkFiles(int argc, const char* const* argv, const ToolStreams& streams, Stage& stage) {
  SfcheckOptions options;
  std::unique_ptr<CLI::App> app = makeSfcheckCommandLine(options);
  if (auto stop = parseCommandLine(*app, argc, argv, streams.out, streams.err)) {
    return toInt(*stop);
  }
  ToolOutput output("sfcheck", streams, options.common);
  Checker checker(options, output, stage);
  for (const std::string& file : options.files) checker.check(file);
  return checker.finish();
}

}  // namespace

std::unique_ptr<CLI::App> makeSfcheckCommandLine(SfcheckOptions& options) {
  std::unique_ptr<CLI::App> app =
      makeToolApp("sfcheck", "Checks " + scene::describeFormats() + " and reports every problem",
                  options.common);
  app->add_option("files", options.files,
                  "the files to check, in any of the formats above (recognised from their "
                  "content); - reads standard input")
      ->required();
  app->add_flag("--werror", options.werror, "treat warnings as errors");
  app->add_option("--format", options.format,
                  "how to print diagnostics: text (quoting the source), short (a line each) or "
                  "json (on standard output)")
      ->option_text("FORMAT")
      ->check(oneOf({"text", "short", "json"}));
  addReadLimitOptions(*app, options.read);
  return app;
}

int runSfcheck(int argc, const char* const* argv, const ToolStreams& streams) {
  Stage stage;
  return runGuarded("sfcheck", streams.err, stage,
                    [&] { return checkFiles(argc, argv, streams, stage); });
}

}  // namespace tools
