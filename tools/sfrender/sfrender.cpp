#include "tools/sfrender/sfrender.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <optional>
#include <sstream>
#include <string>
#include <variant>

#include "tools/common/output_location.h"
#include "scenefile/read.h"
#include "renderer/default_scene.h"
#include "renderer/render.h"
#include "tools/common/command_line.h"
#include "tools/common/diagnostic_printer.h"
#include "tools/common/file_io.h"
#include "tools/common/input_limits.h"
#include "tools/common/output_file_format.h"
#include "tools/common/resource_guard.h"
#include "tools/sfrender/image_file.h"
#include "tools/sfrender/thread_probe.h"

namespace tools {

namespace {

namespace fs = std::filesystem;

std::string withThousands(std::uint64_t n) {
  std::string digits = std::to_string(n);
  for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3) digits.insert(i, ",");
  return digits;
}

// The hard ceilings of --spp and --depth, whatever the --max- flags say: far
// beyond any useful render (65536 samples was the cap before the flags).
constexpr int kSppCeiling = 65536;
constexpr int kDepthCeiling = 1000;

// What one render may ask for; the flags raise them (docs/FORMATS.md, "Limits").
struct RenderLimits {
  std::int64_t maxPixels = std::int64_t{8192} * 8192;
  int maxSpp = 1024;
  int maxDepth = 64;
};

// The setting above its limit, named with the flag that raises it, if any.
std::optional<std::string> settingOverLimit(const render::RenderSettings& settings,
                                            const RenderLimits& limits) {
  std::int64_t pixels = std::int64_t{settings.width} * settings.height;
  if (pixels > limits.maxPixels) {
    return "--width " + std::to_string(settings.width) + " and --height " +
           std::to_string(settings.height) + " make " +
           withThousands(static_cast<std::uint64_t>(pixels)) + " pixels, more than the limit of " +
           withThousands(static_cast<std::uint64_t>(limits.maxPixels)) +
           "; raise it with --max-pixels";
  }
  if (settings.samplesPerPixel > limits.maxSpp) {
    return "--spp " + std::to_string(settings.samplesPerPixel) + " is more than the limit of " +
           std::to_string(limits.maxSpp) + " samples per pixel; raise it with --max-spp";
  }
  if (settings.maxDepth > limits.maxDepth) {
    return "--depth " + std::to_string(settings.maxDepth) + " is more than the limit of " +
           std::to_string(limits.maxDepth) + " bounces; raise it with --max-depth";
  }
  return std::nullopt;
}

void printStatistics(const render::RenderStatistics& s, const render::RenderSettings& settings,
                     std::ostream& err) {
  std::uint64_t total = s.rays.primary + s.rays.secondary + s.rays.shadow;
  std::ostringstream line;
  line << std::fixed << std::setprecision(3) << "sfrender: " << settings.width << "x"
       << settings.height << ", " << settings.samplesPerPixel << " spp, depth " << settings.maxDepth
       << ": " << s.seconds << " s, " << withThousands(total) << " rays ("
       << withThousands(s.rays.primary) << " primary, " << withThousands(s.rays.secondary)
       << " reflected or refracted, " << withThousands(s.rays.shadow) << " shadow), "
       << std::setprecision(2) << (s.seconds > 0 ? total / s.seconds / 1e6 : 0.0)
       << " million rays/s\n";
  // What adaptive depth control (docs/RENDERING.md, "Cost") left out.
  line << "sfrender: left out " << withThousands(s.rays.pruned)
       << " branches (past the depth, or within their share of half a level of the image), traced "
       << withThousands(s.retracedPixels) << " pixels again\n";
  err << line.str();
}

// The scene to render and where its image goes, or the exit status.
struct SceneAndTarget {
  scene::Scene scene;
  fs::path target;
  bool fromOutputFile = false;  // the target is the scene's OUTPUT_FILE
};

std::variant<SceneAndTarget, int> readSceneAndTarget(const std::string& input,
                                                     const std::string& output,
                                                     const scene::ReadOptions& readOptions,
                                                     bool quiet, std::ostream& err) {
  SceneAndTarget job;
  if (input.empty()) {
    job.scene = render::defaultScene();
    job.target = output.empty() ? fs::path(*job.scene.outputFile) : fs::path(output);
    return job;
  }
  InputText text = readInputText(input, readOptions);
  if (text.tooLarge()) {
    printDiagnostics(text.refused, err);
    return toInt(ExitCode::InvalidInput);
  }
  if (!text.text) {
    err << printableText(input)
        << ": error: cannot read the file: " << printableText(text.readError) << "\n";
    return toInt(ExitCode::IoError);
  }
  scene::ReadResult result = scene::parseScene(*text.text, input, readOptions);
  if (result.scene.outputFile && output.empty()) {
    // OUTPUT_FILE is the instruction file's to choose, inside its folder.
    scene::checkOutputLocation(result.scene, fs::path(input).parent_path(), scene::Severity::Error,
                               result.diagnostics);
  }
  if (!quiet || result.diagnostics.hasErrors()) printDiagnostics(result.diagnostics, err);
  if (!result.ok()) return toInt(ExitCode::InvalidInput);
  text.text.reset();  // the scene holds all the render needs
  job.scene = std::move(result.scene);
  if (!output.empty()) {
    job.target = output;
  } else if (job.scene.outputFile) {
    job.target = fs::path(input).parent_path() / *job.scene.outputFile;
    job.fromOutputFile = true;
  } else {
    job.target = fs::path(input).stem().string() + ".ppm";
  }
  return job;
}

// Whether the image can go where it is to go, found out before the first
// ray: the name (not the input, an image format) and the place (the folder
// there and writable, the target no folder or device, room for a PPM).
std::optional<int> targetRefusal(const std::string& input, const SceneAndTarget& job,
                                 const render::RenderSettings& settings,
                                 const ImageOptions& imageOptions, std::ostream& err) {
  const fs::path& target = job.target;
  // Before the extension's check, so that an OUTPUT_FILE naming its own
  // instruction file is told so, not that .txt is no image format.
  if (!input.empty() && isSameFile(input, target)) {
    err << "sfrender: error: the output '" << target.string()
        << "' is the input file; sfrender never writes over its input\n";
    return toInt(ExitCode::InvalidInput);
  }
  if (job.fromOutputFile && !hasImageExtension(target)) {
    // The file's mistake, at its line and column, like any other.
    scene::DiagnosticList diagnostics(input);
    checkOutputFileFormat(job.scene, scene::Severity::Error, diagnostics);
    printDiagnostics(diagnostics, err);
    return toInt(ExitCode::InvalidInput);
  }
  if (std::optional<std::string> refusal = imageRefusal(target, imageOptions)) {
    err << "sfrender: error: " << *refusal << "\n";
    return toInt(ExitCode::Usage);
  }
  std::string error;
  if (!checkCanWrite(target, true,
                     ppmFileSize(settings.width, settings.height, target, imageOptions), error)) {
    err << target.string() << ": error: cannot write the image: " << error << "\n";
    return toInt(ExitCode::IoError);
  }
  return std::nullopt;
}

// Whether the render fits in memory and its threads start: refused before
// it starts rather than killed, or aborted, half-way.
std::optional<int> resourceRefusal(const SceneAndTarget& job,
                                   const render::RenderSettings& settings,
                                   const AvailableMemoryProbe& availableMemory, Stage& stage,
                                   std::ostream& err) {
  render::RenderMemoryEstimate estimate =
      render::estimateRenderMemory(job.scene.objects.size(), job.scene.lights.size(),
                                   settings.width, settings.height, settings.coverage);
  if (std::optional<std::string> refusal = render::renderMemoryRefusal(
          estimate, availableMemory ? availableMemory() : std::nullopt)) {
    err << "sfrender: error: " << *refusal << "\n";
    return toInt(ExitCode::OutOfResources);
  }
  int threads = renderThreadCount(settings.threads);
  stage.set("starting " + std::to_string(threads) + " threads");
  if (std::optional<std::string> failure = threadStartFailure(threads)) {
    err << "sfrender: error: cannot start " << threads << " threads: " << *failure
        << "; ask for fewer with --threads\n";
    return toInt(ExitCode::OutOfResources);
  }
  return std::nullopt;
}

// Which of the view's flags the command line gave.
struct ViewFlags {
  CLI::Option* width = nullptr;
  CLI::Option* height = nullptr;
  CLI::Option* fov = nullptr;
};

// The scene's own view (a POV-Ray or glTF camera's) where the command line
// does not say otherwise: its field of view unless --fov, and at its aspect
// ratio the side that --width and --height leave open (the height, when
// neither is given).
void applySceneView(const scene::Scene& scene, const ViewFlags& given,
                    render::RenderSettings& settings) {
  if (!scene.view) return;
  if (given.fov->count() == 0) {
    settings.verticalFovDegrees = std::clamp(scene.view->verticalFovDegrees, 0.001, 179.999);
  }
  if (!scene.view->aspectRatio || (given.height->count() > 0 && given.width->count() > 0)) return;
  double aspect = *scene.view->aspectRatio;
  auto side = [](double pixels) {
    return static_cast<int>(std::clamp(std::round(pixels), 1.0, 32768.0));
  };
  if (given.height->count() > 0) {
    settings.width = side(settings.height * aspect);
  } else {
    settings.height = side(settings.width / aspect);
  }
}

int renderToFile(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
                 bool errIsTerminal, const AvailableMemoryProbe& availableMemory, Stage& stage) {
  CLI::App app{"Ray traces a scene, in any of " + scene::describeFormats() +
                   " (the default scene without one)",
               "sfrender"};
  app.set_version_flag("--version", SCENEFILE_VERSION);
  std::string input;
  std::string output;
  render::RenderSettings settings;
  bool quiet = false;
  bool stats = false;
  ImageOptions imageOptions;
  app.add_option("scene", input, "the scene to render, its format recognised from its content");
  app.add_option("-o,--output", output,
                 "the image to write; its extension picks the format (listed at the end)");
  // 32768 a side keeps width * height within an int whatever --max-pixels.
  ViewFlags given;
  given.width = app.add_option("--width", settings.width, "image width in pixels")
                    ->check(CLI::Range(1, 32768));
  given.height = app.add_option("--height", settings.height, "image height in pixels")
                     ->check(CLI::Range(1, 32768));
  given.fov = app.add_option("--fov", settings.verticalFovDegrees,
                             "vertical field of view in degrees (default: the scene's, else 60)")
                  ->check(CLI::Range(0.001, 179.999));
  // --spp and --depth are held to the --max- flags below, checked after
  // parsing so that the message can name the flag that raises them.
  app.add_option("--spp", settings.samplesPerPixel, "samples per pixel, stratified")
      ->check(CLI::Range(1, kSppCeiling));
  app.add_option("--depth", settings.maxDepth, "bounces of reflection and refraction")
      ->check(CLI::Range(0, kDepthCeiling));
  app.add_option("--threads", settings.threads, "threads to render with (0: every core)")
      ->check(CLI::Range(0, 1024));
  app.add_option("--seed", settings.seed, "seed of the sample positions");
  app.add_flag("--quiet", quiet, "print nothing but errors");
  app.add_flag("--stats", stats, "print the time, the rays and the rays per second");
  app.add_option("--bits", imageOptions.bits,
                 "bits a channel: 8 or 16 for integer images (PNG, TIFF, PPM), 16 (half) or 32 "
                 "(float) for EXR (default: 8, EXR 32)")
      ->check(CLI::IsMember({8, 16, 32}));
  app.add_flag("--alpha", imageOptions.alpha,
               "a fourth channel: how much of each pixel objects cover, the background "
               "transparent");
  app.footer([] { return imageFormatHelp(); });
  RenderLimits limits;
  app.add_option("--max-pixels", limits.maxPixels,
                 "refuse an image of more pixels (width x height)")
      ->check(CLI::Range(std::int64_t{1}, std::int64_t{32768} * 32768))
      ->capture_default_str();
  app.add_option("--max-spp", limits.maxSpp, "refuse more samples per pixel than this")
      ->check(CLI::Range(1, kSppCeiling))
      ->capture_default_str();
  app.add_option("--max-depth", limits.maxDepth, "refuse more bounces than this")
      ->check(CLI::Range(0, kDepthCeiling))
      ->capture_default_str();
  scene::ReadOptions readOptions;
  addReadLimitOptions(app, readOptions);
  if (auto stop = parseCommandLine(app, argc, argv, out, err)) return toInt(*stop);
  if (std::optional<std::string> overLimit = settingOverLimit(settings, limits)) {
    err << "sfrender: " << *overLimit << "\n";
    return toInt(ExitCode::Usage);
  }

  // Step 1: the scene, and where its image goes.
  if (!input.empty()) stage.set("reading " + printableText(input));
  std::variant<SceneAndTarget, int> read =
      readSceneAndTarget(input, output, readOptions, quiet, err);
  if (const int* status = std::get_if<int>(&read)) return *status;
  SceneAndTarget& job = std::get<SceneAndTarget>(read);
  applySceneView(job.scene, given, settings);
  if (std::optional<std::string> overLimit = settingOverLimit(settings, limits)) {
    err << "sfrender: " << *overLimit << " (at the scene's aspect ratio)\n";
    return toInt(ExitCode::Usage);
  }
  const fs::path& target = job.target;
  if (std::optional<int> refused = targetRefusal(input, job, settings, imageOptions, err)) {
    return *refused;
  }
  fitRenderToImage(target, imageOptions, settings);

  // Step 2: render, with a progress bar on a terminal, if it fits in memory
  // and its threads start.
  if (std::optional<int> refused = resourceRefusal(job, settings, availableMemory, stage, err)) {
    return *refused;
  }
  stage.set("preparing the scene");
  render::RenderScene compiled(job.scene);
  render::RenderStatistics statistics;
  render::ProgressCallback progress;
  if (errIsTerminal && !quiet) {
    progress = [&err](int done, int total) {
      err << "\rsfrender: rendering " << std::setw(3) << (100 * done / total) << "%"
          << (done == total ? "\n" : "") << std::flush;
    };
  }
  stage.set("rendering");
  render::Image image = render::renderImage(compiled, settings, &statistics, progress);

  // Step 3: the file, whole or not at all.
  stage.set("writing " + printableText(target.string()));
  std::string writeError;
  if (!writeImageFile(image, target, writeError, imageOptions)) {
    err << target.string() << ": error: cannot write the image: " << writeError << "\n";
    return toInt(ExitCode::IoError);
  }
  if (stats) printStatistics(statistics, settings, err);
  if (statistics.rays.cut > 0) {
    // Only the cap on rays a sample may trace (materials that reflect and
    // refract everything, where no branch can be left out) loses accuracy.
    err << "sfrender: warning: " << withThousands(statistics.rays.cut)
        << " reflected or refracted rays were not traced: their samples had traced "
        << settings.maxRaysPerSample
        << " already, so the picture may differ from a full trace by more than half a level\n";
  }
  if (!quiet) {
    err << "sfrender: wrote " << target.string() << " (" << settings.width << "x" << settings.height
        << (input.empty() ? ", the default scene" : "") << ")\n";
  }
  return toInt(ExitCode::Success);
}

}  // namespace

int runSfrender(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
                bool errIsTerminal, const AvailableMemoryProbe& availableMemory) {
  Stage stage;
  return runGuarded("sfrender", err, stage, [&] {
    return renderToFile(argc, argv, out, err, errIsTerminal, availableMemory, stage);
  });
}

}  // namespace tools
