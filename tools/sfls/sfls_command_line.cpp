#include "tools/sfls/sfls_command_line.h"

#include <CLI/CLI.hpp>

#include "tools/sfls/lsp_diagnostics.h"
#include "tools/sfls/server.h"

namespace sfls {

std::unique_ptr<CLI::App> makeSflsCommandLine(SflsOptions& options) {
  std::unique_ptr<CLI::App> app = tools::makeToolApp(
      "sfls",
      "The language server of scene files, instruction files and POV-Ray scenes (and glTF's "
      "diagnostics): the Language Server Protocol over standard input and output",
      options.common);
  app->add_flag("--stdio", options.stdio,
                "messages over standard input and output (the only transport; accepted as "
                "clients pass it)");
  app->footer(
      "Exit status:\n"
      "  0  exit after shutdown\n"
      "  1  exit without shutdown, the input ended, or a message's header could not be read\n"
      "  2  the command line is wrong");
  return app;
}

int runSfls(int argc, const char* const* argv, tools::ToolStreams streams) {
  SflsOptions options;
  std::unique_ptr<CLI::App> app = makeSflsCommandLine(options);
  if (auto stop = tools::parseCommandLine(*app, argc, argv, streams.out, streams.err)) {
    return static_cast<int>(*stop);
  }
  ServerOptions serverOptions;
  serverOptions.diagnosticsDocUri = diagnosticsDocUri();
  serverOptions.verbose = options.common.verbose;
  Server server(streams.in, streams.out, streams.err, std::move(serverOptions));
  return server.run();
}

}  // namespace sfls
