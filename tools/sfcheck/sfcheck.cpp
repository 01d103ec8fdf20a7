#include "tools/sfcheck/sfcheck.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "scenefile/read.h"
#include "tools/common/diagnostic_printer.h"
#include "tools/common/document_check.h"
#include "tools/common/document_fix.h"
#include "tools/common/file_io.h"
#include "tools/common/input_limits.h"
#include "tools/common/option_checks.h"
#include "tools/common/resource_guard.h"
#include "tools/common/standard_streams.h"
#include "tools/common/tool_output.h"
#include "tools/common/unified_diff.h"
#include "tools/sfcheck/scene_info.h"

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
    case scene::Format::Obj:
      return "obj";
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
  // Files --fix could not write, counted as errors too.
  std::size_t unwritten = 0;
  // The fix-its --fix applied (with --dry-run: would apply).
  std::size_t fixes = 0;
};

std::string fixCount(std::size_t n) {
  return std::to_string(n) + (n == 1 ? " fix" : " fixes");
}

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
  std::size_t fix(const std::string& file, const std::string& shown,
                  const std::filesystem::path& folder, std::string& text, DocumentCheck& checked);

  const SfcheckOptions& options_;
  ToolOutput& output_;
  Stage& stage_;
  DiagnosticFormat format_;
  Tally tally_;
  // What --fix adds to the file's entry in the JSON report.
  nlohmann::json fixEntry_;
  // What --info adds to it: the scene's summary, null for a file that has
  // errors or cannot be read.
  nlohmann::json infoEntry_;
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
    nlohmann::json entry = {{"file", printableText(shown)},
                            {"format", formatName(detected)},
                            {"diagnostics", diagnosticsToJson(diagnostics, options_.werror)}};
    if (options_.fix) entry.update(fixEntry_);
    if (options_.info) entry["info"] = infoEntry_;
    report_["files"].push_back(std::move(entry));
    return;
  }
  DiagnosticPrinter(output_.err(), output_.diagnosticStyle(format_, options_.werror), sources)
      .print(diagnostics);
}

// --fix: the fix-its applied to `text`, which becomes the fixed text, and
// the file written, or with --dry-run the change printed as a diff; the
// count of fix-its. Standard input's fixed text goes to standard output
// whole, fixed or not, as a filter's would.
std::size_t Checker::fix(const std::string& file, const std::string& shown,
                         const std::filesystem::path& folder, std::string& text,
                         DocumentCheck& checked) {
  stage_.set("fixing " + printableText(shown));
  FixedDocument fixed = fixDocument(text, checked, shown, folder, options_.read);
  fixEntry_ = {{options_.dryRun ? "fixable" : "fixed", fixed.applied}};
  tally_.fixes += fixed.applied;
  if (options_.dryRun) {
    std::string diff = unifiedDiff(text, fixed.text, shown);
    if (format_ == DiagnosticFormat::Json) {
      // As it is, for a script to apply; bytes that are not UTF-8 become
      // U+FFFD when the report is written.
      fixEntry_["diff"] = std::move(diff);
    } else {
      output_.streams().out << diff;
    }
    if (fixed.applied) {
      output_.info(printableText(shown) + ": " + fixCount(fixed.applied) + " to apply");
    }
    return fixed.applied;
  }
  if (isStandardStream(file)) {
    output_.streams().out << fixed.text;
  } else if (fixed.applied) {
    stage_.set("writing " + printableText(shown));
    if (MaybeFailure failure = replaceFileIfUnchanged(file, text, fixed.text)) {
      ++tally_.unwritten;
      ++tally_.errors;
      fixEntry_ = {{"fixed", 0}, {"writeError", printableText(failure->message)}};
      tally_.fixes -= fixed.applied;
      if (format_ != DiagnosticFormat::Json) {
        output_.fileError(shown, "cannot write the fixes: " + printableText(failure->message));
      }
      return 0;
    }
    output_.info("fixed " + printableText(shown) + " (" + fixCount(fixed.applied) + ")");
  }
  text = std::move(fixed.text);
  checked = std::move(fixed.check);
  return fixed.applied;
}

