// Colour on a terminal, as compilers use it (SGR escape sequences): the
// location bold, the severity in its colour, the caret green; nothing when
// off. What formatDiagnostics paints with.
#pragma once

#include <string>
#include <string_view>

#include "scenefile/diagnostic.h"

namespace scene {

class TerminalPaint {
 public:
  explicit TerminalPaint(bool enabled = false) : enabled_(enabled) {}

  std::string location(std::string_view text) const { return paint("\x1b[1m", text); }
  std::string severity(Severity severity, std::string_view text) const {
    switch (severity) {
      case Severity::Error:
        return paint("\x1b[1;31m", text);
      case Severity::Warning:
        return paint("\x1b[1;35m", text);
      case Severity::Note:
        return paint("\x1b[1;36m", text);
    }
    return std::string(text);
  }
  std::string caret(std::string_view text) const { return paint("\x1b[1;32m", text); }
  std::string fixIt(std::string_view text) const { return paint("\x1b[32m", text); }

 private:
  std::string paint(std::string_view sequence, std::string_view text) const {
    if (!enabled_ || text.empty()) return std::string(text);
    return std::string(sequence) + std::string(text) + "\x1b[0m";
  }
  bool enabled_ = false;
};

}  // namespace scene
