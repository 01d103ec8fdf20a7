// canonicalLayout: each line format's own, through its registry row.
#include "scenefile/layout.h"

namespace scene {

std::optional<std::string> canonicalLayout(std::string_view text, Format format) {
  const FormatInfo& row = formatInfo(format);
  if (!row.layout) return std::nullopt;
  return row.layout(text);
}

}  // namespace scene
