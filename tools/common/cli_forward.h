// The CLI11 classes the tools' headers name, declared without CLI11 itself.
//
// <CLI/CLI.hpp> (CLI11 2.1, header only) defines its validators as objects
// in the header, so every file that includes it compiles and constructs
// them again: an empty file that includes it takes 7.6 s to compile in a
// release build and 20.8 s under the sanitizers. 29 files included it, most
// through the tools' headers. Headers include this instead, and only the
// files that build or read a command line include CLI11 (21 now; sfcheck's
// main.cpp compiles in 1.4 s under the sanitizers instead of 18). CLI11
// declares these classes ahead in the same way (CLI/FormatterFwd.hpp).
#pragma once

namespace CLI {
class App;
class Option;
class Validator;
class ParseError;
}  // namespace CLI
