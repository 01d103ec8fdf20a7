#include "tools/sfconvert/sfconvert.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "scenefile/convert.h"
#include "scenefile/mesh.h"
#include "scenefile/read.h"
#include "tools/common/output_location.h"
#include "tools/common/command_line.h"
#include "tools/common/diagnostic_printer.h"
#include "tools/common/file_io.h"
#include "tools/common/input_limits.h"
#include "tools/common/resource_guard.h"
#include "tools/common/standard_streams.h"

namespace tools {

namespace {

// The --to names of the format registry, for CLI11's check.
std::vector<std::string> formatNameList() {
  std::vector<std::string> names;
  for (const scene::FormatInfo& row : scene::formats()) names.emplace_back(row.name);
  return names;
}

// Every extension the registry knows, for the usage error: ".sf, .txt, ...".
std::string extensionList() {
  std::vector<std::string_view> all;
  for (const scene::FormatInfo& row : scene::formats()) {
    all.insert(all.end(), row.extensions.begin(), row.extensions.end());
  }
  std::string text;
  for (std::size_t i = 0; i < all.size(); ++i) {
    text += i == 0 ? "" : i + 1 == all.size() ? " or " : ", ";
    text += all[i];
  }
  return text;
}

void printAll(const scene::DiagnosticList& list, bool json, std::ostream& err) {
  if (json) {
    err << diagnosticsToJson(list).dump(2) << "\n";
  } else {
    printDiagnostics(list, err);
  }
}

// Whether the name is one of standard output's: written as a file, it is
// the pipe or terminal behind it, which an atomic write cannot replace.
bool namesStandardOutput(const std::string& path) {
  return path == "/dev/stdout" || path == "/dev/fd/1" || path == "/proc/self/fd/1";
}

int convert(int argc, const char* const* argv, std::ostream& out, std::ostream& err, Stage& stage) {
  CLI::App app{"Converts between " + scene::describeFormats(), "sfconvert"};
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
      ->check(CLI::IsMember(formatNameList()));
  app.add_flag("--no-loss", noLoss, "fail instead of dropping anything the output cannot hold");
  app.add_flag("--approximate", approximate,
               "write the nearest expressible matrix or camera and report how far it moved");
  app.add_flag("--transpose-matrices", transpose,
               "read each scene-file matrix column by column (repairs files written transposed)");
  std::optional<double> fov;
  int width = 0;
  int height = 0;
  bool externalBuffers = false;
  int tessellation = scene::kDefaultSegments;
  app.add_option("--fov", fov,
                 "glTF and POV-Ray: the camera's vertical field of view in degrees (sfrender's; "
                 "default: the input's, else 60)")
      ->check(CLI::Range(0.0, 180.0));
  app.add_option("--width", width,
                 "glTF and POV-Ray: the image width, for the camera's aspect ratio (POV-Ray "
                 "input: image_width)")
      ->check(CLI::PositiveNumber);
  app.add_option("--height", height,
                 "glTF and POV-Ray: the image height, for the camera's aspect ratio (POV-Ray "
                 "input: image_height)")
      ->check(CLI::PositiveNumber);
  app.add_flag("--external-buffers", externalBuffers,
               "glTF: write the buffer to NAME.bin beside NAME.gltf instead of embedding it");
  app.add_option("--tessellation", tessellation,
                 "glTF: segments around a sphere or cylinder (the sphere gets half as many rings)")
      ->check(CLI::Range(scene::kMinSegments, scene::kMaxSegments))
      ->capture_default_str();
  bool flat = false;
  bool skipUnsupported = false;
  app.add_flag("--flat", flat,
               "POV-Ray output: every object unlit in a colour of its own (an object-identity "
               "picture)");
  app.add_flag("--skip-unsupported", skipUnsupported,
               "POV-Ray input: skip what is outside the subset, with a warning, and convert the "
               "rest");
  app.add_option("--format", format, "how to print diagnostics (on standard error)")
      ->check(CLI::IsMember({"text", "json"}));
  scene::ReadOptions readOptions;
  addReadLimitOptions(app, readOptions);
  if (auto stop = parseCommandLine(app, argc, argv, out, err)) return toInt(*stop);
  bool json = format == "json";
  bool toStdout = output == "-";
  if (fov && !(*fov > 0.0 && *fov < 180.0)) {
    err << "sfconvert: --fov must lie between 0 and 180 degrees\n";
    return toInt(ExitCode::Usage);
  }

  // Work out the output format before reading anything.
  std::optional<scene::Format> outputFormat;
  if (!to.empty()) {
    outputFormat = scene::findFormatByName(to)->format;
  } else if (!toStdout) {
    if (const scene::FormatInfo* row = scene::findFormatByExtension(output)) {
      outputFormat = row->format;
    }
  }
  if (!outputFormat) {
    err << "sfconvert: cannot tell the output format of '" << output
        << "': use " << extensionList() << ", or --to " << scene::formatNames() << "\n";
    return toInt(ExitCode::Usage);
  }
  std::string bufferFile;
  if (externalBuffers) {
    if (*outputFormat != scene::Format::Gltf || toStdout) {
      err << "sfconvert: --external-buffers needs a .gltf output file\n";
      return toInt(ExitCode::Usage);
    }
    bufferFile = std::filesystem::path(output).stem().string() + ".bin";
  }
  if (!toStdout && isSameFile(input, output)) {
    err << "sfconvert: error: the output '" << output
        << "' is the input file; sfconvert never writes over its input\n";
    return toInt(ExitCode::InvalidInput);
  }
  // The buffer lies beside the .gltf that names it and takes its name: when
  // the output is a link, the file at its end (file_io.h writes through
  // links), so that the .gltf actually written finds its buffer.
  std::filesystem::path bufferPath;
  if (!bufferFile.empty()) {
    std::error_code ec;
    std::filesystem::path gltfFile = output;
    if (std::filesystem::is_symlink(gltfFile, ec)) {
      gltfFile = scene::followLinks(gltfFile).value_or(gltfFile);
      bufferFile = gltfFile.stem().string() + ".bin";
    }
    bufferPath = gltfFile.parent_path() / bufferFile;
    if (isSameFile(input, bufferPath)) {
      err << "sfconvert: error: the buffer file '" << bufferPath.string()
          << "' is the input file; sfconvert never writes over its input\n";
      return toInt(ExitCode::InvalidInput);
    }
    if (gltfFile.filename() == bufferFile) {
      err << "sfconvert: error: the buffer file '" << bufferPath.string()
          << "' is the output itself; name the output NAME.gltf\n";
      return toInt(ExitCode::Usage);
    }
  }

  stage.set("reading " + printableText(input));
  InputText text = readInputText(input, readOptions);
  if (text.tooLarge()) {
    printAll(text.refused, json, err);
    return toInt(ExitCode::InvalidInput);
  }
  if (!text.text) {
    err << printableText(input) << ": error: cannot read the file: "
        << printableText(text.readError) << "\n";
    return toInt(ExitCode::IoError);
  }
  readOptions.sceneFile.transposedMatrices = transpose;
  readOptions.noLoss = noLoss;
  readOptions.pov.skipUnsupported = skipUnsupported;
  if (width > 0 && height > 0) {
    readOptions.pov.imageWidth = width;
    readOptions.pov.imageHeight = height;
  }
  scene::ReadResult result = scene::parseScene(*text.text, input, readOptions);
  if (!result.ok()) {
    printAll(result.diagnostics, json, err);
    return toInt(ExitCode::InvalidInput);
  }

  text.text.reset();  // the scene holds all that is needed now
  stage.set("converting");
  scene::ConversionOptions options;
  options.noLoss = noLoss;
  options.instructions.approximate = approximate;
  if (!toStdout) {
    options.instructions.outputFile = std::filesystem::path(output).stem().string() + ".ppm";
  }
  options.gltf.yfovDegrees = fov;
  options.gltf.width = width;
  options.gltf.height = height;
  options.gltf.segments = tessellation;
  options.gltf.externalBuffer = bufferFile;
  options.gltf.generator = std::string("sfconvert ") + SCENEFILE_VERSION;
  options.pov.verticalFovDegrees = fov;
  if (width > 0 && height > 0) {
    options.pov.width = width;
    options.pov.height = height;
  } else if (width > 0 || height > 0) {
    // One side given: the other keeps sfrender's 4:3.
    options.pov.width = width > 0 ? width : std::max(1, height * 4 / 3);
    options.pov.height = height > 0 ? height : std::max(1, width * 3 / 4);
  }
  options.pov.flat = flat;
  std::optional<scene::ConvertedFiles> converted =
      scene::convertSceneToFiles(result.scene, *outputFormat, options, result.diagnostics);
  printAll(result.diagnostics, json, err);
  if (!converted) return toInt(ExitCode::InvalidInput);

  if (toStdout) {
    stage.set("writing to standard output");
    out << converted->main;
    return toInt(flushStandardOutput("sfconvert", out, err) ? ExitCode::Success
                                                            : ExitCode::IoError);
  }
  stage.set("writing " + printableText(output));
  // The buffer first, so that the .gltf never names a buffer not there;
  // both are written in full before either is renamed.
  std::vector<FileToWrite> files;
  if (!converted->sidecar.empty()) files.push_back({bufferPath, converted->sidecar});
  files.push_back({output, converted->main});
  std::string writeError;
  std::filesystem::path failed;
  if (!writeFilesAtomically(files, writeError, &failed)) {
    err << failed.string() << ": error: cannot write the file: " << writeError << "\n";
    if (namesStandardOutput(output)) {
      err << "  hint: sfconvert writes regular files; name the output - for standard output\n";
    }
    return toInt(ExitCode::IoError);
  }
  return toInt(ExitCode::Success);
}

}  // namespace

int runSfconvert(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  Stage stage;
  return runGuarded("sfconvert", err, stage, [&] { return convert(argc, argv, out, err, stage); });
}

}  // namespace tools
