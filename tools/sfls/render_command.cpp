#include "tools/sfls/render_command.h"

#include <CLI/CLI.hpp>
#include <cstdint>
#include <exception>
#include <new>
#include <string>
#include <utility>

#include "image/image_file.h"
#include "renderer/adaptive_sampling.h"
#include "renderer/render.h"
#include "renderer/render_memory.h"
#include "renderer/saturating.h"
#include "scenefile/validation.h"
#include "tools/common/document_check.h"
#include "tools/common/file_io.h"
#include "tools/common/option_checks.h"
#include "tools/common/output_file_format.h"
#include "tools/common/output_location.h"
#include "tools/common/output_plan.h"
#include "tools/sfrender/scene_view.h"
#include "tools/sfrender/sfrender.h"
#include "tools/sfrender/thread_probe.h"

namespace sfls {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Why the render cannot go ahead, as one sentence; nothing when it can.
using Refusal = std::optional<std::string>;

// sfrender's flags as the command's arguments, after they are read.
struct RenderArguments {
  std::optional<int> width;
  std::optional<int> height;
  std::optional<double> fov;
  render::RenderSettings settings;
  std::optional<std::string> output;
};

// A number argument, checked by the very check of sfrender's flag of that
// name, so that the range and the words are the same: "spp: 0 is not
// between 1 and 1024". The check rewrites the value as text that reads
// back to exactly that number.
template <typename Number>
Refusal readNumber(const json& value, const std::string& name, const CLI::Validator& check,
                   Number& into) {
  if (!value.is_number()) return name + ": " + value.dump() + " is not a number";
  std::string text = value.dump();
  if (std::string error = check(text); !error.empty()) return name + ": " + error;
  if constexpr (std::is_floating_point_v<Number>) {
    into = std::stod(text);
  } else {
    into = static_cast<Number>(std::stoll(text));
  }
  return std::nullopt;
}

template <typename Number>
Refusal readNumber(const json& value, const std::string& name, const CLI::Validator& check,
                   std::optional<Number>& into) {
  Number number{};
  if (Refusal refusal = readNumber(value, name, check, number)) return refusal;
  into = number;
  return std::nullopt;
}

Refusal readArgument(const std::string& name, const json& value, RenderArguments& a) {
  const tools::RenderLimits limits;
  render::RenderSettings& s = a.settings;
  if (name == "width")
    return readNumber(value, name, tools::wholeNumberIn(1, scene::kMaxImageSide), a.width);
  if (name == "height") {
    return readNumber(value, name, tools::wholeNumberIn(1, scene::kMaxImageSide), a.height);
  }
  if (name == "fov") {
    return readNumber(value, name, tools::numberIn(scene::kMinFovDegrees, scene::kMaxFovDegrees),
                      a.fov);
  }
  if (name == "spp") {
    return readNumber(value, name, tools::wholeNumberIn(1, limits.maxSpp), s.samplesPerPixel);
  }
  if (name == "depth") {
    return readNumber(value, name, tools::wholeNumberIn(0, limits.maxDepth), s.maxDepth);
  }
  if (name == "threads") return readNumber(value, name, tools::wholeNumberIn(0, 1024), s.threads);
  if (name == "seed") {
    return readNumber(value, name,
                      tools::wholeNumberIn(0, std::numeric_limits<std::int64_t>::max()), s.seed);
  }
  if (name == "adaptive") {
    return readNumber(value, name, tools::numberAbove(0, 1), s.adaptiveThreshold);
  }
  if (name == "output") {
    if (!value.is_string() || value.get<std::string>().empty()) {
      return "output: " + value.dump() + " is not the name of an image file";
    }
    a.output = value.get<std::string>();
    return std::nullopt;
  }
  return "unknown argument '" + name +
         "'; the arguments are width, height, fov, spp, depth, threads, seed, adaptive and output";
}

// The command's arguments: nothing, an object, or the LSP's array of
// arguments holding one.
Refusal readArguments(const json& given, RenderArguments& a) {
  const json* object = &given;
  if (given.is_array() && given.size() <= 1) {
    if (given.empty()) return std::nullopt;
    object = &given.front();
  }
  if (object->is_null()) return std::nullopt;
  if (!object->is_object()) {
    return "the arguments are " + object->dump() + ", not an object such as {\"width\": 800}";
  }
  for (const auto& [name, value] : object->items()) {
    if (Refusal refusal = readArgument(name, value, a)) return refusal;
  }
  return std::nullopt;
}

std::string describe(const tools::ToolFailure& failure) {
  return failure.file.empty() ? failure.message : failure.file + ": " + failure.message;
}

// The first error of a document that does not render, as sfcheck prints
// it on one line.
std::string firstError(const scene::DiagnosticList& diagnostics) {
  std::size_t errors = diagnostics.errorCount();
  for (const scene::Diagnostic& d : diagnostics.items()) {
    if (d.severity != scene::Severity::Error) continue;
    std::string where =
        d.span.known() ? std::to_string(d.span.line) + ":" + std::to_string(d.span.column) + ": "
                       : "";
    std::string more = errors > 1 ? " (and " + std::to_string(errors - 1) + " more)" : "";
    return "the document has errors: " + where + d.message + more;
  }
  return "the document has errors";
}

// Where the image goes: `output` in the document's folder, else the
// scene's OUTPUT_FILE there (refused where sfrender refuses it), else the
// document's stem with .png beside it.
std::variant<fs::path, std::string> imageTarget(const RenderRequest& request,
                                                const RenderArguments& arguments,
                                                const scene::Scene& scene) {
  fs::path folder = request.file.parent_path();
  fs::path target;
  if (arguments.output) {
    target = folder / *arguments.output;
  } else if (scene.outputFile) {
    scene::DiagnosticList refused(request.file.string());
    scene::checkOutputLocation(scene, folder, scene::Severity::Error, refused);
    tools::checkOutputFileFormat(scene, scene::Severity::Error, refused);
    if (refused.hasErrors()) return firstError(refused);
    target = folder / *scene.outputFile;
  } else {
    target = folder / (request.file.stem().string() + ".png");
  }
  if (tools::writesOverInput(request.file.string(), target.string())) {
    return "the image '" + target.string() + "' is the document; a render never writes over it";
  }
  return target;
}

// The limits sfrender holds a render to, and whether it fits in memory.
Refusal resourceRefusal(const render::RenderSettings& s, const scene::Scene& scene) {
  const tools::RenderLimits limits;
  std::int64_t pixels = std::int64_t{s.width} * s.height;
  if (pixels > limits.maxPixels) {
    return "width and height make " + std::to_string(pixels) + " pixels, more than the limit of " +
           std::to_string(limits.maxPixels);
  }
  int threads = tools::renderThreadCount(s.threads);
  render::RenderMemoryEstimate estimate = render::estimateRenderMemory(
      scene.objects.size(), scene.lights.size(), s.width, s.height, s.coverage);
  if (s.adaptiveThreshold > 0) {
    estimate.image = render::saturatingSum(
        estimate.image,
        render::adaptiveSamplingBytes(s.width, s.height, threads, render::kRenderTileSize));
  }
  return render::renderMemoryRefusal(estimate, render::readAvailableMemory());
}

RenderOutcome refused(std::string why) {
  return {std::nullopt, std::move(why), false};
}

RenderOutcome cancelledOutcome() {
  return {std::nullopt, "the render was cancelled", true};
}

// Renders the checked scene to `target`.
RenderOutcome renderScene(const scene::Scene& scene, render::RenderSettings settings,
                          const fs::path& target, const RenderProgress& progress,
                          const render::CancelFlag& cancel) {
  const image::ImageOptions imageOptions;
  if (tools::MaybeFailure failure = image::imageRefusal(target, imageOptions)) {
    return refused(describe(*failure));
  }
  if (tools::MaybeFailure failure = tools::checkCanWrite(target, false, 0)) {
    return refused(target.string() + ": cannot write the image: " + failure->message);
  }
  image::fitRenderToImage(target, imageOptions, settings);
  if (progress) progress(0, "preparing the scene");
  render::RenderScene compiled(scene, tools::renderThreadCount(settings.threads), true);
  if (cancel.requested()) return cancelledOutcome();
  std::string rendering =
      "rendering " + std::to_string(settings.width) + "x" + std::to_string(settings.height);
  render::ProgressCallback tiles;
  if (progress) {
    tiles = [&](int done, int total) {
      progress(total > 0 ? static_cast<double>(done) / total : 1.0, rendering);
    };
  }
  render::Image image;
  try {
    image = render::renderImage(compiled, settings, nullptr, tiles, &cancel);
  } catch (const render::RenderCancelled&) {
    return cancelledOutcome();
  }
  if (cancel.requested()) return cancelledOutcome();
  if (progress) progress(1, "writing " + target.string());
  if (tools::MaybeFailure failure = image::writeImageFile(image, target, imageOptions, true)) {
    return refused(describe(*failure));
  }
  return {target, {}, false};
}

}  // namespace

