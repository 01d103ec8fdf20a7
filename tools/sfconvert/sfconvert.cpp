#include "tools/sfconvert/sfconvert.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "scenefile/convert.h"
#include "scenefile/validation.h"
#include "tools/common/diagnostic_printer.h"
#include "tools/common/file_io.h"
#include "tools/common/input_limits.h"
#include "tools/common/output_location.h"
#include "tools/common/output_pattern.h"
#include "tools/common/output_plan.h"
#include "tools/common/resource_guard.h"
#include "tools/common/standard_streams.h"
#include "tools/common/tool_output.h"
#include "tools/sfconvert/conversion_options.h"

namespace tools {

namespace {

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

// Whether the name is one of standard output's: written as a file, it is
// the pipe or terminal behind it, which an atomic write cannot replace.
bool namesStandardOutput(const std::string& path) {
  return path == "/dev/stdout" || path == "/dev/fd/1" || path == "/proc/self/fd/1";
}

// The format `output` is written in: --to's, else its extension's.
std::optional<scene::Format> outputFormat(const SfconvertOptions& o, const std::string& output) {
  if (!o.to.empty()) return scene::findFormatByName(o.to)->format;
  if (isStandardStream(output)) return std::nullopt;
  const scene::FormatInfo* row = scene::findFormatByExtension(output);
  return row ? std::optional<scene::Format>(row->format) : std::nullopt;
}

// The buffer of the .gltf `output` with --external-buffers (`extension`
// .bin), or the MTL file of an .obj (.mtl): beside the file the output is
// written as and named after it (when the output is a link, the file at its
// end: file_io.h writes through links), so that the file actually written
// finds it.
std::filesystem::path bufferPathOf(const std::string& output, std::string_view extension) {
  std::error_code ec;
  std::filesystem::path gltfFile = output;
  if (std::filesystem::is_symlink(gltfFile, ec)) {
    gltfFile = scene::followLinks(gltfFile).value_or(gltfFile);
  }
  return gltfFile.parent_path() / (gltfFile.stem().string() + std::string(extension));
}

// A conversion's plan, worked out from the command line before anything is
// read: the output format, and the buffer file a .gltf may get.
struct Plan {
  scene::Format format = scene::Format::SceneFile;
  bool toStdout = false;
  std::filesystem::path bufferPath;  // empty: no separate buffer
  std::string bufferFile;
};

class Converter {
 public:
  Converter(const SfconvertOptions& o, ToolOutput& output, Stage& stage)
      : o_(o),
        output_(output),
        stage_(stage),
        format_(diagnosticFormatFromName(o.format).value_or(DiagnosticFormat::Text)) {}

  // Reads, converts and writes the scene: nothing when it is written, else
  // why not.
  MaybeFailure run();

 private:
  MaybeFailure plan();
  MaybeFailure planBuffer();
  MaybeFailure read(std::optional<scene::ReadResult>& parsed);
  scene::ConversionOptions conversionOptions() const;
  MaybeFailure write(const scene::ConvertedFiles& converted, const scene::Scene& scene);
  void print(const scene::DiagnosticList& list) const;

  // Inputs up to this size are kept until the conversion's diagnostics are
  // printed, to quote the lines they point at.
  static constexpr std::size_t kKeptForQuotes = std::size_t{16} << 20;

