// What a tool says on standard error besides diagnostics, in one voice:
//
//   sfconvert: error: cannot tell the output format of 'out.xyz'
//     hint: use .sf, .txt, ...
//   sfconvert: wrote out.gltf (glTF 2.0)
//
// Errors always print; what the tool did prints unless --quiet; what it
// decided and how long each step took only with --verbose.
#pragma once

#include <chrono>
#include <ostream>
#include <string>
#include <string_view>

#include "scenefile/scene.h"
#include "tools/common/command_line.h"
#include "tools/common/diagnostic_printer.h"
#include "tools/common/tool_failure.h"
#include "tools/common/tool_streams.h"

namespace tools {

// "1 file", "3 errors": a count and its word, plural but for one.
std::string countOf(std::size_t n, std::string_view word);

// What a scene holds, as the tools say it: "3 objects, 1 light".
std::string sceneContents(const scene::Scene& scene);

class ToolOutput {
 public:
  ToolOutput(std::string tool, const ToolStreams& streams, const CommonFlags& flags);

  const std::string& tool() const { return tool_; }
  const ToolStreams& streams() const { return streams_; }
  const CommonFlags& flags() const { return flags_; }
  std::ostream& err() const { return streams_.err; }
  const TerminalStyle& style() const { return style_; }

  // "TOOL: error: MESSAGE", then "  hint: HINT" when there is one.
  void error(std::string_view message, std::string_view hint = {}) const;
  // "FILE: error: MESSAGE", for a file that cannot be read or written; FILE
  // as it is safe to show (printableText).
  void fileError(std::string_view file, std::string_view message) const;
  // The failure as error() or fileError() prints it (nothing more when it
  // was told already), and its exit status: where a tool's failures end.
  int report(const ToolFailure& failure) const;
  // "TOOL: warning: MESSAGE", unless quiet.
  void warning(std::string_view message) const;
  // "TOOL: MESSAGE", unless quiet: what the tool did ("wrote out.png").
  void info(std::string_view message) const;
  // "TOOL: MESSAGE" with --verbose only.
  void detail(std::string_view message) const;
  // With --verbose, "TOOL: STEP took 0.123 s" since the last call (or the
  // start), and the clock starts again.
  void step(std::string_view what);

  // How diagnostics print for these flags: coloured as --color says, the
  // source quoted unless `format` is short, only errors when quiet, notes
  // only when verbose.
  DiagnosticStyle diagnosticStyle(DiagnosticFormat format, bool warningsAsErrors = false) const;

 private:
  std::string tool_;
  const ToolStreams& streams_;
  CommonFlags flags_;
  TerminalStyle style_;
  std::chrono::steady_clock::time_point stepStart_ = std::chrono::steady_clock::now();
};

}  // namespace tools
