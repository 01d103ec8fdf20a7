// Batches: many inputs, one output pattern (`sfrender a.sf b.sf -o
// 'out/{stem}.png'`), and the summary line a batch ends with
// (docs/TOOLS.md, "Batches").
//
// What a placeholder may expand to is one rule, so that a pattern's fixed
// folder is a promise: {stem} and {name} are a file name, never empty, `.`
// or `..`, and never hold `/`; {dir} is the input's folder as given, which
// may climb with `..` only where it begins the pattern (the output then goes
// beside the input, wherever that is), never out of a fixed folder before
// it. Standard input has no name, so no placeholder of it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tools/common/tool_failure.h"

namespace tools {

// Whether `pattern` holds a placeholder ({stem}, {name} or {dir}).
bool hasPlaceholder(const std::string& pattern);

// The output of `input` under `pattern`: {stem} is the input's file name
// without its extension (the last one), {name} its file name, {dir} its
// folder ("." for none). A usage failure for a placeholder that is none of
// those, or one the rule above refuses for this input.
Outcome<std::string> expandOutputPattern(const std::string& pattern, const std::string& input);

// A usage failure when `inputs` cannot make a batch (standard input among
// several).
MaybeFailure batchInputsRefusal(const std::vector<std::string>& inputs);

// The output of each input under `pattern`, or a usage failure: several
// inputs and no placeholder, standard input among several, an unknown
// placeholder, or one that the rule refuses. Whether two outputs are one
// file, or an output an input, is output_plan.h's to tell.
Outcome<std::vector<std::string>> batchOutputs(const std::string& pattern,
                                               const std::vector<std::string>& inputs);

// The last line of a batch: "sfrender: 18 of 20 scenes rendered, 2 failed".
std::string batchSummary(const std::string& tool, int succeeded, int total,
                         const std::string& done);

}  // namespace tools
