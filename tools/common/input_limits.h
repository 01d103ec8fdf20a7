// The limits on what one input may cost (docs/FORMATS.md, "Limits"): the
// flags that raise them, and reading an input file within them.
#pragma once

#include <istream>
#include <string>

#include "scenefile/read.h"
#include "scenefile/read_file.h"
#include "tools/common/cli_forward.h"

namespace tools {

// --max-file-size (CLI11's size suffixes: 512MiB, 2GB), --max-objects,
// --max-vertices and --max-nodes, stored into `options`.
void addReadLimitOptions(CLI::App& app, scene::ReadOptions& options);

// An input's text read within the limits (scenefile/read_file.h):
// readError is exit 3, file-too-large exit 1.
using InputText = scene::SourceText;

// The file `file` read as scene::readSourceFile reads it; the name "-" reads
// `standardInput` (when given) as scene::readSourceStream does, and its
// diagnostics name it "<stdin>".
InputText readInputText(const std::string& file, const scene::ReadOptions& options,
                        std::istream* standardInput = nullptr);

// The name diagnostics give an input: "<stdin>" for "-", else the name.
std::string inputDisplayName(const std::string& file);

}  // namespace tools
