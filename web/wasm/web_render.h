// The module's RenderSession: one scene, read and compiled once, rendered
// band by band as sfrender renders it, so that the page can show rows as
// they come and drop a render between two bands.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/render_scene.h"
#include "scenefile/read.h"
#include "tools/sfls/render_arguments.h"

namespace web {

class RenderSession {
 public:
  // Reads `text` (named `name` in diagnostics) and compiles its scene for
  // the settings of `optionsJson`: sfrender's names (width, height, spp,
  // adaptive, depth, fov, threads, seed), each optional; adaptive is false,
  // true (0.03) or sfrender's --adaptive threshold.
  RenderSession(std::string_view text, const std::string& name, const std::string& optionsJson);

  // {ok, diagnostics, error, width, height, spp, adaptive, depth, fov,
  // threads}: error the scene's first error, an option refused in
  // sfrender's words, or why the last band failed.
  std::string statusJson() const;

  // The 8-bit RGBA pixels (alpha 255) of rows [y0, y1) of the image of the
  // session's settings with `overridesJson` (some of width, height, spp,
  // adaptive, depth) laid over them: exactly those rows of sfrender's PNG.
  // Nothing when the band cannot be rendered; statusJson then says why.
  std::optional<std::vector<unsigned char>> renderRows(int y0, int y1,
                                                       const std::string& overridesJson);

 private:
  // The settings of `overridesJson` over the session's, or why not.
  std::optional<render::RenderSettings> settingsWith(const std::string& overridesJson);

  scene::ReadResult result_;
  sfls::RenderArguments arguments_;
  render::RenderSettings settings_;
  std::unique_ptr<render::RenderScene> compiled_;
  std::string error_;
};

// sfrender's default scene (no input) as text in a format that holds it
// exactly, and the name of a file of that format: "default.sf" or
// "default.txt".
std::string defaultSceneText();
std::string defaultSceneName();

}  // namespace web
