#include "tools/sfrender/sfrender.h"

#include <malloc.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <memory>
#include <optional>
#include <sstream>
#include <stop_token>
#include <string>
#include <system_error>
#include <thread>
#include <variant>

#include "image/image_file.h"
#include "image/region_merge.h"
#include "renderer/adaptive_sampling.h"
#include "renderer/default_scene.h"
#include "renderer/render.h"
#include "renderer/render_scene_builder.h"
#include "renderer/saturating.h"
#include "scenefile/read.h"
#include "scenefile/read_stream.h"
#include "scenefile/render.h"
#include "scenefile/validation.h"
#include "tools/common/diagnostic_printer.h"
#include "tools/common/file_io.h"
#include "tools/common/input_limits.h"
#include "tools/common/output_file_format.h"
#include "tools/common/output_location.h"
#include "tools/common/output_pattern.h"
#include "tools/common/output_plan.h"
#include "tools/common/resource_guard.h"
#include "tools/common/standard_streams.h"
#include "tools/common/tool_output.h"
#include "tools/sfrender/image_region.h"
#include "tools/sfrender/image_target.h"
#include "tools/sfrender/memory_report.h"
#include "tools/sfrender/progress_line.h"
#include "tools/sfrender/render_hint.h"
#include "tools/sfrender/thread_probe.h"

namespace tools {

namespace {

namespace fs = std::filesystem;

std::string withThousands(std::uint64_t n) {
  std::string digits = std::to_string(n);
  for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3) digits.insert(i, ",");
  return digits;
}

// A usage failure for the setting above its limit, named with the flag that
// raises it, if any; `where` follows the sentence.
MaybeFailure settingOverLimit(const render::RenderSettings& settings, const RenderLimits& limits,
                              const std::string& where = {}) {
  auto over = [&](const std::string& message) {
    return toolFailure(ExitCode::Usage, message + where);
  };
  std::int64_t pixels = std::int64_t{settings.width} * settings.height;
  if (pixels > limits.maxPixels) {
    return over("--width " + std::to_string(settings.width) + " and --height " +
                std::to_string(settings.height) + " make " +
                withThousands(static_cast<std::uint64_t>(pixels)) +
                " pixels, more than the limit of " +
                withThousands(static_cast<std::uint64_t>(limits.maxPixels)) +
                "; raise it with --max-pixels");
  }
  if (settings.samplesPerPixel > limits.maxSpp) {
    return over("--spp " + std::to_string(settings.samplesPerPixel) +
                " is more than the limit of " + std::to_string(limits.maxSpp) +
                " samples per pixel; raise it with --max-spp");
  }
  if (settings.maxDepth > limits.maxDepth) {
    return over("--depth " + std::to_string(settings.maxDepth) + " is more than the limit of " +
                std::to_string(limits.maxDepth) + " bounces; raise it with --max-depth");
  }
  return std::nullopt;
}

std::string statisticsText(const render::RenderStatistics& s,
                           const render::RenderSettings& settings) {
  std::uint64_t total = s.rays.primary + s.rays.secondary + s.rays.shadow;
  std::ostringstream line;
  line << std::fixed << std::setprecision(3) << "sfrender: " << settings.width << "x"
       << settings.height;
  if (!settings.region.empty()) {
    const render::PixelRegion& r = settings.region;
    line << " (region " << r.x0 << "," << r.y0 << "," << r.x1 << "," << r.y1 << ")";
  }
  line << ", " << settings.samplesPerPixel << " spp, depth " << settings.maxDepth << ": "
       << s.seconds << " s, " << withThousands(total) << " rays (" << withThousands(s.rays.primary)
       << " primary, " << withThousands(s.rays.secondary) << " reflected or refracted, "
       << withThousands(s.rays.shadow) << " shadow), " << std::setprecision(2)
       << (s.seconds > 0 ? total / s.seconds / 1e6 : 0.0) << " million rays/s\n";
  // What adaptive depth control (docs/RENDERING.md, "Cost") left out.
  line << "sfrender: left out " << withThousands(s.rays.pruned)
       << " branches (past the depth, or within their share of half a level of the image), traced "
       << withThousands(s.retracedPixels) << " pixels again\n";
  if (!s.device.empty()) {
    line << std::setprecision(3) << "sfrender: device " << s.device << ": start "
         << s.deviceStartSeconds << " s, upload " << s.uploadSeconds << " s, kernel "
         << s.kernelSeconds << " s, readback " << s.readbackSeconds << " s\n";
  }
  if (settings.adaptiveThreshold > 0) {
    line << std::setprecision(2) << "sfrender: adaptive sampling refined "
         << withThousands(s.refinedPixels) << " of " << withThousands(s.pixels) << " pixels ("
         << (s.pixels > 0 ? 100.0 * s.refinedPixels / s.pixels : 0.0) << "%), "
         << withThousands(s.fullySampledPixels) << " of them to squares of 1/"
         << (1 << render::subdivisionDepth(settings.samplesPerPixel)) << " pixel, and sampled "
         << withThousands(s.centredPixels) << " more at their centre; "
         << (s.pixels > 0 ? static_cast<double>(s.samples) / s.pixels : 0.0)
         << " samples a pixel on average\n";
  }
  return line.str();
}

// The pixels the image file holds: the region's, or the whole image's.
int imageWidth(const render::RenderSettings& s) {
  return s.region.empty() ? s.width : s.region.width();
}
int imageHeight(const render::RenderSettings& s) {
  return s.region.empty() ? s.height : s.region.height();
}

// The scene to render and where its image goes.
struct SceneAndTarget {
  scene::Scene scene;  // the camera, lights and view: the objects go to the builder
  fs::path target;
  bool toStdout = false;        // -o -: PPM on standard output
  bool fromOutputFile = false;  // the target is the scene's OUTPUT_FILE
};

// Frees a scene and its compiled form on a thread of its own, and hands
// the free memory back to the system there (malloc_trim), so that neither
// the destructors nor the system's reclaiming of the pages at exit keep
// the process waiting; joined when it goes. Without a thread it frees them
// there and then.
class ReleasedScene {
 public:
  ReleasedScene(scene::Scene scene, render::RenderScene compiled) {
    auto held = std::make_unique<Held>(Held{std::move(scene), std::move(compiled)});
    try {
      thread_ = std::thread([held = std::move(held)]() mutable {
        held.reset();
        ::malloc_trim(0);
      });
    } catch (const std::system_error&) {
      // No thread: what it held is freed here, on the way out.
    }
  }
  ~ReleasedScene() {
    if (thread_.joinable()) thread_.join();
  }
  ReleasedScene(const ReleasedScene&) = delete;
  ReleasedScene& operator=(const ReleasedScene&) = delete;

