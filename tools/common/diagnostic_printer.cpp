#include "tools/common/diagnostic_printer.h"

#include <algorithm>
#include <string_view>
#include <vector>

namespace tools {

namespace {

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

scene::DiagnosticFormOptions formOptions(const DiagnosticStyle& style) {
  scene::DiagnosticFormOptions options;
  options.form = scene::DiagnosticForm::Text;
  options.quoteSource = style.quoteSource;
  options.color = style.terminal.enabled();
  options.warningsAsErrors = style.warningsAsErrors;
  options.lowestSeverity = style.errorsOnly   ? scene::Severity::Error
                           : style.notesShown ? scene::Severity::Note
                                              : scene::Severity::Warning;
  options.hint = style.hint ? style.hint : hintText;
  return options;
}

void DiagnosticPrinter::print(const scene::Diagnostic& d) const {
  out_ << scene::formatDiagnostic(d, formOptions(style_), sources_);
}

void DiagnosticPrinter::print(const scene::DiagnosticList& list) const {
  out_ << scene::formatDiagnostics(list, formOptions(style_), sources_);
}

void printDiagnostics(const scene::DiagnosticList& list, std::ostream& out) {
  DiagnosticStyle style;
  style.quoteSource = false;
  DiagnosticPrinter(out, style).print(list);
}

nlohmann::json diagnosticsToJson(const scene::DiagnosticList& list, bool warningsAsErrors) {
  scene::DiagnosticFormOptions options;
  options.form = scene::DiagnosticForm::Json;
  options.warningsAsErrors = warningsAsErrors;
  options.hint = hintText;
  return nlohmann::json::parse(scene::formatDiagnostics(list, options));
}

}  // namespace tools
