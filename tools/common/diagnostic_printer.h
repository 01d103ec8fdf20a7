// How the tools show diagnostics: the compilers' text form, or JSON.
#pragma once

#include <ostream>

#include <nlohmann/json.hpp>

#include "libscene/diagnostic.h"

namespace tools {

enum class DiagnosticFormat { Text, Json };

// FILE:LINE:COLUMN: error: message [code], then "  hint: ..." and one line per
// note. With `warningsAsErrors`, warnings print as errors.
void printDiagnostic(const scene::Diagnostic& d, std::ostream& out, bool warningsAsErrors = false);
void printDiagnostics(const scene::DiagnosticList& list, std::ostream& out,
                      bool warningsAsErrors = false);

nlohmann::json diagnosticToJson(const scene::Diagnostic& d, bool warningsAsErrors = false);
nlohmann::json diagnosticsToJson(const scene::DiagnosticList& list, bool warningsAsErrors = false);

}  // namespace tools
