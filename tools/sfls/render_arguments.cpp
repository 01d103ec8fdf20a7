#include "tools/sfls/render_arguments.h"

#include <CLI/CLI.hpp>
#include <limits>
#include <type_traits>

#include "renderer/adaptive_sampling.h"
#include "renderer/image.h"
#include "renderer/render_memory.h"
#include "renderer/render_settings.h"
#include "renderer/saturating.h"
#include "scenefile/render.h"
#include "scenefile/validation.h"
#include "tools/common/option_checks.h"
#include "tools/sfrender/sfrender.h"

namespace sfls {

namespace {

using nlohmann::json;

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
}  // namespace

Refusal readRenderArguments(const json& given, RenderArguments& a) {
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

render::RenderSettings renderSettingsFor(const RenderArguments& a, const scene::Scene& scene) {
  render::RenderSettings settings = a.settings;
  settings.width = a.width.value_or(settings.width);
  settings.height = a.height.value_or(settings.height);
  settings.verticalFovDegrees = a.fov.value_or(settings.verticalFovDegrees);
  scene::applySceneView(scene, a.width, a.height, a.fov.has_value(), settings);
  return settings;
}

Refusal renderResourceRefusal(const render::RenderSettings& s, const scene::Scene& scene,
                              int threads, std::optional<std::uint64_t> available) {
  const tools::RenderLimits limits;
  std::int64_t pixels = std::int64_t{s.width} * s.height;
  if (pixels > limits.maxPixels) {
    return "width and height make " + std::to_string(pixels) + " pixels, more than the limit of " +
           std::to_string(limits.maxPixels);
  }
  render::RenderMemoryEstimate estimate =
      render::estimateRenderMemory(render::renderSizeOf(scene, s));
  if (s.adaptiveThreshold > 0) {
    estimate.image = render::saturatingSum(
        estimate.image,
        render::adaptiveSamplingBytes(s.width, s.height, threads, render::kRenderTileSize));
  }
  return render::renderMemoryRefusal(estimate, available);
}

std::string firstRenderError(const scene::DiagnosticList& diagnostics) {
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

}  // namespace sfls
