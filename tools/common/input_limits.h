// The limits on what one input may cost (docs/FORMATS.md, "Limits"): the
// flags that raise them, and reading an input file within them.
#pragma once

#include <istream>
#include <optional>
#include <string>

#include "scenefile/read.h"
#include "tools/common/cli_forward.h"

namespace tools {

// --max-file-size (CLI11's size suffixes: 512MiB, 2GB), --max-objects,
// --max-vertices and --max-nodes, stored into `options`.
void addReadLimitOptions(CLI::App& app, scene::ReadOptions& options);

// An input file's bytes, read only when it is within options.maxFileSize.
struct InputText {
  std::optional<std::string> text;  // the bytes, when read and within the limit
  std::string readError;            // why the file could not be read (exit 3)
  scene::DiagnosticList refused;    // file-too-large (exit 1), else empty

  bool tooLarge() const { return refused.hasErrors(); }
};

// A regular file over the limit is refused by its size, unread; anything
// else (a pipe) is read up to one byte past the limit. The name "-" reads
// `standardInput` (when given) the same way, and its diagnostics name it
// "<stdin>".
InputText readInputText(const std::string& file, const scene::ReadOptions& options,
                        std::istream* standardInput = nullptr);

// The name diagnostics give an input: "<stdin>" for "-", else the name.
std::string inputDisplayName(const std::string& file);

}  // namespace tools
