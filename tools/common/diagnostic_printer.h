// How the tools show diagnostics: the compilers' text form, or JSON.
#pragma once

#include <ostream>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "scenefile/diagnostic.h"

namespace tools {

enum class DiagnosticFormat { Text, Json };

// The text as it is safe to show: a message may quote bytes from a file, and
// a control byte (a terminal's escape sequence) or a byte that is not UTF-8
// is written as \xNN instead, so that printing cannot drive the terminal and
// JSON output stays valid UTF-8.
std::string printableText(std::string_view text);

// FILE:LINE:COLUMN: error: message [code], then "  hint: ..." and one line per
// note. With `warningsAsErrors`, warnings print as errors.
void printDiagnostic(const scene::Diagnostic& d, std::ostream& out, bool warningsAsErrors = false);
void printDiagnostics(const scene::DiagnosticList& list, std::ostream& out,
                      bool warningsAsErrors = false);

nlohmann::json diagnosticToJson(const scene::Diagnostic& d, bool warningsAsErrors = false);
nlohmann::json diagnosticsToJson(const scene::DiagnosticList& list, bool warningsAsErrors = false);

}  // namespace tools
