/// @file
/// Diagnostics as text, in the three forms the command-line tools print
/// (docs/DIAGNOSTICS.md, "Output"): the compilers' text form quoting the
/// source, the short form of one line each, and JSON.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "scenefile/diagnostic.h"
#include "scenefile/source_excerpt.h"

namespace scene {

/// How formatDiagnostics writes each diagnostic.
enum class DiagnosticForm {
  /// `FILE:LINE:COLUMN: error: message [code]`, the source line quoted with
  /// a caret under the span, then the hint and the notes.
  Text,
  /// The text form without the quotes: a line a diagnostic (and one a hint
  /// and a note), as rustc's short error format.
  Short,
  /// A JSON array, one object a diagnostic: file, severity, code, message,
  /// line, column, length, endLine and endColumn (the column just past the
  /// span, as in SARIF and LSP), hint, notes and fixIt.
  Json,
};

/// The form named `name` ("text", "short", "json"); nothing for any other
/// name.
std::optional<DiagnosticForm> diagnosticFormFromName(std::string_view name);

/// What formatDiagnostics is told besides the form.
struct DiagnosticFormOptions {
  DiagnosticForm form = DiagnosticForm::Text;
  /// The text form quotes the source lines it was given (SourceExcerpts).
  bool quoteSource = true;
  /// The text forms colour the location, the severity and the caret with
  /// a terminal's escape sequences.
  bool color = false;
  /// A warning is shown as an error.
  bool warningsAsErrors = false;
  /// Diagnostics of a lower severity (as shown) are left out, in every form:
  /// Severity::Error shows only errors.
  Severity lowestSeverity = Severity::Note;
  /// A diagnostic's hint in the caller's words, each remedy named as the
  /// caller names the setting (scene::hintText); empty: settingHintText.
  /// A hint it gives as empty text is left out.
  std::function<std::string(const Diagnostic&)> hint;
};

/// The hint of `d` with each remedy said by its setting's name
/// (settingName) and, where it has one, its value: "raise the limit with
/// max-file-size=2000000".
std::string settingHintText(const Diagnostic& d);

/// `list` in `options.form`: for the text forms, each line ended by a
/// newline, nothing for an empty list; for JSON, the array indented by two
/// spaces and a newline. `sources` holds the lines the text form quotes;
/// without it nothing is quoted. Text from the input is written as
/// printableText shows it.
std::string formatDiagnostics(const DiagnosticList& list, const DiagnosticFormOptions& options = {},
                              const SourceExcerpts* sources = nullptr);

/// One diagnostic as formatDiagnostics writes it in a text form (JSON: the
/// one object, unindented); empty where its severity is not shown.
std::string formatDiagnostic(const Diagnostic& d, const DiagnosticFormOptions& options = {},
                             const SourceExcerpts* sources = nullptr);

}  // namespace scene
