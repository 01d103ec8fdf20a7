// sfrender's options: what --help, the man page and the completion show.
#include <CLI/CLI.hpp>
#include <map>
#include <string>

#include "image/image_file.h"
#include "scenefile/validation.h"
#include "tools/common/input_limits.h"
#include "tools/common/option_checks.h"
#include "tools/sfrender/image_region.h"
#include "tools/sfrender/sfrender.h"

namespace tools {

namespace {

// The hard ceilings of --spp and --depth, whatever the --max- flags say: far
// beyond any useful render (65536 samples was the cap before the flags).
constexpr int kSppCeiling = 65536;
constexpr int kDepthCeiling = 1000;

void addImageOptions(CLI::App& app, SfrenderOptions& o) {
  // A view's range (scene::checkView): kMaxImageSide a side keeps width *
  // height within an int whatever --max-pixels.
  app.add_option("--width", o.width,
                 "image width in pixels (default: 640, or from the height at the scene's aspect "
                 "ratio)")
      ->transform(wholeNumberIn(1, scene::kMaxImageSide));
  app.add_option("--height", o.height,
                 "image height in pixels (default: 480, or from the width at the scene's aspect "
                 "ratio)")
      ->transform(wholeNumberIn(1, scene::kMaxImageSide));
  app.add_option("--fov", o.fov,
                 "vertical field of view in degrees (default: the scene's, else 60)")
      ->option_text("DEGREES")
      ->transform(numberIn(scene::kMinFovDegrees, scene::kMaxFovDegrees));
  // --spp and --depth are held to the --max- flags below, checked after
  // parsing so that the message can name the flag that raises them.
  app.add_option("--spp", o.settings.samplesPerPixel, "samples per pixel, stratified")
      ->transform(wholeNumberIn(1, kSppCeiling));
  app.add_option("--depth", o.settings.maxDepth, "bounces of reflection and refraction")
      ->transform(wholeNumberIn(0, kDepthCeiling));
  app.add_option("--threads", o.settings.threads, "threads to read and render with (0: every core)")
      ->transform(wholeNumberIn(0, 1024));
  app.add_option_function<std::string>(
         "--device",
         [&o](const std::string& device) {
           const std::map<std::string, render::RenderDevice> devices{
               {"cpu", render::RenderDevice::Cpu},
               {"gpu", render::RenderDevice::Gpu},
               {"auto", render::RenderDevice::Auto}};
           o.settings.device = devices.at(device);
         },
         "where to trace: cpu, gpu (a Vulkan device with double precision; lavapipe counts) or "
         "auto (a real GPU when present and the image has at least a million samples for each "
         "thread of --threads, else the cpu)")
      ->check(oneOf({"cpu", "gpu", "auto"}))
      ->option_text("cpu|gpu|auto")
      ->default_str("cpu");
  app.add_option("--seed", o.settings.seed, "seed of the sample positions")
      ->transform(wholeNumberIn(0, std::numeric_limits<std::int64_t>::max()));
  app.add_option("--adaptive", o.settings.adaptiveThreshold,
                 "adaptive anti-aliasing: every pixel corner is sampled, and a pixel whose "
                 "corners differ by more than THRESHOLD (above 0, at most 1, in any channel; 0.03 "
                 "is a good start) or show different objects is cut in four, its squares again "
                 "where their corners differ by twice as much, and so on, until a pixel holds at "
                 "most --spp squares (16: 4x4, 64: 8x8); a pixel not cut whose corners differ by "
                 "more than half THRESHOLD is also sampled at its centre; with --spp 1 to 3 "
                 "nothing is refined")
      ->option_text("THRESHOLD")
      ->default_str("")  // 0, uniform sampling, is what leaving it out gives
      // Any threshold above 0 means what it says, a subnormal one too.
      ->transform(numberAbove(0, 1));
  CLI::Option* region =
      app.add_option("--region", o.region,
                     "render only the pixels from column x0 and row y0 up to, not including, x1 "
                     "and y1 of the --width x --height image; the file holds just those")
          ->option_text("x0,y0,x1,y1")
          ->check(regionOption());
  app.add_option("--tile", o.tile,
                 "render only tile i (from 0) of N: the image cut into N bands of whole rows, "
                 "their heights differing by at most one, the first at the top")
      ->option_text("i/N")
      ->check(tileOption())
      ->excludes(region);
}

void addLimitOptions(CLI::App& app, SfrenderOptions& o) {
  app.add_option("--max-pixels", o.limits.maxPixels,
                 "refuse an image, or a --merge tile's whole image, of more pixels (width x "
                 "height)")
      ->transform(wholeNumberIn(1, std::int64_t{scene::kMaxImageSide} * scene::kMaxImageSide));
  app.add_option("--max-spp", o.limits.maxSpp, "refuse more samples per pixel than this")
      ->transform(wholeNumberIn(1, kSppCeiling));
  app.add_option("--max-depth", o.limits.maxDepth, "refuse more bounces than this")
      ->transform(wholeNumberIn(0, kDepthCeiling));
  addReadLimitOptions(app, o.read);
}

}  // namespace

std::unique_ptr<CLI::App> makeSfrenderCommandLine(SfrenderOptions& o) {
  std::unique_ptr<CLI::App> app =
      makeToolApp("sfrender",
                  "Ray traces a scene, in any of " + scene::describeFormats() +
                      " (the default scene without one)",
                  o.common);
  app->add_option("scenes", o.inputs,
                  "the scenes to render, each format recognised from its content; - reads "
                  "standard input; several go on past a failed one (with --merge: the regions "
                  "to merge)");
  app->add_option("-o,--output", o.output,
                  "the image to write; its extension picks the format (listed at the end); - "
                  "writes PPM to standard output (default: the scene's name with .png, or an "
                  "instruction file's OUTPUT_FILE); for several scenes a pattern: {stem} (the "
                  "scene's name without extension), {name}, {dir}")
      ->option_text("FILE");
  app->add_flag("--merge", o.merge,
                "put the regions of one image (EXR files of --tile or --region) together into "
                "the image -o names, exactly as one render makes it");
  addImageOptions(*app, o);
  app->add_option("--bits", o.image.bits,
                  "bits a channel: 8 or 16 for integer images (PNG, TIFF, PPM), 16 (half) or 32 "
                  "(float) for EXR (default: 8, EXR 32)")
      ->default_str("")  // the description says it: it depends on the format
      ->check(oneOf({"8", "16", "32"}));
  app->add_flag("--alpha", o.image.alpha,
                "a fourth channel: how much of each pixel objects cover, the background "
                "transparent");
  // The formats OpenImageIO writes, found when --help is printed; CLI11
  // puts them before the exit statuses.
  app->footer([] { return image::imageFormatHelp(); });
  app->add_flag("--stats", o.stats,
                "print the time, the rays and the rays per second (also when quiet)");
  app->add_flag("--no-clobber", o.noClobber, "never write over an existing file");
  // As sfconvert's: the same reader option, told in the same words.
  app->add_flag("--skip-unsupported", o.read.pov.skipUnsupported,
                "POV-Ray input: skip what is outside the subset, with a warning, and render the "
                "rest");
  addLimitOptions(*app, o);
  return app;
}

}  // namespace tools
