// sfrender's flags given as JSON (the scenefile.render command's arguments,
// the web module's render options): read with sfrender's own checks and
// words, and made into a render's settings as sfrender makes them.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "renderer/render_settings.h"
#include "scenefile/diagnostic.h"
#include "scenefile/scene.h"

namespace sfls {

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

// Reads `given` (null, an object of sfrender's names: width, height, spp,
// depth, fov, seed, threads, adaptive, output, or the LSP's array holding
// one) into `a`; each number checked by the check of sfrender's flag of
// that name: "spp: 0 is not between 1 and 1024".
Refusal readRenderArguments(const nlohmann::json& given, RenderArguments& a);

// The settings of the render: the arguments over sfrender's defaults, and
// the scene's own view where they leave it open (scene::applySceneView).
render::RenderSettings renderSettingsFor(const RenderArguments& a, const scene::Scene& scene);

// The limits sfrender holds a render on `threads` threads to (its pixels),
// and whether it fits in the `available` memory (unknown: it does).
Refusal renderResourceRefusal(const render::RenderSettings& s, const scene::Scene& scene,
                              int threads, std::optional<std::uint64_t> available);

// The first error of a document that does not render, as sfcheck prints
// it on one line.
std::string firstRenderError(const scene::DiagnosticList& diagnostics);

}  // namespace sfls
