#include "tools/sfbuild/sfbuild_command_line.h"

#include <CLI/CLI.hpp>

#include "tools/common/input_limits.h"
#include "tools/common/option_checks.h"

namespace sfbuild {

std::unique_ptr<CLI::App> makeSfbuildCommandLine(SfbuildOptions& o) {
  std::unique_ptr<CLI::App> app = tools::makeToolApp(
      "sfbuild", "The interactive scene builder: P saves Scene<n>.sf in the current folder",
      o.common);
  app->footer(tools::exitStatusHelp() + "\n  5  there is no display to open a window on");
  app->add_option("scene", o.input, "a scene to open (any format sfrender reads)");
  app->add_option("--width", o.width, "window width in pixels")
      ->transform(tools::wholeNumberIn(64, 8192));
  app->add_option("--height", o.height, "window height in pixels")
      ->transform(tools::wholeNumberIn(64, 8192));
  app->add_flag("--id-view", o.idView, "draw each object in a flat colour of its own (F9 toggles)");
  tools::addReadLimitOptions(*app, o.read);
  return app;
}

}  // namespace sfbuild
