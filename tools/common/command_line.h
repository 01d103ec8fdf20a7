// Every tool's command line: CLI11 with the flags that every tool has, help
// in the GNU layout (the source of the man pages, through help2man), and
// mistakes told in the house style:
//
//   sfrender: error: unknown option '--widht'; did you mean '--width'?
//     hint: run 'sfrender --help' for the options
#pragma once

#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include "tools/common/cli_forward.h"
#include "tools/common/exit_code.h"
#include "tools/common/terminal_style.h"

namespace tools {

// The flags every tool has, beside -h/--help and -V/--version.
struct CommonFlags {
  bool quiet = false;          // -q: only errors (and what was asked for, --stats)
  bool verbose = false;        // -v: also what the tool decided and how long each step took
  std::string color = "auto";  // --color auto|always|never

  ColorMode colorMode() const { return colorModeFromName(color).value_or(ColorMode::Auto); }
};

// A tool's App: its name and one line of what it does, help in the GNU
// layout with each option's default, -h/--help and -V/--version, and the
// common flags. Every option added later shows its default in --help.
std::unique_ptr<CLI::App> makeToolApp(const std::string& name, const std::string& description,
                                      CommonFlags& flags);

// The help's last paragraph: the exit statuses every tool shares
// (exit_code.h), which a tool with more appends to.
std::string exitStatusHelp();

// Parses the arguments. Returns the exit code to stop with (0 after --help or
// --version, Usage after a mistake, with the message on `err`), or nothing
// when the tool should go on. No option takes an empty value ("--width=" is
// one), and one that takes a single value may not be given twice.
std::optional<ExitCode> parseCommandLine(CLI::App& app, int argc, const char* const* argv,
                                         std::ostream& out, std::ostream& err);

// The message for a mistake on the command line, without the tool's name:
// an unknown option is named, with the closest known one; a value that is
// no number says so; a missing argument is named in upper case as --help
// shows it. Exposed for the tests.
std::string describeCommandLineError(const CLI::App& app, int argc, const char* const* argv,
                                     const CLI::ParseError& error);

// The first argument that names no option of `app` (an unknown flag), with
// the values of the options that take one skipped; nothing when all are
// known. CLI11 would first complain that a required argument is missing.
std::optional<std::string> unknownOption(const CLI::App& app, int argc, const char* const* argv);

// The names of an option as --help shows them ("-o, --output"), and a
// positional's as the usage line does ("FILES...").
std::string optionDisplayName(const CLI::Option& option);

}  // namespace tools
