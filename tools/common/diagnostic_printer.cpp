#include "tools/common/diagnostic_printer.h"

namespace tools {

namespace {

scene::Severity shownSeverity(const scene::Diagnostic& d, bool warningsAsErrors) {
  if (warningsAsErrors && d.severity == scene::Severity::Warning) return scene::Severity::Error;
  return d.severity;
}

void printLocation(const std::string& file, const scene::SourceSpan& span, std::ostream& out) {
  out << (file.empty() ? "<input>" : file) << ':';
  if (span.known()) out << span.line << ':' << span.column << ':';
}

nlohmann::json spanToJson(const scene::SourceSpan& span) {
  return {{"line", span.line}, {"column", span.column}, {"length", span.length}};
}

}  // namespace

void printDiagnostic(const scene::Diagnostic& d, std::ostream& out, bool warningsAsErrors) {
  printLocation(d.file, d.span, out);
  out << ' ' << scene::severityName(shownSeverity(d, warningsAsErrors)) << ": " << d.message
      << " [" << scene::codeName(d.code) << "]\n";
  if (!d.hint.empty()) out << "  hint: " << d.hint << '\n';
  for (const scene::DiagnosticNote& note : d.notes) {
    printLocation(d.file, note.span, out);
    out << " note: " << note.message << '\n';
  }
}

void printDiagnostics(const scene::DiagnosticList& list, std::ostream& out,
                      bool warningsAsErrors) {
  for (const scene::Diagnostic& d : list.items()) printDiagnostic(d, out, warningsAsErrors);
}

nlohmann::json diagnosticToJson(const scene::Diagnostic& d, bool warningsAsErrors) {
  nlohmann::json j = {
      {"file", d.file},
      {"severity", std::string(scene::severityName(shownSeverity(d, warningsAsErrors)))},
      {"code", std::string(scene::codeName(d.code))},
      {"message", d.message},
  };
  j.update(spanToJson(d.span));
  if (!d.hint.empty()) j["hint"] = d.hint;
  if (!d.notes.empty()) {
    nlohmann::json notes = nlohmann::json::array();
    for (const scene::DiagnosticNote& note : d.notes) {
      nlohmann::json n = spanToJson(note.span);
      n["message"] = note.message;
      notes.push_back(std::move(n));
    }
    j["notes"] = std::move(notes);
  }
  if (d.fixIt) {
    nlohmann::json fix = spanToJson(d.fixIt->span);
    fix["replacement"] = d.fixIt->replacement;
    j["fixIt"] = std::move(fix);
  }
  return j;
}

nlohmann::json diagnosticsToJson(const scene::DiagnosticList& list, bool warningsAsErrors) {
  nlohmann::json out = nlohmann::json::array();
  for (const scene::Diagnostic& d : list.items()) {
    out.push_back(diagnosticToJson(d, warningsAsErrors));
  }
  return out;
}

}  // namespace tools
