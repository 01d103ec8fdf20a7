#include "scenefile/diagnostic.h"

#include <array>
#include <utility>

namespace scene {

std::string_view severityName(Severity severity) {
  switch (severity) {
    case Severity::Note:
      return "note";
    case Severity::Warning:
      return "warning";
    case Severity::Error:
      return "error";
  }
  return "error";
}

std::string_view settingName(Setting setting) {
  switch (setting) {
    case Setting::MaxFileSize:
      return "max-file-size";
    case Setting::MaxObjects:
      return "max-objects";
    case Setting::MaxGltfNodes:
      return "max-gltf-nodes";
    case Setting::TransposedMatrices:
      return "transposed-matrices";
    case Setting::SkipUnsupported:
      return "skip-unsupported";
    case Setting::Approximate:
      return "approximate";
    case Setting::FieldOfView:
      return "field-of-view";
    case Setting::Width:
      return "width";
    case Setting::Height:
      return "height";
    case Setting::Depth:
      return "depth";
    case Setting::OutputPath:
      return "output-path";
  }
  return "unknown";
}

namespace {

struct CodeEntry {
  DiagnosticCode code;
  std::string_view name;
};

// In the enum's order, so that a code's entry is at its value.
constexpr std::array kCodes = {
#define SCENEFILE_DIAGNOSTIC(enumerator, name) CodeEntry{DiagnosticCode::enumerator, name},
#include "scenefile/diagnostic_codes.def"
};

// The names codes had before they were renamed; diagnosticCodeFromName
// reads them, codeName never prints them.
constexpr CodeEntry kAliases[] = {
#define SCENEFILE_DIAGNOSTIC(enumerator, name)
#define SCENEFILE_DIAGNOSTIC_ALIAS(enumerator, oldName) \
  CodeEntry{DiagnosticCode::enumerator, oldName},
#include "scenefile/diagnostic_codes.def"
};

}  // namespace

const std::vector<DiagnosticCode>& allDiagnosticCodes() {
  static const std::vector<DiagnosticCode> codes = [] {
    std::vector<DiagnosticCode> out;
    for (const CodeEntry& entry : kCodes) out.push_back(entry.code);
    return out;
  }();
  return codes;
}

std::string_view codeName(DiagnosticCode code) {
  auto index = static_cast<std::size_t>(code);
  // A value cast from an integer may be no code at all.
  if (index >= kCodes.size()) return "unknown";
  return kCodes[index].name;
}

std::optional<DiagnosticCode> diagnosticCodeFromName(std::string_view name) {
  for (const CodeEntry& entry : kCodes) {
    if (entry.name == name) return entry.code;
  }
  for (const CodeEntry& entry : kAliases) {
    if (entry.name == name) return entry.code;
  }
  return std::nullopt;
}

Diagnostic& DiagnosticList::report(Severity severity, DiagnosticCode code, SourceSpan span,
                                   std::string message) {
  // Past the limit, warnings and notes are still counted but no longer kept.
  if (full() || (severity != Severity::Error && items_.size() >= 2 * errorLimit_)) {
    if (severity == Severity::Warning && !full()) ++warningCount_;
    discarded_ = Diagnostic{};
    return discarded_;
  }
  items_.push_back(Diagnostic{severity, code, file_, span, std::move(message), {}, {}, {}, {}});
  std::size_t index = items_.size() - 1;
  if (severity == Severity::Error) ++errorCount_;
  if (severity == Severity::Warning) ++warningCount_;
  if (full()) {
    items_.push_back(Diagnostic{Severity::Note,
                                DiagnosticCode::TooManyErrors,
                                file_,
                                span,
                                "too many errors; stopped after " + std::to_string(errorLimit_),
                                {},
                                {},
                                {},
                                {}});
  }
  // The caller may still attach a hint, notes or a fix-it to what it reported.
  return items_[index];
}

void DiagnosticList::append(const DiagnosticList& other) {
  for (const Diagnostic& d : other.items_) {
    items_.push_back(d);
    if (d.severity == Severity::Error) ++errorCount_;
    if (d.severity == Severity::Warning) ++warningCount_;
  }
}

}  // namespace scene
