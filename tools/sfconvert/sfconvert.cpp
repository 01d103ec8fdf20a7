#include "tools/sfconvert/sfconvert.h"

#include <filesystem>
#include <map>
#include <string>

#include "libscene/conversion.h"
#include "libscene/scene_reader.h"
#include "tools/common/command_line.h"
#include "tools/common/diagnostic_printer.h"
#include "tools/common/file_io.h"

namespace tools {

namespace {

const std::map<std::string, scene::OutputFormat> kFormatNames = {
    {"sf", scene::OutputFormat::SceneFile},
    {"instructions", scene::OutputFormat::InstructionFile},
};

// The output format from the file's extension: .sf, or .txt for an
// instruction file (the manual's own example is instructions.txt).
std::optional<scene::OutputFormat> formatFromExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  if (ext == ".sf") return scene::OutputFormat::SceneFile;
  if (ext == ".txt") return scene::OutputFormat::InstructionFile;
  return std::nullopt;
}

void printAll(const scene::DiagnosticList& list, bool json, std::ostream& err) {
  if (json) {
    err << diagnosticsToJson(list).dump(2) << "\n";
  } else {
    printDiagnostics(list, err);
  }
}

}  // namespace

int runSfconvert(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{"Converts between scene files (.sf) and instruction files", "sfconvert"};
  app.set_version_flag("--version", SCENEFILE_VERSION);
  std::string input;
  std::string output;
  std::string to;
  std::string format = "text";
  bool noLoss = false;
  bool approximate = false;
  bool transpose = false;
  app.add_option("input", input, "the scene to read (format recognised from its content)")
      ->required();
  app.add_option("output", output, "the file to write, or - for standard output")->required();
  app.add_option("--to", to, "output format, instead of the output's extension")
      ->check(CLI::IsMember({"sf", "instructions"}));
  app.add_flag("--no-loss", noLoss, "fail instead of dropping anything the output cannot hold");
  app.add_flag("--approximate", approximate,
               "write the nearest expressible matrix or camera and report how far it moved");
  app.add_flag("--transpose-matrices", transpose,
               "read each scene-file matrix column by column (repairs files written transposed)");
  app.add_option("--format", format, "how to print diagnostics (on standard error)")
      ->check(CLI::IsMember({"text", "json"}));
  if (auto stop = parseCommandLine(app, argc, argv, out, err)) return toInt(*stop);
  bool json = format == "json";
  bool toStdout = output == "-";

  // Work out the output format before reading anything.
  std::optional<scene::OutputFormat> outputFormat;
  if (!to.empty()) {
    outputFormat = kFormatNames.at(to);
  } else if (!toStdout) {
    outputFormat = formatFromExtension(output);
  }
  if (!outputFormat) {
    err << "sfconvert: cannot tell the output format of '" << output
        << "': use .sf or .txt (instruction file), or --to sf|instructions\n";
    return toInt(ExitCode::Usage);
  }
  if (!toStdout && isSameFile(input, output)) {
    err << "sfconvert: error: the output '" << output
        << "' is the input file; sfconvert never writes over its input\n";
    return toInt(ExitCode::InvalidInput);
  }

  std::string readError;
  std::optional<std::string> text = readWholeFile(input, readError);
  if (!text) {
    err << input << ": error: cannot read the file: " << readError << "\n";
    return toInt(ExitCode::IoError);
  }
  scene::ReadOptions readOptions;
  readOptions.transposedMatrices = transpose;
  scene::ReadResult result = scene::parseScene(*text, input, readOptions);
  if (!result.ok()) {
    printAll(result.diagnostics, json, err);
    return toInt(ExitCode::InvalidInput);
  }

  scene::ConversionOptions options;
  options.noLoss = noLoss;
  options.approximate = approximate;
  if (!toStdout) {
    options.outputFile = std::filesystem::path(output).stem().string() + ".ppm";
  }
  std::optional<std::string> converted =
      scene::convertScene(result.scene, *outputFormat, options, result.diagnostics);
  printAll(result.diagnostics, json, err);
  if (!converted) return toInt(ExitCode::InvalidInput);

  if (toStdout) {
    out << *converted;
    out.flush();
    return toInt(out ? ExitCode::Success : ExitCode::IoError);
  }
  std::string writeError;
  if (!writeFileAtomically(output, *converted, writeError)) {
    err << output << ": error: cannot write the file: " << writeError << "\n";
    return toInt(ExitCode::IoError);
  }
  return toInt(ExitCode::Success);
}

}  // namespace tools
