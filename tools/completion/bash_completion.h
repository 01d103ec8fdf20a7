// Bash completion scripts made from the tools' own command lines, so that
// they offer exactly the flags --help lists: every flag, the choices of an
// option that takes one of a list (--to's come from the format registry),
// and files by extension where a file belongs.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "tools/common/cli_forward.h"

namespace tools {

// Which files complete where: the extensions (without the dot) for the
// positional arguments and for each option that takes a file (by its long
// name, "--output").
struct CompletedFiles {
  std::vector<std::string> arguments;
  std::map<std::string, std::vector<std::string>> options;
};

// The script for `app`'s tool: a function _NAME and `complete -F _NAME NAME`.
std::string bashCompletionScript(const CLI::App& app, const CompletedFiles& files);

}  // namespace tools
