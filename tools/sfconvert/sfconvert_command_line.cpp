// sfconvert's options: what --help, the man page and the completion show.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "scenefile/format.h"
#include "scenefile/validation.h"
#include "tools/common/input_limits.h"
#include "tools/common/option_checks.h"
#include "tools/sfconvert/sfconvert.h"

namespace tools {

namespace {

// The --to names of the format registry.
std::vector<std::string> formatNameList() {
  std::vector<std::string> names;
  for (const scene::FormatInfo& row : scene::formats()) names.emplace_back(row.name);
  return names;
}

void addViewOptions(CLI::App& app, SfconvertOptions& o) {
  app.add_option("--fov", o.fov,
                 "glTF and POV-Ray: the camera's vertical field of view in degrees, sfrender's "
                 "(default: the input's, else 60)")
      ->option_text("DEGREES")
      ->transform(numberIn(scene::kMinFovDegrees, scene::kMaxFovDegrees));
  app.add_option("--width", o.width,
                 "glTF and POV-Ray: the image width, for the camera's aspect ratio (POV-Ray "
                 "input: image_width)")
      ->transform(wholeNumberIn(1, scene::kMaxImageSide));
  app.add_option("--height", o.height,
                 "glTF and POV-Ray: the image height, for the camera's aspect ratio (POV-Ray "
                 "input: image_height)")
      ->transform(wholeNumberIn(1, scene::kMaxImageSide));
}

void addFormatOptions(CLI::App& app, SfconvertOptions& o) {
  app.add_flag("--external-buffers", o.externalBuffers,
               "glTF: write the buffer to NAME.bin beside NAME.gltf instead of embedding it");
  app.add_option("--tessellation", o.tessellation,
                 "glTF and OBJ: segments around a sphere or cylinder (the sphere gets half as many "
                 "rings)")
      ->transform(wholeNumberIn(scene::kMinSegments, scene::kMaxSegments));
  app.add_flag("--no-lights", o.noLights,
               "glTF: leave the lights out (each reported), for readers that refuse "
               "KHR_lights_punctual, as assimp 5.2 does");
  app.add_flag("--no-extras", o.noExtras,
               "glTF: leave out the exact values kept in extras (reported), for readers that "
               "cannot copy them, as assimp 5.2's export; the file reads back by mesh fitting");
  app.add_option("--light-falloff", o.lightFalloff,
                 "glTF: how the viewer's point lights fall off, which their intensities are made "
                 "for: inverse-square (glTF's rule: Blender, three.js; default) or none (f3d 1.3)")
      ->option_text("RULE")
      ->check(oneOf({"inverse-square", "none"}));
  app.add_flag("--flat", o.flat,
               "POV-Ray output: every object unlit in a colour of its own (an object-identity "
               "picture)");
  app.add_flag("--skip-unsupported", o.skipUnsupported,
               "POV-Ray input: skip what is outside the subset, with a warning, and convert the "
               "rest");
}

}  // namespace

std::unique_ptr<CLI::App> makeSfconvertCommandLine(SfconvertOptions& o) {
  std::unique_ptr<CLI::App> app =
      makeToolApp("sfconvert", "Converts between " + scene::describeFormats(), o.common);
  app->add_option("files", o.files,
                  "INPUT OUTPUT: the scene to read (its format recognised from its content; - "
                  "reads standard input) and the file to write (its format from its extension; "
                  "- writes standard output); with -o, the scenes to read")
      ->required();
  app->add_option("-o,--output", o.outputPattern,
                  "the file to write for each input, a pattern for several: {stem} (the input's "
                  "name without extension), {name}, {dir}; several go on past a failed one")
      ->option_text("PATTERN");
  app->add_option("--to", o.to,
                  "the output format, instead of the output's extension: " + scene::formatNames())
      ->option_text("FORMAT")
      ->check(oneOf(formatNameList()));
  app->add_flag("--no-loss", o.noLoss, "fail instead of dropping anything the output cannot hold");
  app->add_flag("--no-clobber", o.noClobber, "never write over an existing file");
  app->add_flag("--approximate", o.approximate,
                "write the nearest expressible matrix or camera and report how far it moved");
  app->add_flag("--transpose-matrices", o.transpose,
                "read each scene-file matrix column by column (repairs files written transposed)");
  addViewOptions(*app, o);
  addFormatOptions(*app, o);
  app->add_option("--format", o.format,
                  "how to print diagnostics on standard error: text (quoting the source), short "
                  "(a line each) or json")
      ->option_text("FORMAT")
      ->check(oneOf({"text", "short", "json"}));
  addReadLimitOptions(*app, o.read);
  return app;
}

}  // namespace tools