  const SfconvertOptions& o_;
  ToolOutput& output_;
  Stage& stage_;
  DiagnosticFormat format_;
  Plan plan_;
  SourceExcerpts sources_;
  std::string shown_;
  std::string keptText_;
};

void Converter::print(const scene::DiagnosticList& list) const {
  if (format_ == DiagnosticFormat::Json) {
    output_.err() << diagnosticsToJson(list).dump(2) << "\n";
    return;
  }
  DiagnosticPrinter(output_.err(), output_.diagnosticStyle(format_), &sources_).print(list);
}

// The output format and where each file goes, or why the command line
// cannot work.
MaybeFailure Converter::plan() {
  plan_.toStdout = isStandardStream(o_.output);
  std::optional<scene::Format> format = outputFormat(o_, o_.output);
  if (!format) {
    return toolFailure(ExitCode::Usage,
                       "cannot tell the output format of '" + printableText(o_.output) + "'",
                       "use " + extensionList() + ", or --to " + scene::formatNames());
  }
  plan_.format = *format;
  if (plan_.toStdout && scene::formatInfo(*format).binary && output_.streams().outIsTerminal) {
    return toolFailure(ExitCode::Usage,
                       "standard output is a terminal, and " +
                           std::string(scene::formatInfo(*format).singular) + " is binary",
                       "redirect it to a file or a pipe (> out.glb), or name the output file");
  }
  if (!plan_.toStdout && writesOverInput(o_.input, o_.output)) {
    return toolFailure(ExitCode::InvalidInput,
                       "the output '" + printableText(o_.output) +
                           "' is the input file; sfconvert never writes over its input");
  }
  if (MaybeFailure failure = planBuffer()) return failure;
  if (o_.noClobber && !plan_.toStdout) {
    for (const std::filesystem::path& path : {std::filesystem::path(o_.output), plan_.bufferPath}) {
      if (!path.empty() && pathExists(path)) {
        return fileFailure(ExitCode::IoError, path.string(), kNoClobberMessage);
      }
    }
  }
  return std::nullopt;
}

// The buffer lies beside the .gltf that names it, an OBJ's MTL file beside
// the .obj (bufferPathOf), as every OBJ exporter writes it; an OBJ on
// standard output has its materials in its comments alone.
MaybeFailure Converter::planBuffer() {
  bool mtl = plan_.format == scene::Format::Obj && !plan_.toStdout;
  if (!o_.externalBuffers && !mtl) return std::nullopt;
  if (o_.externalBuffers && (plan_.format != scene::Format::Gltf || plan_.toStdout)) {
    return toolFailure(ExitCode::Usage, "--external-buffers needs a .gltf output file");
  }
  std::string what = mtl ? "the MTL file '" : "the buffer file '";
  plan_.bufferPath = bufferPathOf(o_.output, mtl ? ".mtl" : ".bin");
  plan_.bufferFile = plan_.bufferPath.filename().string();
  if (writesOverInput(o_.input, plan_.bufferPath.string())) {
    return toolFailure(ExitCode::InvalidInput,
                       what + printableText(plan_.bufferPath.string()) +
                           "' is the input file; sfconvert never writes over its input");
  }
  OutputPlan outputs;
  outputs.addOutput(o_.output, o_.input);
  outputs.addOutput(plan_.bufferPath.string(), o_.input);
  if (outputs.firstClash()) {
    return toolFailure(ExitCode::Usage, what + printableText(plan_.bufferPath.string()) +
                                            "' is the output itself; name the output " +
                                            (mtl ? "NAME.obj" : "NAME.gltf"));
  }
  return std::nullopt;
}

MaybeFailure Converter::read(std::optional<scene::ReadResult>& parsed) {
  std::string shown = inputDisplayName(o_.input);
  stage_.set("reading " + printableText(shown));
  scene::ReadOptions readOptions = o_.read;
  InputText text = readInputText(o_.input, readOptions, &output_.streams().in);
  if (text.tooLarge()) {
    print(text.diagnostics);
    return toldFailure(ExitCode::InvalidInput);
  }
  if (!text.text) {
    return fileFailure(ExitCode::IoError, shown,
                       "cannot read the file: " + printableText(text.readError));
  }
  readOptions.sceneFile.transposedMatrices = o_.transpose;
  readOptions.noLoss = o_.noLoss;
  readOptions.pov.skipUnsupported = o_.skipUnsupported;
  if (o_.width > 0 && o_.height > 0) {
    readOptions.pov.imageWidth = o_.width;
    readOptions.pov.imageHeight = o_.height;
  }
  scene::ReadResult result = scene::parseScene(*text.text, shown, readOptions);
  if (!result.ok()) {
    if (format_ == DiagnosticFormat::Text) sources_.capture(shown, *text.text, result.diagnostics);
    print(result.diagnostics);
    return toldFailure(ExitCode::InvalidInput);
  }
  std::optional<scene::Format> detected = scene::detectFormat(*text.text, shown);
  // The conversion's warnings point into the input too: a small input is
  // kept to quote them; of a large one only the lines the reader's
  // diagnostics quote are, so that the text does not stay beside the
  // scene while it converts.
  if (format_ == DiagnosticFormat::Text) {
    shown_ = shown;
    if (text.text->size() <= kKeptForQuotes) {
      keptText_ = std::move(*text.text);
    } else {
      sources_.capture(shown, *text.text, result.diagnostics);
    }
  }
  output_.detail("read " + printableText(shown) + " (" +
                 std::string(detected ? scene::formatInfo(*detected).singular : "a scene") + ", " +
                 sceneContents(result.scene) + ")");
  output_.step("reading");
  parsed = std::move(result);
  return std::nullopt;
}

scene::ConversionOptions Converter::conversionOptions() const {
  return conversionOptionsFor(o_, plan_.toStdout, plan_.bufferFile);
}

MaybeFailure Converter::write(const scene::ConvertedFiles& converted, const scene::Scene& scene) {
  // What the file holds: a glTF written with --no-lights has no light.
  bool gltf = plan_.format == scene::Format::Gltf || plan_.format == scene::Format::Glb;
  std::size_t lights = gltf && o_.noLights ? 0 : scene.lights.size();
  std::string what = std::string(scene::formatInfo(plan_.format).singular) + ", " +
                     countOf(scene.objects.size(), "object") + ", " + countOf(lights, "light");
  if (plan_.toStdout) {
    stage_.set("writing to standard output");
    output_.streams().out << converted.main;
    if (!flushStandardOutput("sfconvert", output_.streams().out, output_.err())) {
      return toldFailure(ExitCode::IoError);
    }
    output_.info("wrote standard output (" + what + ")");
    return std::nullopt;
  }
  stage_.set("writing " + printableText(o_.output));
  // The buffer first, so that the .gltf never names a buffer not there;
  // both are written in full before either is renamed.
  std::vector<FileToWrite> files;
  if (!converted.sidecar.empty()) files.push_back({plan_.bufferPath, converted.sidecar});
  files.push_back({o_.output, converted.main});
  if (MaybeFailure failure = writeFilesAtomically(files, !o_.noClobber)) {
    failure->message = "cannot write the file: " + failure->message;
    if (namesStandardOutput(o_.output)) {
      failure->hint = "sfconvert writes regular files; name the output - for standard output";
    }
    return failure;
  }
  output_.step("writing");
  std::string wrote = "wrote " + printableText(o_.output) + " (" + what + ")";
  if (!converted.sidecar.empty()) wrote += " and " + printableText(plan_.bufferPath.string());
  output_.info(wrote);
  std::string outputFile = scene::outputFileNameFor(o_.output);
  if (plan_.format == scene::Format::InstructionFile && !scene.outputFile &&
      outputFile != std::filesystem::path(o_.output).stem().string() + ".ppm") {
    output_.info("OUTPUT_FILE is " + outputFile +
                 ": an instruction file holds no blank, control character or character that "
                 "is not ASCII in a name");
  }
  return std::nullopt;
}

MaybeFailure Converter::run() {
  if (MaybeFailure failure = plan()) return failure;
  std::optional<scene::ReadResult> result;
  if (MaybeFailure failure = read(result)) return failure;
  stage_.set("converting");
  std::optional<scene::ConvertedFiles> converted = scene::convertSceneToFiles(
      result->scene, plan_.format, conversionOptions(), result->diagnostics);
  if (!keptText_.empty()) {
    sources_.capture(shown_, keptText_, result->diagnostics);
    keptText_ = std::string();
  }
  print(result->diagnostics);
  if (!converted) return toldFailure(ExitCode::InvalidInput);
  output_.step("converting");
  return write(*converted, result->scene);
}

// What the command line asks: one conversion, or a batch's.
MaybeFailure runCommand(SfconvertOptions& options, ToolOutput& output, Stage& stage) {
  if (options.outputPattern.empty()) {
    if (options.files.size() != 2) {
      return toolFailure(ExitCode::Usage,
                         options.files.size() < 2 ? "missing OUTPUT"
                                                  : "several inputs need -o, a pattern such as "
                                                    "'out/{stem}.gltf'",
                         "run 'sfconvert --help' for the options");
    }
    options.input = options.files[0];
    options.output = options.files[1];
    return Converter(options, output, stage).run();
  }
  Outcome<std::vector<std::string>> outputs = batchOutputs(options.outputPattern, options.files);
  if (!outputs) return outputs.failure();
  // Every file the batch writes, buffers included, checked together (one
  // input is checked as `sfconvert IN OUT` is, by its conversion).
  OutputPlan plan;
  for (const std::string& input : options.files) plan.addInput(input);
  for (std::size_t i = 0; i < outputs->size(); ++i) {
    const std::string& out = (*outputs)[i];
    plan.addOutput(out, options.files[i]);
    std::optional<scene::Format> format = outputFormat(options, out);
    if (options.externalBuffers && format == scene::Format::Gltf) {
      plan.addOutput(bufferPathOf(out, ".bin").string(), options.files[i], "its buffer");
    }
    if (format == scene::Format::Obj && !isStandardStream(out)) {
      plan.addOutput(bufferPathOf(out, ".mtl").string(), options.files[i], "its MTL file");
    }
  }
  std::optional<OutputClash> clash = options.files.size() > 1 ? plan.firstClash() : std::nullopt;
  if (clash) {
    return toolFailure(
        ExitCode::Usage,
        plan.describe(*clash) + "; a batch writes each file once, and never over an input",
        clash->overInput ? "write the outputs to a folder of their own, such as -o "
                           "'out/{stem}.sf'"
                         : "use {dir} or {name} in -o");
  }
  // Each file converted as if alone, the batch going on past one that
  // fails (its failure reported where it ends); the batch ends with the
  // first failure's status.
  int converted = 0;
  MaybeFailure first;
  for (std::size_t i = 0; i < options.files.size(); ++i) {
    SfconvertOptions one = options;
    one.input = options.files[i];
    one.output = (*outputs)[i];
    if (MaybeFailure failure = Converter(one, output, stage).run()) {
      output.report(*failure);
      if (!first) first = toldFailure(failure->code);
    } else {
      ++converted;
    }
  }
  int total = static_cast<int>(options.files.size());
  if (total > 1 && (!options.common.quiet || converted < total)) {
    output.err() << batchSummary("sfconvert", converted, total, "scenes converted") << "\n";
  }
  return first;
}

int convert(int argc, const char* const* argv, const ToolStreams& streams, Stage& stage) {
  SfconvertOptions options;
  std::unique_ptr<CLI::App> app = makeSfconvertCommandLine(options);
  if (auto stop = parseCommandLine(*app, argc, argv, streams.out, streams.err)) {
    return toInt(*stop);
  }
  ToolOutput output("sfconvert", streams, options.common);
  MaybeFailure failure = runCommand(options, output, stage);
  return failure ? output.report(*failure) : toInt(ExitCode::Success);
}

}  // namespace

int runSfconvert(int argc, const char* const* argv, const ToolStreams& streams) {
  Stage stage;
  return runGuarded("sfconvert", streams.err, stage,
                    [&] { return convert(argc, argv, streams, stage); });
}

}  // namespace tools
