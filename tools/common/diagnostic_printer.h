// How the tools show diagnostics: the library's three forms
// (scenefile/diagnostic_format.h) in the style a run's flags ask for.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <ostream>

#include "scenefile/diagnostic.h"
#include "scenefile/diagnostic_format.h"
#include "scenefile/printable_text.h"
#include "scenefile/source_excerpt.h"
#include "tools/common/terminal_style.h"

namespace tools {

using scene::printableText;
using scene::SourceExcerpts;

// --format: text (quoting the source), short (one line a diagnostic; what
// the tests' .expect files hold) or json.
using DiagnosticFormat = scene::DiagnosticForm;
inline constexpr auto diagnosticFormatFromName = scene::diagnosticFormFromName;

struct DiagnosticStyle {
  TerminalStyle terminal;
  bool quoteSource = true;        // the source line and caret under each message
  bool warningsAsErrors = false;  // --werror: warnings print as errors
  bool errorsOnly = false;        // --quiet: warnings and notes are not printed
  bool notesShown = true;         // notes are printed (a tool's run: with --verbose)
  // A diagnostic's hint in the running tool's words; empty: hintText.
  std::function<std::string(const scene::Diagnostic&)> hint;
};

// The library's options for a text form in `style`: hints in style.hint's
// words, else hintText's.
scene::DiagnosticFormOptions formOptions(const DiagnosticStyle& style);

// Prints diagnostics in the text forms (formatDiagnostics): the source
// quoted from `sources` where style.quoteSource, else the short form.
class DiagnosticPrinter {
 public:
  DiagnosticPrinter(std::ostream& out, DiagnosticStyle style,
                    const SourceExcerpts* sources = nullptr)
      : out_(out), style_(style), sources_(sources) {}

  void print(const scene::Diagnostic& d) const;
  void print(const scene::DiagnosticList& list) const;

 private:
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

// The JSON form as a value, for a report that holds it (sfcheck's).
nlohmann::json diagnosticsToJson(const scene::DiagnosticList& list, bool warningsAsErrors = false);

}  // namespace tools
