// Colour on a terminal, as compilers use it: the location bold, the
// severity in its colour, the caret green. Decided once per run from
// --color, the terminal and NO_COLOR, then passed by value.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "scenefile/diagnostic.h"
#include "tools/common/tool_streams.h"

namespace tools {

// --color: auto (colour when standard error is a terminal, NO_COLOR is unset
// or empty and TERM is not "dumb"), always, never.
enum class ColorMode { Auto, Always, Never };

std::optional<ColorMode> colorModeFromName(std::string_view name);

// Whether a stream that is (or is not) a terminal gets colour: --color always
// wins over NO_COLOR, as no-color.org asks of a flag given on the command
// line.
bool useColor(ColorMode mode, bool isTerminal, const ToolStreams& streams);

// The escape sequences (SGR) of each part, or nothing when colour is off.
class TerminalStyle {
 public:
  explicit TerminalStyle(bool enabled = false) : enabled_(enabled) {}
  bool enabled() const { return enabled_; }

  std::string location(std::string_view text) const { return paint("\x1b[1m", text); }
  std::string severity(scene::Severity severity, std::string_view text) const;
  std::string caret(std::string_view text) const { return paint("\x1b[1;32m", text); }
  std::string fixIt(std::string_view text) const { return paint("\x1b[32m", text); }

 private:
  std::string paint(std::string_view sequence, std::string_view text) const;
  bool enabled_ = false;
};

}  // namespace tools