 private:
  struct Held {
    scene::Scene scene;
    render::RenderScene compiled;
  };
  std::thread thread_;
};

class RenderJob {
 public:
  // `sharedGpu`, where given, is the batch's GPU device: opened by the first
  // scene that renders on the GPU and used by the rest, so that a batch
  // starts the device once and loads the driver once (render::GpuDevice).
  // `planned`, where given, is the image a batch without -o read ahead for
  // this scene (image_target.h), which its outputs were checked by.
  RenderJob(SfrenderOptions& o, ToolOutput& output, const AvailableMemoryProbe& memory,
            Stage& stage, std::unique_ptr<render::GpuDevice>* sharedGpu = nullptr,
            const std::optional<fs::path>* planned = nullptr)
      : o_(o),
        output_(output),
        memory_(memory),
        stage_(stage),
        sharedGpu_(sharedGpu),
        planned_(planned) {}

  // Reads, renders and writes the scene: nothing when its image is
  // written, else why not.
  MaybeFailure run();

 private:
  MaybeFailure readScene();
  MaybeFailure readStandardInput(const std::string& shown, const scene::ReadOptions& read);
  MaybeFailure acceptScene(scene::ReadResult result, std::optional<scene::Format> format,
                           const std::string& shown, const SourceExcerpts& sources);
  void addObjects(std::span<const scene::Object> objects);
  std::vector<StageMemory> stagesHeld(const render::RenderScene& compiled,
                                      const render::Image& image) const;
  void chooseTarget();
  MaybeFailure targetRefusal();
  MaybeFailure resourceRefusal();
  std::optional<std::string> memoryRefusal(std::uint64_t objects, std::uint64_t lights,
                                           bool recordsMade) const;
  void reserveObjects(std::uint64_t objects);
  MaybeFailure chooseRegion();
  MaybeFailure writeImage(const render::Image& image, const render::RenderStatistics& statistics);