void Checker::check(const std::string& file) {
  std::string shown = inputDisplayName(file);
  fixEntry_ = {{options_.dryRun ? "fixable" : "fixed", 0}};
  infoEntry_ = nullptr;
  stage_.set("reading " + printableText(shown));
  InputText input = readInputText(file, options_.read, &output_.streams().in);
  if (input.tooLarge()) {
    report(shown, std::nullopt, input.diagnostics, nullptr);
    return;
  }
  if (!input.text) {
    ++tally_.unreadable;
    ++tally_.errors;
    if (format_ == DiagnosticFormat::Json) {
      nlohmann::json entry = {{"file", printableText(shown)},
                              {"format", formatName(std::nullopt)},
                              {"diagnostics", nlohmann::json::array()},
                              {"readError", printableText(input.readError)}};
      if (options_.fix) entry.update(fixEntry_);
      if (options_.info) entry["info"] = nullptr;
      report_["files"].push_back(std::move(entry));
    } else {
      output_.fileError(shown, "cannot read the file: " + printableText(input.readError));
    }
    return;
  }
  std::string& text = *input.text;
  std::uintmax_t bytes = text.size();
  stage_.set("checking " + printableText(shown));
  // Standard input's OUTPUT_FILE is taken in the current folder.
  std::filesystem::path folder =
      isStandardStream(file) ? std::filesystem::path() : std::filesystem::path(file).parent_path();
  DocumentCheck checked = checkDocument(text, shown, folder, options_.read);
  // The diagnostics reported are those left after the fixes.
  if (options_.fix) fix(file, shown, folder, text, checked);
  const std::optional<scene::Format>& detected = checked.format;
  scene::ReadResult& result = checked.result;
  if (detected) {
    output_.detail(printableText(shown) + ": " + formatName(detected) + ", " +
                   sceneContents(result.scene));
  }
  if (options_.info && detected && !result.diagnostics.hasErrors()) {
    if (format_ == DiagnosticFormat::Json) {
      infoEntry_ = sceneInfoJson(bytes, result.scene);
    } else {
      output_.streams().out << sceneInfoText(printableText(shown), *detected, bytes, result.scene);
    }
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
    if (options_.fix) {
      report_["summary"][options_.dryRun ? "fixable" : "fixed"] = tally_.fixes;
      report_["summary"]["unwritten"] = tally_.unwritten;
    }
    output_.streams().out << report_.dump(2, ' ', false, nlohmann::json::error_handler_t::replace)
                          << "\n";
    if (!flushStandardOutput("sfcheck", output_.streams().out, output_.err())) {
      return toInt(ExitCode::IoError);
    }
  } else {
    std::string summary = countOf(options_.files.size(), "file") + " checked, ";
    if (options_.fix) {
      summary += fixCount(tally_.fixes) + (options_.dryRun ? " to apply, " : " applied, ");
    }
    summary += countOf(tally_.errors, "error") + ", " + countOf(tally_.warnings, "warning");
    if (tally_.unreadable)
      summary += " (" + countOf(tally_.unreadable, "file") + " could not be read)";
    if (tally_.unwritten)
      summary += " (" + countOf(tally_.unwritten, "file") + " could not be written)";
    output_.info(summary);
  }
  if (tally_.unreadable || tally_.unwritten) return toInt(ExitCode::IoError);
  return toInt(tally_.errors ? ExitCode::InvalidInput : ExitCode::Success);
}

int checkFiles(int argc, const char* const* argv, const ToolStreams& streams, Stage& stage) {
  SfcheckOptions options;
  std::unique_ptr<CLI::App> app = makeSfcheckCommandLine(options);
  if (auto stop = parseCommandLine(*app, argc, argv, streams.out, streams.err)) {
    return toInt(*stop);
  }
  ToolOutput output("sfcheck", streams, options.common);
  if (options.fix && !options.dryRun && options.format == "json" &&
      std::find_if(options.files.begin(), options.files.end(), isStandardStream) !=
          options.files.end()) {
    output.error(
        "--fix writes standard input's fixed text to standard output, where --format "
        "json puts its report",
        "use --format text or short, or fix a file");
    return toInt(ExitCode::Usage);
  }
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
  CLI::Option* fix = app->add_flag(
      "--fix", options.fix,
      "apply every fix-it of the diagnostics, in place: each file written whole, and left as it "
      "is when it changed since it was read (exit 3); the diagnostics left are reported; - "
      "writes the fixed text to standard output");
  app->add_flag("--dry-run", options.dryRun,
                "with --fix: change no file, print the fixes as a unified diff on standard "
                "output (in the JSON report, each file's diff)")
      ->needs(fix);
  app->add_flag("--info", options.info,
                "also print what each file holds, on standard output: the format and size, the "
                "objects by kind, the lights, the camera, the box of the finite objects and the "
                "distinct materials (in the JSON report, each file's info)");
  addReadLimitOptions(*app, options.read);
  return app;
}

int runSfcheck(int argc, const char* const* argv, const ToolStreams& streams) {
  Stage stage;
  return runGuarded("sfcheck", streams.err, stage,
                    [&] { return checkFiles(argc, argv, streams, stage); });
}

}  // namespace tools
