// How the tools show diagnostics: the compilers' text form, with the source
// line quoted and the span underlined (docs/DIAGNOSTICS.md, "Output"), the
// short form of one line each, or JSON.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>

#include "scenefile/diagnostic.h"
#include "tools/common/printable_text.h"
#include "tools/common/source_excerpt.h"
#include "tools/common/terminal_style.h"

namespace tools {

// --format: text (quoting the source), short (one line a diagnostic, as
// `rustc --error-format short`; what the tests' .expect files hold) or json.
enum class DiagnosticFormat { Text, Short, Json };

std::optional<DiagnosticFormat> diagnosticFormatFromName(std::string_view name);

struct DiagnosticStyle {
  TerminalStyle terminal;
  bool quoteSource = true;        // the source line and caret under each message
  bool warningsAsErrors = false;  // --werror: warnings print as errors
  bool errorsOnly = false;        // --quiet: warnings and notes are not printed
  bool notesShown = true;         // notes are printed (a tool's run: with --verbose)
  // A diagnostic's hint in the running tool's words; empty: hintText.
  std::function<std::string(const scene::Diagnostic&)> hint;
};

// Prints diagnostics in the text forms:
//
//   FILE:LINE:COLUMN: error: message [code]
//       LINE | the source line
//            |     ^~~~
//     hint: ...
//   FILE:LINE:COLUMN: note: ...
//
// A diagnostic without a place prints "FILE: error: ...", and one whose line
// was not captured (or with quoteSource off) prints no quote.
class DiagnosticPrinter {
 public:
  DiagnosticPrinter(std::ostream& out, DiagnosticStyle style,
                    const SourceExcerpts* sources = nullptr)
      : out_(out), style_(style), sources_(sources) {}

  void print(const scene::Diagnostic& d) const;
  void print(const scene::DiagnosticList& list) const;

 private:
  void printLocation(const std::string& file, const scene::SourceSpan& span) const;
  void quote(const std::string& file, const scene::SourceSpan& span,
             const scene::FixIt* fixIt) const;

  std::ostream& out_;
  DiagnosticStyle style_;
  const SourceExcerpts* sources_;
};

// The hint in the tools' words: each setting of d.remedies as the flag that
// sets it ("raise the limit with --max-file-size ..."), the tool that has
// the flag said once where the hint names it ("sfrender --fov 50 --width
// 640").
std::string hintText(const scene::Diagnostic& d);

// The short form, uncoloured: for messages built outside a tool's run.
void printDiagnostics(const scene::DiagnosticList& list, std::ostream& out);

// JSON: file, severity, code, message, line, column, length, endLine and
// endColumn (the column just past the span, as in SARIF and LSP), hint,
// notes and fixIt.
nlohmann::json diagnosticToJson(const scene::Diagnostic& d, bool warningsAsErrors = false);
nlohmann::json diagnosticsToJson(const scene::DiagnosticList& list, bool warningsAsErrors = false);

}  // namespace tools