  SfrenderOptions& o_;
  ToolOutput& output_;
  const AvailableMemoryProbe& memory_;
  Stage& stage_;
  std::unique_ptr<render::GpuDevice>* sharedGpu_;
  const std::optional<fs::path>* planned_;
  render::RenderSettings settings_;
  SceneAndTarget job_;
  // The objects, compiled as they are read: no list of them all is held.
  std::optional<render::RenderSceneBuilder> builder_;
  std::uint64_t objectCount_ = 0;
  scene::StreamReadMemory readMemory_;
  // Stops the read once its first window shows that the records cannot fit:
  // refused then, not killed half-way through a file of millions of objects.
  std::stop_source readStop_;
  std::optional<std::string> readRefusal_;
};

void RenderJob::reserveObjects(std::uint64_t objects) {
  if ((readRefusal_ = memoryRefusal(objects, 0, false))) {
    readStop_.request_stop();
    return;
  }
  builder_->reserve(objects);
}

void RenderJob::addObjects(std::span<const scene::Object> objects) {
  builder_->add(objects);
  objectCount_ += objects.size();
}

// Step 1: the scene, from the file, standard input or the built-in one, its
// objects compiled as they come: a scene file is streamed
// (scenefile/read_stream.h), so that neither its text nor a model of all
// its objects is ever held.
MaybeFailure RenderJob::readScene() {
  builder_.emplace(renderThreadCount(o_.settings.threads));
  if (o_.input.empty()) {
    job_.scene = render::defaultScene();
    addObjects(job_.scene.objects);
    job_.scene.objects.clear();
    return std::nullopt;
  }
  std::string shown = inputDisplayName(o_.input);
  stage_.set("reading " + printableText(shown));
  // A big scene file is read on the render's threads too.
  scene::ReadOptions read = o_.read;
  read.threads = static_cast<unsigned>(renderThreadCount(o_.settings.threads));
  if (isStandardStream(o_.input)) return readStandardInput(shown, read);
  SourceExcerpts sources;
  read.stop = readStop_.get_token();
  scene::StreamReadResult streamed = scene::streamSceneFile(
      o_.input, read, [this](std::span<const scene::Object> batch) { addObjects(batch); }, &sources,
      [this](std::uint64_t objects) { reserveObjects(objects); });
  if (readRefusal_) return toolFailure(ExitCode::OutOfResources, *readRefusal_);
  readMemory_ = streamed.memory;
  // The text and model the read freed stay with the process: the BVH and
  // the image take that room, already written once, rather than fresh
  // pages. Handing it back (malloc_trim) lowered the peak by 8 MB at
  // 1,000,000 objects but cost 0.04 s of its 1 s (docs/PERFORMANCE.md,
  // "Memory per object").
  const std::vector<scene::Diagnostic>& items = streamed.read.diagnostics.items();
  if (!streamed.format && items.size() == 1 &&
      items[0].code == scene::DiagnosticCode::CannotReadFile) {
    return fileFailure(ExitCode::IoError, shown, printableText(items[0].message));
  }
  if (!streamed.format && items.size() == 1 &&
      items[0].code == scene::DiagnosticCode::FileTooLarge) {
    DiagnosticPrinter(output_.err(), output_.diagnosticStyle(DiagnosticFormat::Text))
        .print(streamed.read.diagnostics);
    return toldFailure(ExitCode::InvalidInput);
  }
  return acceptScene(std::move(streamed.read), streamed.format, shown, sources);
}

// Standard input, read whole: a pipe cannot be read again for the
// diagnostics of a file with errors.
MaybeFailure RenderJob::readStandardInput(const std::string& shown,
                                          const scene::ReadOptions& read) {
  InputText text = readInputText(o_.input, read, &output_.streams().in);
  if (text.tooLarge()) {
    DiagnosticPrinter(output_.err(), output_.diagnosticStyle(DiagnosticFormat::Text))
        .print(text.diagnostics);
    return toldFailure(ExitCode::InvalidInput);
  }
  if (!text.text) {
    return fileFailure(ExitCode::IoError, shown,
                       "cannot read the file: " + printableText(text.readError));
  }
  scene::ReadResult result = scene::parseScene(*text.text, shown, read);
  SourceExcerpts sources;
  sources.capture(shown, *text.text, result.diagnostics);
  std::optional<scene::Format> format = scene::detectFormat(*text.text, shown);
  text.text.reset();
  if (result.ok()) addObjects(result.scene.objects);
  std::vector<scene::Object>().swap(result.scene.objects);
  return acceptScene(std::move(result), format, shown, sources);
}

// The scene read, its diagnostics printed; a failure where it holds errors.
MaybeFailure RenderJob::acceptScene(scene::ReadResult result, std::optional<scene::Format> format,
                                    const std::string& shown, const SourceExcerpts& sources) {
  // Only an instruction file names its image where it can be seen; the
  // OUTPUT_FILE that another format carries for a round trip (glTF extras,
  // OBJ comments) does not choose the image's name.
  if (format != scene::Format::InstructionFile) result.scene.outputFile.reset();
  if (result.scene.outputFile && o_.output.empty()) {
    // OUTPUT_FILE is the instruction file's to choose, inside its folder
    // (standard input's: the current folder).
    fs::path folder = isStandardStream(o_.input) ? fs::path() : fs::path(o_.input).parent_path();
    scene::checkOutputLocation(result.scene, folder, scene::Severity::Error, result.diagnostics);
  }
  DiagnosticStyle style = output_.diagnosticStyle(DiagnosticFormat::Text);
  // The view this render will use, which no hint asks for again.
  render::RenderSettings inUse = settings_;
  scene::applySceneView(result.scene, o_.width, o_.height, o_.fov.has_value(), inUse);
  style.hint = [inUse](const scene::Diagnostic& d) { return renderHintText(d, inUse); };
  DiagnosticPrinter(output_.err(), style, &sources).print(result.diagnostics);
  if (!result.ok()) return toldFailure(ExitCode::InvalidInput);
  output_.detail("read " + printableText(shown) + " (" + countOf(objectCount_, "object") + ", " +
                 countOf(result.scene.lights.size(), "light") + ")");
  job_.scene = std::move(result.scene);
  return std::nullopt;
}

// What each stage held at most, for -v: the read's text and model, the
// compiled scene's parts, the image.
std::vector<StageMemory> RenderJob::stagesHeld(const render::RenderScene& compiled,
                                               const render::Image& image) const {
  render::RenderSceneMemory held = compiled.memory();
  std::uint64_t pixels = (image.rgb.capacity() + image.coverage.capacity()) * sizeof(float);
  return {{"text", readMemory_.textBytes}, {"model", readMemory_.modelBytes},
          {"records", held.records},       {"BVH", held.bvh},
          {"grids", held.grids},           {"image", pixels}};
}

void RenderJob::chooseTarget() {
  if (isStandardStream(o_.output)) {
    job_.toStdout = true;
  } else if (!o_.output.empty()) {
    job_.target = o_.output;
  } else {
    ImageTarget target = defaultImageTarget(o_.input, job_.scene.outputFile);
    job_.target = target.path;
    job_.fromOutputFile = target.fromOutputFile;
  }
}

// Whether the image can go where it is to go, found out before the first
// ray: the name (not the input, an image format) and the place (the folder
// there and writable, the target no folder or device, room for a PPM).
MaybeFailure RenderJob::targetRefusal() {
  if (job_.toStdout) {
    // A PPM: what --bits and --alpha ask of it holds as for a file.
    if (std::optional<std::string> refusal =
            image::imageOptionsRefusal({image::ppmFormat()}, image::ppmFormat(), o_.image)) {
      return toolFailure(ExitCode::Usage, "cannot write standard output as asked: " + *refusal);
    }
    if (!output_.streams().outIsTerminal) return std::nullopt;
    return toolFailure(ExitCode::Usage, "standard output is a terminal, and the image is binary",
                       "redirect it to a file or a pipe (-o - > image.ppm), or name the image");
  }
  const fs::path& target = job_.target;
  // Before the extension's check, so that an OUTPUT_FILE naming its own
  // instruction file is told so, not that .txt is no image format.
  if (writesOverInput(o_.input, target.string())) {
    return toolFailure(ExitCode::InvalidInput,
                       "the output '" + printableText(target.string()) +
                           "' is the input file; sfrender never writes over its input");
  }
  if (job_.fromOutputFile && !hasImageExtension(target)) {
    // The file's mistake, at its line and column, like any other.
    scene::DiagnosticList diagnostics(inputDisplayName(o_.input));
    checkOutputFileFormat(job_.scene, scene::Severity::Error, diagnostics);
    DiagnosticPrinter(output_.err(), output_.diagnosticStyle(DiagnosticFormat::Short))
        .print(diagnostics);
    return toldFailure(ExitCode::InvalidInput);
  }
  if (planned_ && *planned_ != target) {
    // The file changed between the batch's look ahead and its render.
    return toolFailure(ExitCode::InvalidInput,
                       "'" + printableText(o_.input) + "' changed since the batch began: its " +
                           "image would now go to '" + printableText(target.string()) + "'",
                       "run the batch again");
  }
  if (MaybeFailure refusal = image::imageRefusal(target, o_.image)) return refusal;
  if (o_.noClobber && pathExists(target)) {
    return fileFailure(ExitCode::IoError, target.string(), kNoClobberMessage);
  }
  if (MaybeFailure failure = checkCanWrite(
          target, false,
          image::ppmFileSize(imageWidth(settings_), imageHeight(settings_), target, o_.image))) {
    return fileFailure(failure->code, target.string(),
                       "cannot write the image: " + failure->message);
  }
  return std::nullopt;
}

// Whether the render fits in memory and its threads start: refused before
// it starts rather than killed, or aborted, half-way.
// Why a render of `objects` objects and `lights` lights does not fit in the
// free memory, if it does not; `recordsMade` where the records are made
// already, so that the free memory has counted them.
std::optional<std::string> RenderJob::memoryRefusal(std::uint64_t objects, std::uint64_t lights,
                                                    bool recordsMade) const {
  // The materials known so far: a streamed read's first window gives a
  // few, the whole read all of them.
  render::RenderMemoryEstimate estimate = render::estimateRenderMemory(
      {.objects = objects,
       .lights = lights,
       .materials = std::max<std::uint64_t>(1, builder_ ? builder_->materialCount() : 0),
       .width = imageWidth(settings_),
       .height = imageHeight(settings_),
       .cameraSamples = render::uniformSampleCount(settings_),
       .coverage = settings_.coverage});
  if (recordsMade) estimate.scene = 0;
  if (settings_.adaptiveThreshold > 0) {
    estimate.image = render::saturatingSum(
        estimate.image, render::adaptiveSamplingBytes(imageWidth(settings_), imageHeight(settings_),
                                                      renderThreadCount(settings_.threads),
                                                      render::kRenderTileSize));
  }
  return render::renderMemoryRefusal(estimate, memory_ ? memory_() : std::nullopt);
}

MaybeFailure RenderJob::resourceRefusal() {
  if (std::optional<std::string> refusal =
          memoryRefusal(objectCount_, job_.scene.lights.size(), true)) {
    return toolFailure(ExitCode::OutOfResources, *refusal);
  }
  int threads = renderThreadCount(settings_.threads);
  stage_.set("starting " + std::to_string(threads) + " threads");
  if (MaybeFailure failure = threadStartFailure(threads)) return failure;
  output_.detail(
      "rendering " + std::to_string(settings_.width) + "x" + std::to_string(settings_.height) +
      " at a vertical field of view of " + std::to_string(settings_.verticalFovDegrees) +
      " degrees, " + std::to_string(settings_.samplesPerPixel) + " spp, depth " +
      std::to_string(settings_.maxDepth) + ", on " + std::to_string(threads) + " threads");
  return std::nullopt;
}

// --region or --tile, against the image's size once it is known (the
// scene's aspect ratio may set it).
MaybeFailure RenderJob::chooseRegion() {
  if (!o_.region.empty()) {
    settings_.region = parseRegion(o_.region).value_or(render::PixelRegion{});
    if (MaybeFailure refusal = regionRefusal(settings_.region, settings_.width, settings_.height)) {
      return refusal;
    }
  } else if (!o_.tile.empty()) {
    TileChoice tile = parseTile(o_.tile).value_or(TileChoice{});
    if (MaybeFailure refusal = tileRefusal(tile, settings_.height)) return refusal;
    settings_.region = render::imageTile(settings_.width, settings_.height, tile.index, tile.count);
  }
  return std::nullopt;
}

// Step 3: the file, whole or not at all, or standard output.
MaybeFailure RenderJob::writeImage(const render::Image& image,
                                   const render::RenderStatistics& statistics) {
  std::string written;
  if (job_.toStdout) {
    stage_.set("writing to standard output");
    output_.streams().out << image::ppmImageBytes(image, o_.image);
    if (!flushStandardOutput("sfrender", output_.streams().out, output_.err())) {
      return toldFailure(ExitCode::IoError);
    }
    written = "standard output";
  } else {
    stage_.set("writing " + printableText(job_.target.string()));
    if (MaybeFailure failure = image::writeImageFile(image, job_.target, o_.image, !o_.noClobber)) {
      return failure;
    }
    written = printableText(job_.target.string());
  }
  output_.step("writing");
  // --stats is asked for, so it prints even when quiet.
  if (o_.stats) output_.err() << statisticsText(statistics, settings_);
  if (statistics.rays.cut > 0) {
    // Only the cap on rays a sample may trace (materials that reflect and
    // refract everything, where no branch can be left out) loses accuracy.
    output_.warning(withThousands(statistics.rays.cut) +
                    " reflected or refracted rays were not traced: their samples had traced " +
                    std::to_string(settings_.maxRaysPerSample) +
                    " already, so the picture may differ from a full trace by more than half a "
                    "level");
  }
  std::string size = std::to_string(image.width) + "x" + std::to_string(image.height);
  if (!settings_.region.empty()) {
    size += " pixels at " + std::to_string(image.originX) + "," + std::to_string(image.originY) +
            " of " + std::to_string(image.fullWidth) + "x" + std::to_string(image.fullHeight);
  }
  output_.info("wrote " + written + " (" + size + (o_.input.empty() ? ", the default scene" : "") +
               ")");
  return std::nullopt;
}

MaybeFailure RenderJob::run() {
  settings_ = o_.settings;
  settings_.width = o_.width.value_or(settings_.width);
  settings_.height = o_.height.value_or(settings_.height);
  settings_.verticalFovDegrees = o_.fov.value_or(settings_.verticalFovDegrees);
  if (MaybeFailure overLimit = settingOverLimit(settings_, o_.limits)) return overLimit;
  // A usage error, told before the scene is read and compiled.
  if (settings_.device == render::RenderDevice::Gpu && render::samplesAdaptively(settings_)) {
    return toolFailure(ExitCode::Usage,
                       "--adaptive is not done on the gpu; leave it out or use --device cpu");
  }
  if (isStandardStream(o_.input) && o_.output.empty()) {
    return toolFailure(ExitCode::Usage,
                       "the scene comes from standard input, so the image needs a name",
                       "name it with -o FILE, or -o - for a PPM on standard output");
  }
  if (MaybeFailure failure = readScene()) return failure;
  output_.step("reading");
  scene::applySceneView(job_.scene, o_.width, o_.height, o_.fov.has_value(), settings_);
  if (MaybeFailure overLimit =
          settingOverLimit(settings_, o_.limits, " (at the scene's aspect ratio)")) {
    return overLimit;
  }
  if (MaybeFailure failure = chooseRegion()) return failure;
  chooseTarget();
  if (MaybeFailure failure = targetRefusal()) return failure;
  image::fitRenderToImage(job_.toStdout ? fs::path("standard output.ppm") : job_.target, o_.image,
                          settings_);
  // Step 2: render, with a progress bar on a terminal, if it fits in memory
  // and its threads start.
  if (MaybeFailure failure = resourceRefusal()) return failure;
  stage_.set("preparing the scene");
  // The lights' direction grids serve the CPU path only, where they pay.
  const bool lightGrids =
      settings_.device != render::RenderDevice::Gpu &&
      render::RenderScene::lightGridsPay(objectCount_, render::uniformSampleCount(settings_));
  // The tree's kind by the whole image's samples, as every tool's render
  // of it, and each of its regions, chooses it.
  render::RenderScene compiled =
      std::move(*builder_).finish(job_.scene, lightGrids, render::fullImageSampleCount(settings_));
  builder_.reset();
  output_.step("preparing the scene");
  render::RenderStatistics statistics;
  render::ProgressCallback progress;
  ProgressLine progressLine(output_.err());
  if (output_.streams().errIsTerminal && !o_.common.quiet) {
    auto start = std::chrono::steady_clock::now();
    progress = [&progressLine, start](int done, int total) {
      std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
      progressLine.update(done, total, elapsed.count());
    };
  }
  stage_.set("rendering");
  render::Image image;
  try {
    if (sharedGpu_) {
      // Once a scene has opened it, --device auto asks it instead of probing.
      settings_.gpu = sharedGpu_->get();
      if (!settings_.gpu && render::chooseDevice(settings_) == render::RenderDevice::Gpu) {
        *sharedGpu_ = std::make_unique<render::GpuDevice>();
        output_.detail("opened " + (*sharedGpu_)->name() + " for the scenes on the gpu");
        settings_.gpu = sharedGpu_->get();
      }
    }
    image = render::renderImage(compiled, settings_, &statistics, progress);
  } catch (const render::DeviceUnavailable& e) {
    return toolFailure(ExitCode::OutOfResources,
                       std::string("cannot render on the gpu: ") + e.what() +
                           "; install a Vulkan driver with shaderFloat64 (mesa-vulkan-drivers "
                           "gives lavapipe) or use --device cpu");
  }
  output_.step("rendering");
  // The scene and its compiled form are freed while the image is written:
  // at 1,000,000 objects their destructors took 8 ms, and the heap they
  // leave, handed back to the system, 25 ms more at the process's exit.
  std::vector<StageMemory> held = stagesHeld(compiled, image);
  ReleasedScene aside(std::move(job_.scene), std::move(compiled));
  MaybeFailure failure = writeImage(image, statistics);
  // The peak as it stands once the image is written, whose bytes it counts.
  if (!failure) output_.detail(memoryReportText(held, peakResidentBytes(), objectCount_));
  return failure;
}

// --merge: the regions in o.inputs, one image in o.output (region_merge.h).
MaybeFailure mergeRegions(const SfrenderOptions& o, ToolOutput& output, Stage& stage) {
  if (o.inputs.empty()) {
    return toolFailure(ExitCode::Usage, "--merge needs the regions to merge",
                       "sfrender --merge tile-*.exr -o image.png");
  }
  if (o.output.empty() || isStandardStream(o.output)) {
    return toolFailure(ExitCode::Usage, "--merge needs -o FILE, the image to write");
  }
  if (o.image.alpha) {
    return toolFailure(ExitCode::Usage,
                       "--merge puts RGB regions together; --alpha is for a render");
  }
  if (MaybeFailure refusal = image::imageRefusal(o.output, o.image)) return refusal;
  OutputPlan plan;
  for (const std::string& input : o.inputs) plan.addInput(input);
  plan.addOutput(o.output, {});
  if (std::optional<OutputClash> clash = plan.firstClash()) {
    return toolFailure(ExitCode::InvalidInput, "the output '" + printableText(o.output) +
                                                   "' is the input file '" +
                                                   printableText(plan.input(clash->other)) +
                                                   "'; sfrender never writes over its input");
  }
  if (o.noClobber && pathExists(o.output)) {
    return fileFailure(ExitCode::IoError, o.output, kNoClobberMessage);
  }
  stage.set("merging " + std::to_string(o.inputs.size()) + " regions");
  std::vector<fs::path> files(o.inputs.begin(), o.inputs.end());
  Outcome<render::Image> image = image::mergeImageRegions(files, o.limits.maxPixels);
  if (!image) {
    ToolFailure failure = image.failure();
    failure.message = printableText(failure.message);
    return failure;
  }
  output.step("merging");
  if (MaybeFailure failure = image::writeImageFile(*image, o.output, o.image, !o.noClobber)) {
    return failure;
  }
  output.info("wrote " + printableText(o.output) + " (" + std::to_string(image->width) + "x" +
              std::to_string(image->height) + ", from " + std::to_string(o.inputs.size()) +
              " regions)");
  return std::nullopt;
}

// The image of each scene of a batch: -o's pattern expanded, or without
// -o each scene's own (read ahead), checked together before the first
// render (output_plan.h), into `targets`; a usage error when the batch
// cannot go ahead.
MaybeFailure batchTargets(const SfrenderOptions& o, std::vector<std::optional<fs::path>>& targets) {
  if (!o.output.empty()) {
    Outcome<std::vector<std::string>> expanded = batchOutputs(o.output, o.inputs);
    if (!expanded) return expanded.failure();
    targets.assign(expanded->begin(), expanded->end());
  } else if (MaybeFailure refusal = batchInputsRefusal(o.inputs)) {
    return refusal;
  } else {
    scene::ReadOptions read = o.read;
    read.threads = static_cast<unsigned>(renderThreadCount(o.settings.threads));
    targets = readAheadImageTargets(o.inputs, read);
  }
  OutputPlan plan;
  for (const std::string& input : o.inputs) plan.addInput(input);
  for (std::size_t i = 0; i < o.inputs.size(); ++i) {
    if (targets[i]) plan.addOutput(targets[i]->string(), o.inputs[i]);
  }
  if (std::optional<OutputClash> clash = plan.firstClash()) {
    return toolFailure(
        ExitCode::Usage,
        plan.describe(*clash) + "; a batch writes each image once, and never over an input",
        clash->overInput   ? "write the images to a folder of their own, such as -o "
                             "'out/{stem}.png'"
        : o.output.empty() ? "name the images with -o, such as -o '{dir}/{stem}.png'"
                           : "use {dir} or {name} in -o");
  }
  return std::nullopt;
}

// Several scenes: each rendered as if alone, the batch going on past one
// that fails (its failure reported where it ends), then the summary; the
// batch ends with the first failure's status.
MaybeFailure renderBatch(const SfrenderOptions& o, ToolOutput& output,
                         const AvailableMemoryProbe& availableMemory, Stage& stage) {
  std::vector<std::optional<fs::path>> targets;
  if (MaybeFailure failure = batchTargets(o, targets)) return failure;
  int rendered = 0;
  MaybeFailure first;
  std::unique_ptr<render::GpuDevice> gpu;
  for (std::size_t i = 0; i < o.inputs.size(); ++i) {
    SfrenderOptions one = o;
    one.input = o.inputs[i];
    // With -o each image is named; without, each scene's own is checked
    // against what was read ahead.
    if (!o.output.empty()) one.output = targets[i]->string();
    const std::optional<fs::path>* planned = o.output.empty() ? &targets[i] : nullptr;
    if (MaybeFailure failure =
            RenderJob(one, output, availableMemory, stage, &gpu, planned).run()) {
      output.report(*failure);
      if (!first) first = toldFailure(failure->code);
    } else {
      ++rendered;
    }
  }
  if (!o.common.quiet || rendered < static_cast<int>(o.inputs.size())) {
    output.err() << batchSummary("sfrender", rendered, static_cast<int>(o.inputs.size()),
                                 "scenes rendered")
                 << "\n";
  }
  return first;
}

// What the command line asks: a merge, a batch or one scene.
MaybeFailure runCommand(SfrenderOptions& options, ToolOutput& output,
                        const AvailableMemoryProbe& availableMemory, Stage& stage) {
  if (options.merge) return mergeRegions(options, output, stage);
  if (options.inputs.size() > 1) return renderBatch(options, output, availableMemory, stage);
  if (!options.inputs.empty()) options.input = options.inputs.front();
  if (!options.input.empty() && hasPlaceholder(options.output)) {
    // One scene of a batch (a Slurm task's slice may hold one): the pattern
    // names its image, and no summary follows.
    Outcome<std::string> named = expandOutputPattern(options.output, options.input);
    if (!named) return named.failure();
    options.output = *named;
  }
  return RenderJob(options, output, availableMemory, stage).run();
}

int renderToFile(int argc, const char* const* argv, const ToolStreams& streams,
                 const AvailableMemoryProbe& availableMemory, Stage& stage) {
  SfrenderOptions options;
  std::unique_ptr<CLI::App> app = makeSfrenderCommandLine(options);
  if (auto stop = parseCommandLine(*app, argc, argv, streams.out, streams.err)) {
    return toInt(*stop);
  }
  ToolOutput output("sfrender", streams, options.common);
  MaybeFailure failure = runCommand(options, output, availableMemory, stage);
  return failure ? output.report(*failure) : toInt(ExitCode::Success);
}

}  // namespace

int runSfrender(int argc, const char* const* argv, const ToolStreams& streams,
                const AvailableMemoryProbe& availableMemory) {
  Stage stage;
  return runGuarded("sfrender", streams.err, stage,
                    [&] { return renderToFile(argc, argv, streams, availableMemory, stage); });
}

}  // namespace tools
