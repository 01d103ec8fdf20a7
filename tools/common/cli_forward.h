// The CLI11 classes the tools' headers name, declared without CLI11 itself.
//
// <CLI/CLI.hpp> (CLI11 2.1, header only) defines its validators as objects
// in the header, so every file that includes it compiles and constructs
// them again: about 7 s of compile time a file in a release build and 20 s
// under the sanitizers, where 34 files included it and were half of the
// build. Headers include this instead; only the files that build or read a
// command line include CLI11. CLI11 declares these classes ahead in the same
// way (CLI/FormatterFwd.hpp).
#pragma once

namespace CLI {
class App;
class Option;
class Validator;
class ParseError;
}  // namespace CLI
