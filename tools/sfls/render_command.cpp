#include "tools/sfls/render_command.h"

#include <cstdint>
#include <exception>
#include <new>
#include <string>
#include <utility>

#include "image/image_file.h"
#include "renderer/render.h"
#include "renderer/render_memory.h"
#include "renderer/render_scene.h"
#include "renderer/render_settings.h"
#include "scenefile/validation.h"
#include "tools/common/document_check.h"
#include "tools/common/file_io.h"
#include "tools/common/output_file_format.h"
#include "tools/common/output_location.h"
#include "tools/common/output_plan.h"
#include "tools/sfls/render_arguments.h"
#include "tools/sfrender/thread_probe.h"

namespace sfls {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string describe(const tools::ToolFailure& failure) {
  return failure.file.empty() ? failure.message : failure.file + ": " + failure.message;
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
    if (refused.hasErrors()) return firstRenderError(refused);
    target = folder / *scene.outputFile;
  } else {
    target = folder / (request.file.stem().string() + ".png");
  }
  if (tools::writesOverInput(request.file.string(), target.string())) {
    return "the image '" + target.string() + "' is the document; a render never writes over it";
  }
  return target;
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
  // The lights' grids only where they pay, as sfrender decides.
  render::RenderScene compiled(scene, tools::renderThreadCount(settings.threads),
                               render::RenderScene::lightGridsPay(
                                   scene.objects.size(), render::uniformSampleCount(settings)),
                               render::fullImageSampleCount(settings));
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
  if (Refusal refusal = readRenderArguments(request.arguments, arguments)) return refused(*refusal);
  scene::ReadOptions read;
  read.threads = static_cast<unsigned>(tools::renderThreadCount(arguments.settings.threads));
  tools::DocumentCheck checked =
      tools::checkDocument(request.text, request.file.string(), request.file.parent_path(), read);
  const scene::ReadResult& result = checked.result;
  if (!result.ok()) return refused(firstRenderError(result.diagnostics));
  if (cancel.requested()) return cancelledOutcome();
  std::variant<fs::path, std::string> target = imageTarget(request, arguments, result.scene);
  if (std::string* why = std::get_if<std::string>(&target)) return refused(std::move(*why));

  render::RenderSettings settings = renderSettingsFor(arguments, result.scene);
  if (Refusal refusal =
          renderResourceRefusal(settings, result.scene, tools::renderThreadCount(settings.threads),
                                render::readAvailableMemory())) {
    return refused(*refusal);
  }
  try {
    return renderScene(result.scene, settings, std::get<fs::path>(target), progress, cancel);
  } catch (const std::bad_alloc&) {
    return refused("the render ran out of memory");
  }
}

}  // namespace sfls
