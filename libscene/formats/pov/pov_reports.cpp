#include "libscene/formats/pov/pov_reports.h"

#include <utility>

namespace scene {

void PovReports::fail(SourceSpan span, std::string message, std::string hint) {
  out_.error(DiagnosticCode::PovSyntax, span, std::move(message)).hint = std::move(hint);
  throw PovParseError{};
}

void PovReports::unsupported(SourceSpan span, const std::string& what, std::string hint) {
  Severity severity = options_.pov.skipUnsupported ? Severity::Warning : Severity::Error;
  Diagnostic& d = out_.report(severity, DiagnosticCode::PovUnsupported, span,
                              what + " is not supported (line " + std::to_string(span.line) + ")");
  d.hint = hint.empty() ? (options_.pov.skipUnsupported ? std::string("skipped")
                                                        : std::string("{0} converts the rest"))
                        : std::move(hint);
  if (d.hint.find("{0}") != std::string::npos) d.remedies = {{Setting::SkipUnsupported, "true"}};
}

void PovReports::loss(SourceSpan span, std::string message, std::string hint) {
  Severity severity = options_.noLoss ? Severity::Error : Severity::Warning;
  out_.report(severity, DiagnosticCode::PovLoss, span, std::move(message)).hint = std::move(hint);
}

void PovReports::ignored(SourceSpan span, std::string message, std::string hint,
                         std::vector<Remedy> remedies) {
  Diagnostic& d = out_.note(DiagnosticCode::PovIgnored, span, std::move(message));
  d.hint = std::move(hint);
  d.remedies = std::move(remedies);
}

void PovReports::refuse(SourceSpan span, std::string message, std::string hint) {
  out_.error(DiagnosticCode::PovRefused, span, std::move(message)).hint = std::move(hint);
  throw PovParseError{};
}

}  // namespace scene
