// Batches: many inputs, one output pattern (`sfrender a.sf b.sf -o
// 'out/{stem}.png'`), and the summary line a batch ends with
// (docs/TOOLS.md, "Batches").
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace tools {

// Whether `pattern` holds a placeholder ({stem}, {name} or {dir}).
bool hasPlaceholder(const std::string& pattern);

// The output of `input` under `pattern`: {stem} is the input's file name
// without its extension (the last one), {name} its file name, {dir} its
// folder ("." for none). Nothing, with why in `error`, for a placeholder
// that is none of those.
std::optional<std::string> expandOutputPattern(const std::string& pattern, const std::string& input,
                                               std::string& error);

// The output of each input under `pattern`, or nothing with why in `error`
// (a sentence for "TOOL: error: "): several inputs and no placeholder,
// standard input among several, an unknown placeholder, or two inputs that
// would write the same file.
std::optional<std::vector<std::string>> batchOutputs(const std::string& pattern,
                                                     const std::vector<std::string>& inputs,
                                                     std::string& error);

// The last line of a batch: "sfrender: 18 of 20 scenes rendered, 2 failed".
std::string batchSummary(const std::string& tool, int succeeded, int total,
                         const std::string& done);

}  // namespace tools
