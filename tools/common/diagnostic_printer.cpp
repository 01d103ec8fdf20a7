#include "tools/common/diagnostic_printer.h"

namespace tools {

namespace {

// The length of the well-formed UTF-8 character at the start of `text`
// (RFC 3629: no overlong forms, no surrogates, nothing past U+10FFFF), or 0.
std::size_t utf8CharacterLength(std::string_view text) {
  auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  auto continuation = [&](std::size_t i) { return i < text.size() && (byte(i) & 0xC0) == 0x80; };
  unsigned char lead = byte(0);
  if (lead < 0x80) return 1;
  if (lead >= 0xC2 && lead <= 0xDF) return continuation(1) ? 2 : 0;
  if (lead >= 0xE0 && lead <= 0xEF) {
    if (!continuation(1) || !continuation(2)) return 0;
    if (lead == 0xE0 && byte(1) < 0xA0) return 0;   // overlong
    if (lead == 0xED && byte(1) >= 0xA0) return 0;  // a surrogate
    return 3;
  }
  if (lead >= 0xF0 && lead <= 0xF4) {
    if (!continuation(1) || !continuation(2) || !continuation(3)) return 0;
    if (lead == 0xF0 && byte(1) < 0x90) return 0;   // overlong
    if (lead == 0xF4 && byte(1) >= 0x90) return 0;  // past U+10FFFF
    return 4;
  }
  return 0;
}

scene::Severity shownSeverity(const scene::Diagnostic& d, bool warningsAsErrors) {
  if (warningsAsErrors && d.severity == scene::Severity::Warning) return scene::Severity::Error;
  return d.severity;
}

void printLocation(const std::string& file, const scene::SourceSpan& span, std::ostream& out) {
  out << (file.empty() ? "<input>" : printableText(file)) << ':';
  if (span.known()) out << span.line << ':' << span.column << ':';
}

nlohmann::json spanToJson(const scene::SourceSpan& span) {
  return {{"line", span.line}, {"column", span.column}, {"length", span.length}};
}

}  // namespace

std::string printableText(std::string_view text) {
  std::string shown;
  shown.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    std::size_t length = utf8CharacterLength(text.substr(i));
    unsigned char c = static_cast<unsigned char>(text[i]);
    if (length == 0 || c < 0x20 || c == 0x7F) {
      constexpr char kHex[] = "0123456789ABCDEF";
      shown += "\\x";
      shown += kHex[c >> 4];
      shown += kHex[c & 15];
      ++i;
    } else {
      shown.append(text.substr(i, length));
      i += length;
    }
  }
  return shown;
}

void printDiagnostic(const scene::Diagnostic& d, std::ostream& out, bool warningsAsErrors) {
  printLocation(d.file, d.span, out);
  out << ' ' << scene::severityName(shownSeverity(d, warningsAsErrors)) << ": "
      << printableText(d.message) << " [" << scene::codeName(d.code) << "]\n";
  if (!d.hint.empty()) out << "  hint: " << printableText(d.hint) << '\n';
  for (const scene::DiagnosticNote& note : d.notes) {
    printLocation(d.file, note.span, out);
    out << " note: " << printableText(note.message) << '\n';
  }
}

void printDiagnostics(const scene::DiagnosticList& list, std::ostream& out, bool warningsAsErrors) {
  for (const scene::Diagnostic& d : list.items()) printDiagnostic(d, out, warningsAsErrors);
}

nlohmann::json diagnosticToJson(const scene::Diagnostic& d, bool warningsAsErrors) {
  nlohmann::json j = {
      {"file", printableText(d.file)},
      {"severity", std::string(scene::severityName(shownSeverity(d, warningsAsErrors)))},
      {"code", std::string(scene::codeName(d.code))},
      {"message", printableText(d.message)},
  };
  j.update(spanToJson(d.span));
  if (!d.hint.empty()) j["hint"] = printableText(d.hint);
  if (!d.notes.empty()) {
    nlohmann::json notes = nlohmann::json::array();
    for (const scene::DiagnosticNote& note : d.notes) {
      nlohmann::json n = spanToJson(note.span);
      n["message"] = printableText(note.message);
      notes.push_back(std::move(n));
    }
    j["notes"] = std::move(notes);
  }
  if (d.fixIt) {
    nlohmann::json fix = spanToJson(d.fixIt->span);
    fix["replacement"] = printableText(d.fixIt->replacement);
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
