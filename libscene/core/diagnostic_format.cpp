#include "scenefile/diagnostic_format.h"

#include <nlohmann/json.hpp>
#include <vector>

#include "libscene/text/source_quote.h"
#include "libscene/text/terminal_paint.h"
#include "scenefile/printable_text.h"

namespace scene {

namespace {

Severity shownSeverity(const Diagnostic& d, bool warningsAsErrors) {
  if (warningsAsErrors && d.severity == Severity::Warning) return Severity::Error;
  return d.severity;
}

bool shown(const Diagnostic& d, const DiagnosticFormOptions& options) {
  return shownSeverity(d, options.warningsAsErrors) >= options.lowestSeverity;
}

std::string hintOf(const Diagnostic& d, const DiagnosticFormOptions& options) {
  return options.hint ? options.hint(d) : settingHintText(d);
}

// The text forms' writer: one diagnostic, its quotes, hint and notes.
class TextWriter {
 public:
  TextWriter(const DiagnosticFormOptions& options, const SourceExcerpts* sources)
      : options_(options),
        paint_(options.color),
        sources_(options.form == DiagnosticForm::Text && options.quoteSource ? sources : nullptr) {}

  void write(const Diagnostic& d, std::string& out) const {
    Severity severity = shownSeverity(d, options_.warningsAsErrors);
    writeLocation(d.file, d.span, out);
    std::string name(severityName(severity));
    out += ' ' + paint_.severity(severity, name + ":") + ' ' + printableText(d.message) + " [" +
           paint_.severity(severity, codeName(d.code)) + "]\n";
    quote(d.file, d.span, d.fixIt ? &*d.fixIt : nullptr, out);
    // A front end's words may leave no hint (the advice is followed already).
    std::string hint = d.hint.empty() ? std::string() : hintOf(d, options_);
    if (!hint.empty()) out += "  " + paint_.location("hint:") + ' ' + printableText(hint) + '\n';
    for (const DiagnosticNote& note : d.notes) {
      writeLocation(d.file, note.span, out);
      out +=
          ' ' + paint_.severity(Severity::Note, "note:") + ' ' + printableText(note.message) + '\n';
      quote(d.file, note.span, nullptr, out);
    }
  }

 private:
  void writeLocation(const std::string& file, const SourceSpan& span, std::string& out) const {
    std::string location = (file.empty() ? "<input>" : printableText(file)) + ":";
    if (span.known()) {
      location += std::to_string(span.line) + ":" + std::to_string(span.column) + ":";
    }
    out += paint_.location(location);
  }

  void quote(const std::string& file, const SourceSpan& span, const FixIt* fixIt,
             std::string& out) const {
    if (!sources_) return;
    const SourceLine* line = sources_->find(file, span);
    if (!line) return;
    for (const std::string& text : quoteSourceLine(*line, span, fixIt, paint_)) {
      out += text + '\n';
    }
  }

  const DiagnosticFormOptions& options_;
  TerminalPaint paint_;
  const SourceExcerpts* sources_;
};

nlohmann::json spanToJson(const SourceSpan& span) {
  nlohmann::json j = {{"line", span.line}, {"column", span.column}, {"length", span.length}};
  if (span.known()) {
    j["endLine"] = span.line;
    j["endColumn"] = span.column + span.length;
  }
  return j;
}

nlohmann::json toJson(const Diagnostic& d, const DiagnosticFormOptions& options) {
  nlohmann::json j = {
      {"file", printableText(d.file)},
      {"severity", std::string(severityName(shownSeverity(d, options.warningsAsErrors)))},
      {"code", std::string(codeName(d.code))},
      {"message", printableText(d.message)},
  };
  j.update(spanToJson(d.span));
  std::string hint = d.hint.empty() ? std::string() : hintOf(d, options);
  if (!hint.empty()) j["hint"] = printableText(hint);
  if (!d.notes.empty()) {
    nlohmann::json notes = nlohmann::json::array();
    for (const DiagnosticNote& note : d.notes) {
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

}  // namespace

std::optional<DiagnosticForm> diagnosticFormFromName(std::string_view name) {
  if (name == "text") return DiagnosticForm::Text;
  if (name == "short") return DiagnosticForm::Short;
  if (name == "json") return DiagnosticForm::Json;
  return std::nullopt;
}

std::string settingHintText(const Diagnostic& d) {
  return hintText(d.hint, d.remedies, [](const Remedy& remedy) {
    std::string text(settingName(remedy.setting));
    if (!remedy.value.empty()) text += "=" + remedy.value;
    return text;
  });
}

std::string formatDiagnostic(const Diagnostic& d, const DiagnosticFormOptions& options,
                             const SourceExcerpts* sources) {
  if (!shown(d, options)) return {};
  if (options.form == DiagnosticForm::Json) return toJson(d, options).dump();
  std::string out;
  TextWriter(options, sources).write(d, out);
  return out;
}

std::string formatDiagnostics(const DiagnosticList& list, const DiagnosticFormOptions& options,
                              const SourceExcerpts* sources) {
  if (options.form == DiagnosticForm::Json) {
    nlohmann::json array = nlohmann::json::array();
    for (const Diagnostic& d : list.items()) {
      if (shown(d, options)) array.push_back(toJson(d, options));
    }
    return array.dump(2) + "\n";
  }
  TextWriter writer(options, sources);
  std::string out;
  for (const Diagnostic& d : list.items()) {
    if (shown(d, options)) writer.write(d, out);
  }
  return out;
}

}  // namespace scene
