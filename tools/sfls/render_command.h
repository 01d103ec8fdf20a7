// The scenefile.render command: the document, as the editor holds it,
// ray traced to an image file beside it, through sfrender's own pieces
// (the renderer, the image writers, the checked write).
#pragma once

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "renderer/render_progress.h"

namespace sfls {

struct RenderRequest {
  // The document's text: what the editor shows, saved or not.
  std::string text;
  // The document's file: the image goes beside it, and an instruction
  // file's OUTPUT_FILE is taken in its folder.
  std::filesystem::path file;
  // The command's arguments: null, or an object with sfrender's names and
  // ranges: width, height, spp, depth, fov, seed, threads, adaptive (the
  // --adaptive threshold), output (a path, relative to the document's
  // folder). What is left out takes sfrender's default.
  nlohmann::json arguments;
};

struct RenderOutcome {
  // The image written; nothing when none was.
  std::optional<std::filesystem::path> image;
  // Why no image was written (an argument, the document's errors, the
  // write), as one sentence; empty on success.
  std::string failure;
  // The render was cancelled: nothing was written.
  bool cancelled = false;
};

// Called from the render's threads with the part done (0 to 1) and what is
// being done, for $/progress.
using RenderProgress = std::function<void(double fraction, std::string_view message)>;

// Renders `request`'s document to an image: `output` where given, else an
// instruction file's OUTPUT_FILE in the document's folder (refused, as by
// sfrender, when it leaves the folder), else the document's stem with .png
// beside it (PNG rather than sfrender's PPM: editors show PNG). Setting
// `cancel` from another thread stops the render within a row of pixels;
// nothing is written then.
RenderOutcome renderDocument(const RenderRequest& request, const RenderProgress& progress,
                             const render::CancelFlag& cancel);

}  // namespace sfls
