// A captured source line quoted under a diagnostic (scenefile/source_excerpt.h).
#pragma once

#include <string>
#include <vector>

#include "libscene/text/terminal_paint.h"
#include "scenefile/source_excerpt.h"

namespace scene {

// The lines that quote `line` (line number `span.line`) under a diagnostic:
// the source line behind a gutter, a caret line under `span`, and, when
// `fixIt` is on the same line, the replacement under what it replaces. Tabs
// expand to 8 columns and bytes that cannot be shown as they are print as
// \xNN, with the caret still under the byte it points at.
std::vector<std::string> quoteSourceLine(const SourceLine& line, const SourceSpan& span,
                                         const FixIt* fixIt, const TerminalPaint& paint);

}  // namespace scene
