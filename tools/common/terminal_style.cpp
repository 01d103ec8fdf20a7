#include "tools/common/terminal_style.h"

namespace tools {

std::optional<ColorMode> colorModeFromName(std::string_view name) {
  if (name == "auto") return ColorMode::Auto;
  if (name == "always") return ColorMode::Always;
  if (name == "never") return ColorMode::Never;
  return std::nullopt;
}

bool useColor(ColorMode mode, bool isTerminal, const ToolStreams& streams) {
  switch (mode) {
    case ColorMode::Always:
      return true;
    case ColorMode::Never:
      return false;
    case ColorMode::Auto:
      break;
  }
  if (!isTerminal) return false;
  if (streams.noColor && !streams.noColor->empty()) return false;
  return !(streams.term && *streams.term == "dumb");
}

std::string TerminalStyle::severity(scene::Severity severity, std::string_view text) const {
  switch (severity) {
    case scene::Severity::Error:
      return paint("\x1b[1;31m", text);
    case scene::Severity::Warning:
      return paint("\x1b[1;35m", text);
    case scene::Severity::Note:
      return paint("\x1b[1;36m", text);
  }
  return std::string(text);
}

std::string TerminalStyle::paint(std::string_view sequence, std::string_view text) const {
  if (!enabled_ || text.empty()) return std::string(text);
  std::string painted(sequence);
  painted += text;
  painted += "\x1b[0m";
  return painted;
}

}  // namespace tools
