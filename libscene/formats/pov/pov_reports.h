// How the POV-Ray reader's layers report: the errors that abandon a
// statement, and the reports whose severity the read options decide
// (unsupported under PovReadOptions::skipUnsupported, loss under
// ReadOptions::noLoss). Shared by
// the parser and by the scene built after it, so that each rule is in one
// place.
#pragma once

#include <string>
#include <vector>

#include "scenefile/diagnostic.h"
#include "scenefile/read.h"

namespace scene {

// Thrown after an error is reported: unwinds to the statement, which then
// skips to its end.
struct PovParseError {};
// Thrown when reading must stop: a limit, or the error list is full.
struct PovStopReading {};

class PovReports {
 protected:
  PovReports(const ReadOptions& options, DiagnosticList& out) : options_(options), out_(out) {}

  // A syntax error [pov-syntax]; the statement is abandoned.
  [[noreturn]] void fail(SourceSpan span, std::string message, std::string hint = {});
  // What is outside the subset [pov-unsupported]: an error, or a warning
  // when the options skip it. "{0}" in `hint` names the option that skips.
  void unsupported(SourceSpan span, const std::string& what, std::string hint = {});
  // What the scene model cannot hold [pov-loss]: a warning, or an error
  // under noLoss.
  void loss(SourceSpan span, std::string message, std::string hint = {});
  // What POV-Ray reads and the renderer has no use for [pov-ignored]: a note.
  void ignored(SourceSpan span, std::string message, std::string hint = {},
               std::vector<Remedy> remedies = {});
  // What would read or write a file [pov-refused]; the statement is
  // abandoned.
  [[noreturn]] void refuse(SourceSpan span, std::string message, std::string hint = {});

  const ReadOptions& options_;
  DiagnosticList& out_;
};

}  // namespace scene