RenderOutcome renderDocument(const RenderRequest& request, const RenderProgress& progress,
                             const render::CancelFlag& cancel) {
  RenderArguments arguments;
  if (Refusal refusal = readArguments(request.arguments, arguments)) return refused(*refusal);
  scene::ReadOptions read;
  read.threads = static_cast<unsigned>(tools::renderThreadCount(arguments.settings.threads));
  tools::DocumentCheck checked =
      tools::checkDocument(request.text, request.file.string(), request.file.parent_path(), read);
  const scene::ReadResult& result = checked.result;
  if (!result.ok()) return refused(firstError(result.diagnostics));
  if (cancel.requested()) return cancelledOutcome();
  std::variant<fs::path, std::string> target = imageTarget(request, arguments, result.scene);
  if (std::string* why = std::get_if<std::string>(&target)) return refused(std::move(*why));

  render::RenderSettings settings = arguments.settings;
  settings.width = arguments.width.value_or(settings.width);
  settings.height = arguments.height.value_or(settings.height);
  settings.verticalFovDegrees = arguments.fov.value_or(settings.verticalFovDegrees);
  tools::applySceneView(result.scene, arguments.width, arguments.height, arguments.fov.has_value(),
                        settings);
  if (Refusal refusal = resourceRefusal(settings, result.scene)) return refused(*refusal);
  try {
    return renderScene(result.scene, settings, std::get<fs::path>(target), progress, cancel);
  } catch (const std::bad_alloc&) {
    return refused("the render ran out of memory");
  }
}

}  // namespace sfls
