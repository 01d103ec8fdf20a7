#include "tools/common/diagnostic_printer.h"

#include <algorithm>
#include <vector>

namespace tools {

namespace {

scene::Severity shownSeverity(const scene::Diagnostic& d, bool warningsAsErrors) {
  if (warningsAsErrors && d.severity == scene::Severity::Warning) return scene::Severity::Error;
  return d.severity;
}

// A setting as the tools' flags say it, and the tool that has the flag
// where the hint names it (its other tools read the same option).
struct SettingFlag {
  std::string_view tool;  // said before the flag, once a hint
  std::string_view flag;
  bool showsValue;  // the value is written after the flag
};

SettingFlag settingFlag(scene::Setting setting) {
  switch (setting) {
    case scene::Setting::MaxFileSize:
      return {"", "--max-file-size", false};
    case scene::Setting::MaxObjects:
      return {"", "--max-objects", false};
    case scene::Setting::MaxGltfNodes:
      return {"", "--max-nodes", false};
    case scene::Setting::TransposedMatrices:
      return {"sfconvert", "--transpose-matrices", false};
    case scene::Setting::SkipUnsupported:
      return {"", "--skip-unsupported", false};
    case scene::Setting::Approximate:
      return {"", "--approximate", false};
    case scene::Setting::FieldOfView:
      return {"sfrender", "--fov", true};
    case scene::Setting::Width:
      return {"sfrender", "--width", true};
    case scene::Setting::Height:
      return {"sfrender", "--height", true};
    case scene::Setting::Depth:
      return {"", "--depth", true};
    case scene::Setting::OutputPath:
      return {"sfrender", "-o", true};
  }
  return {"", "", false};
}

nlohmann::json spanToJson(const scene::SourceSpan& span) {
  nlohmann::json j = {{"line", span.line}, {"column", span.column}, {"length", span.length}};
  if (span.known()) {
    j["endLine"] = span.line;
    j["endColumn"] = span.column + span.length;
  }
  return j;
}

}  // namespace

std::string hintText(const scene::Diagnostic& d) {
  std::vector<std::string_view> toolsSaid;
  return scene::hintText(d.hint, d.remedies, [&](const scene::Remedy& remedy) {
    SettingFlag words = settingFlag(remedy.setting);
    std::string text;
    if (!words.tool.empty() &&
        std::find(toolsSaid.begin(), toolsSaid.end(), words.tool) == toolsSaid.end()) {
      toolsSaid.push_back(words.tool);
      text = std::string(words.tool) + " ";
    }
    text += words.flag;
    if (words.showsValue && !remedy.value.empty()) text += " " + remedy.value;
    return text;
  });
}

std::optional<DiagnosticFormat> diagnosticFormatFromName(std::string_view name) {
  if (name == "text") return DiagnosticFormat::Text;
  if (name == "short") return DiagnosticFormat::Short;
  if (name == "json") return DiagnosticFormat::Json;
  return std::nullopt;
}

void DiagnosticPrinter::printLocation(const std::string& file,
                                      const scene::SourceSpan& span) const {
  std::string location = (file.empty() ? "<input>" : printableText(file)) + ":";
  if (span.known()) {
    location += std::to_string(span.line) + ":" + std::to_string(span.column) + ":";
  }
  out_ << style_.terminal.location(location);
}

void DiagnosticPrinter::quote(const std::string& file, const scene::SourceSpan& span,
                              const scene::FixIt* fixIt) const {
  if (!style_.quoteSource || !sources_) return;
  const SourceLine* line = sources_->find(file, span);
  if (!line) return;
  for (const std::string& text : quoteSourceLine(*line, span, fixIt, style_.terminal)) {
    out_ << text << '\n';
  }
}

void DiagnosticPrinter::print(const scene::Diagnostic& d) const {
  scene::Severity severity = shownSeverity(d, style_.warningsAsErrors);
  if (style_.errorsOnly && severity != scene::Severity::Error) return;
  if (!style_.notesShown && severity == scene::Severity::Note) return;
  const TerminalStyle& paint = style_.terminal;
  printLocation(d.file, d.span);
  std::string name(scene::severityName(severity));
  out_ << ' ' << paint.severity(severity, name + ":") << ' ' << printableText(d.message) << " ["
       << paint.severity(severity, scene::codeName(d.code)) << "]\n";
  quote(d.file, d.span, d.fixIt ? &*d.fixIt : nullptr);
  // The running tool's words may leave no hint (the advice is followed already).
  std::string hint = d.hint.empty() ? std::string() : style_.hint ? style_.hint(d) : hintText(d);
  if (!hint.empty()) out_ << "  " << paint.location("hint:") << ' ' << printableText(hint) << '\n';
  for (const scene::DiagnosticNote& note : d.notes) {
    printLocation(d.file, note.span);
    out_ << ' ' << paint.severity(scene::Severity::Note, "note:") << ' '
         << printableText(note.message) << '\n';
    quote(d.file, note.span, nullptr);
  }
}

void DiagnosticPrinter::print(const scene::DiagnosticList& list) const {
  for (const scene::Diagnostic& d : list.items()) print(d);
}

void printDiagnostics(const scene::DiagnosticList& list, std::ostream& out) {
  DiagnosticStyle style;
  style.quoteSource = false;
  DiagnosticPrinter(out, style).print(list);
}

nlohmann::json diagnosticToJson(const scene::Diagnostic& d, bool warningsAsErrors) {
  nlohmann::json j = {
      {"file", printableText(d.file)},
      {"severity", std::string(scene::severityName(shownSeverity(d, warningsAsErrors)))},
      {"code", std::string(scene::codeName(d.code))},
      {"message", printableText(d.message)},
  };
  j.update(spanToJson(d.span));
  if (!d.hint.empty()) j["hint"] = printableText(hintText(d));
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
