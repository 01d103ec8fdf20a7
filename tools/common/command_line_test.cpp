// The command lines of all four tools: mistakes told in the house style,
// the flags every tool has, and help that shows each default.
#include "tools/common/command_line.h"

#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <charconv>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tools/common/option_checks.h"
#include "tools/sfbuild/sfbuild_command_line.h"
#include "tools/sfcheck/sfcheck.h"
#include "tools/sfconvert/sfconvert.h"
#include "tools/sfrender/sfrender.h"

namespace tools {
namespace {

// A tool's App with the options it writes into, which must outlive it.
struct MadeApp {
  std::shared_ptr<void> options;
  std::unique_ptr<CLI::App> app;
  CLI::App* operator->() const { return app.get(); }
  CLI::App& operator*() const { return *app; }
};

template <typename Options>
MadeApp madeWith(std::unique_ptr<CLI::App> (*make)(Options&)) {
  auto options = std::make_shared<Options>();
  std::unique_ptr<CLI::App> app = make(*options);
  return {options, std::move(app)};
}

// One tool's command line, made afresh for each parse, as each run does.
struct ToolCommandLine {
  std::string name;
  std::function<MadeApp()> make;
  std::vector<std::string> arguments;  // what it needs besides options
};

std::vector<ToolCommandLine> allTools() {
  return {
      {"sfcheck", [] { return madeWith(&makeSfcheckCommandLine); }, {"a.sf"}},
      {"sfconvert", [] { return madeWith(&makeSfconvertCommandLine); }, {"a.sf", "b.sf"}},
      {"sfrender", [] { return madeWith(&makeSfrenderCommandLine); }, {}},
      {"sfbuild", [] { return madeWith(&sfbuild::makeSfbuildCommandLine); }, {}},
  };
}

// What the tool prints for `args` (its name first), and the exit status.
struct ParseOutcome {
  std::optional<ExitCode> status;
  std::string out;
  std::string err;
};

std::string firstLine(const std::string& text) {
  return text.substr(0, text.find('\n'));
}

ParseOutcome parse(CLI::App& app, std::vector<std::string> args) {
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  std::ostringstream out, err;
  std::optional<ExitCode> status =
      parseCommandLine(app, static_cast<int>(argv.size()), argv.data(), out, err);
  return {status, out.str(), err.str()};
}

TEST(CommandLine, AnUnknownOptionIsNamedWithTheClosestKnownOne) {
  SfrenderOptions o;
  auto app = makeSfrenderCommandLine(o);
  ParseOutcome r = parse(*app, {"sfrender", "--widht", "3"});
  EXPECT_EQ(r.status, ExitCode::Usage);
  EXPECT_EQ(r.err,
            "sfrender: error: unknown option '--widht'; did you mean '--width'?\n"
            "  hint: run 'sfrender --help' for the options\n");
  app = makeSfrenderCommandLine(o);
  EXPECT_EQ(firstLine(parse(*app, {"sfrender", "--colour", "never"}).err),
            "sfrender: error: unknown option '--colour'; did you mean '--color'?");
  // Nothing close: no guess.
  app = makeSfrenderCommandLine(o);
  EXPECT_EQ(firstLine(parse(*app, {"sfrender", "--bogus"}).err),
            "sfrender: error: unknown option '--bogus'");
}

TEST(CommandLine, ALoneUnknownFlagIsNamedBeforeAMissingArgument) {
  SfcheckOptions o;
  auto app = makeSfcheckCommandLine(o);
  EXPECT_EQ(firstLine(parse(*app, {"sfcheck", "--bogus"}).err),
            "sfcheck: error: unknown option '--bogus'");
  app = makeSfcheckCommandLine(o);
  EXPECT_EQ(firstLine(parse(*app, {"sfcheck", "-x"}).err), "sfcheck: error: unknown option '-x'");
  // Short flags together, one of them unknown.
  app = makeSfcheckCommandLine(o);
  EXPECT_EQ(firstLine(parse(*app, {"sfcheck", "-qz", "a.sf"}).err),
            "sfcheck: error: unknown option '-z'");
  // With nothing unknown, what is missing is named as --help shows it.
  app = makeSfcheckCommandLine(o);
  EXPECT_EQ(firstLine(parse(*app, {"sfcheck"}).err), "sfcheck: error: missing FILES");
  // An option's value that looks like a flag is its value, not a flag.
  app = makeSfcheckCommandLine(o);
  EXPECT_EQ(firstLine(parse(*app, {"sfcheck", "--max-objects", "-5", "a.sf"}).err),
            "sfcheck: error: --max-objects: -5 is not between 1 and 9223372036854775807");
}

TEST(CommandLine, ABadNumberSaysItIsNotANumber) {
  SfrenderOptions o;
  auto app = makeSfrenderCommandLine(o);
  EXPECT_EQ(firstLine(parse(*app, {"sfrender", "--width", "abc"}).err),
            "sfrender: error: --width: 'abc' is not a number");
  app = makeSfrenderCommandLine(o);
  EXPECT_EQ(firstLine(parse(*app, {"sfrender", "--width", "1.5"}).err),
            "sfrender: error: --width: '1.5' is not a whole number");
  app = makeSfrenderCommandLine(o);
  EXPECT_EQ(firstLine(parse(*app, {"sfrender", "--width", "0"}).err),
            "sfrender: error: --width: 0 is not between 1 and 32768");
  app = makeSfrenderCommandLine(o);
  EXPECT_EQ(firstLine(parse(*app, {"sfrender", "--fov", "200"}).err),
            "sfrender: error: --fov: 200 is not between 0.001 and 179.999");
  app = makeSfrenderCommandLine(o);
  EXPECT_EQ(firstLine(parse(*app, {"sfrender", "--width"}).err),
            "sfrender: error: --width needs a value");
}

// Whatever the option, a word where a number belongs says so: no option is
// left to CLI11's "not in range" or "could not convert".
TEST(CommandLine, EveryNumericOptionOfEveryToolRefusesAWordAsNoNumber) {
  int checked = 0;
  for (const ToolCommandLine& tool : allTools()) {
    auto probe = tool.make();
    for (const CLI::Option* option : probe->get_options()) {
      std::string type = option->get_type_name();
      type = type.substr(0, type.find(':'));
      if (option->get_positional() || (type != "INT" && type != "UINT" && type != "FLOAT")) {
        continue;
      }
      std::string name = "--" + option->get_lnames().front();
      auto app = tool.make();
      ParseOutcome r = parse(*app, {tool.name, name, "abc"});
      EXPECT_EQ(r.status, ExitCode::Usage) << tool.name << " " << name;
      EXPECT_NE(r.err.find(name + ": 'abc' is not a number"), std::string::npos)
          << tool.name << " " << name << ": " << r.err;
      ++checked;
    }
  }
  EXPECT_GT(checked, 20);
}

TEST(CommandLine, AChoiceNotOfferedListsTheChoicesAndTheClosest) {
  SfcheckOptions o;
  auto app = makeSfcheckCommandLine(o);
  EXPECT_EQ(firstLine(parse(*app, {"sfcheck", "--format", "jsn", "a.sf"}).err),
            "sfcheck: error: --format: 'jsn' is not text, short or json; did you mean 'json'?");
}

TEST(CommandLine, EveryToolHasTheCommonFlags) {
  for (const ToolCommandLine& tool : allTools()) {
    auto app = tool.make();
    for (const char* flag :
         {"-h", "--help", "-V", "--version", "-q", "--quiet", "-v", "--verbose", "--color"}) {
      EXPECT_NE(app->get_option_no_throw(flag), nullptr) << tool.name << " " << flag;
    }
    app = tool.make();
    ParseOutcome version = parse(*app, {tool.name, "-V"});
    EXPECT_EQ(version.status, ExitCode::Success);
    EXPECT_EQ(version.out, tool.name + " " + SCENEFILE_VERSION + "\n");
    app = tool.make();
    ParseOutcome both = parse(*app, {tool.name, "-q", "-v"});
    EXPECT_EQ(both.status, ExitCode::Usage) << tool.name;
    EXPECT_NE(both.err.find("--quiet and --verbose cannot be used together"), std::string::npos)
        << both.err;
    app = tool.make();
    EXPECT_NE(parse(*app, {tool.name, "--color", "sometimes"})
                  .err.find("'sometimes' is not auto, always or never"),
              std::string::npos);
  }
}

// Help in the GNU layout, within 79 columns, every option's default shown:
// the source of the man pages (help2man).
TEST(CommandLine, HelpShowsEveryOptionAndItsDefault) {
  for (const ToolCommandLine& tool : allTools()) {
    auto app = tool.make();
    ParseOutcome help = parse(*app, {tool.name, "--help"});
    EXPECT_EQ(help.status, ExitCode::Success);
    EXPECT_EQ(help.out.rfind("Usage: " + tool.name + " [OPTIONS]", 0), 0u) << help.out;
    std::istringstream lines(help.out);
    for (std::string line; std::getline(lines, line);) {
      EXPECT_LE(line.size(), 79u) << tool.name << ": " << line;
    }
    auto probe = tool.make();
    for (const CLI::Option* option : probe->get_options()) {
      std::string shown = optionDisplayName(*option);
      EXPECT_NE(help.out.find(shown), std::string::npos) << tool.name << " " << shown;
    }
  }
  SfrenderOptions o;
  auto app = makeSfrenderCommandLine(o);
  std::string help = parse(*app, {"sfrender", "--help"}).out;
  EXPECT_NE(help.find("--spp N"), std::string::npos);
  EXPECT_NE(help.find("(default: 1)"), std::string::npos);
  EXPECT_NE(help.find("(default: auto)"), std::string::npos);
  EXPECT_NE(help.find("Exit status:"), std::string::npos);
}

// The options of a tool that take a value, and the numeric ones among them.
std::vector<std::string> valueOptions(const ToolCommandLine& tool, bool numericOnly) {
  std::vector<std::string> names;
  auto probe = tool.make();
  for (const CLI::Option* option : probe->get_options()) {
    std::string type = option->get_type_name();
    type = type.substr(0, type.find(':'));
    bool numeric = type == "INT" || type == "UINT" || type == "FLOAT";
    if (option->get_positional() || option->get_expected_max() == 0 ||
        option->get_lnames().empty() || (numericOnly && !numeric)) {
      continue;
    }
    names.push_back("--" + option->get_lnames().front());
  }
  return names;
}

// The number `text` is, read as the tools promise to read it: decimal,
// whole, correctly rounded; nothing where it is none.
std::optional<double> reference(std::string text, bool whole) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+') text.erase(0, 1);
  const char* end = text.data() + text.size();
  if (whole) {
    std::int64_t n = 0;
    auto [stop, ec] = std::from_chars(text.data(), end, n);
    if (ec != std::errc() || stop != end || text.empty()) return std::nullopt;
    return static_cast<double>(n);
  }
  double d = 0;
  auto [stop, ec] = std::from_chars(text.data(), end, d);
  if (ec != std::errc() || stop != end || text.empty()) return std::nullopt;
  return d;
}

// Every numeric option of every tool, given words, the edges of a double
// and numbers CLI11 alone would read otherwise (octal 010, a subnormal that
// strtod calls out of range): a usage error that names the option and the
// value, or exactly the number the text is. Never an exception.
TEST(CommandLine, EveryNumericOptionOfEveryToolReadsANumberOneWay) {
  const std::string values[] = {"",
                                "abc",
                                "nan",
                                "-nan",
                                "inf",
                                "-infinity",
                                "1e400",
                                "-1e400",
                                "1e-400",
                                "0x10",
                                " 5",
                                "5 ",
                                "5x",
                                "+-5",
                                "1,5",
                                "1e-310",
                                "4.9e-324",
                                "-4.9e-324",
                                "010",
                                "+7",
                                "-0",
                                "1.5",
                                "1e3",
                                "0",
                                "1",
                                "3",
                                "64",
                                "100",
                                "0.001",
                                "179.999",
                                "180",
                                "32768",
                                "32769",
                                "99999999999999999999",
                                "9223372036854775807",
                                "-9223372036854775809"};
  int accepted = 0, refused = 0;
  for (const ToolCommandLine& tool : allTools()) {
    for (const std::string& name : valueOptions(tool, true)) {
      for (const std::string& value : values) {
        for (bool joined : {false, true}) {
          SCOPED_TRACE(tool.name + " " + name + (joined ? "=" : " ") + "'" + value + "'");
          std::vector<std::string> args{tool.name};
          if (joined) {
            args.push_back(name + "=" + value);
          } else {
            args.insert(args.end(), {name, value});
          }
          args.insert(args.end(), tool.arguments.begin(), tool.arguments.end());
          auto app = tool.make();
          ParseOutcome r;
          ASSERT_NO_THROW(r = parse(*app, args));
          if (r.status) {
            ++refused;
            EXPECT_EQ(r.status, ExitCode::Usage);
            EXPECT_NE(r.err.find(name + ": "), std::string::npos) << r.err;
            EXPECT_NE(r.err.find(value.empty() ? "''" : value), std::string::npos) << r.err;
            continue;
          }
          ++accepted;
          const CLI::Option* option = app->get_option(name);
          bool whole = option->get_type_name().substr(0, 5) != "FLOAT";
          std::optional<double> want = reference(value, whole);
          ASSERT_TRUE(want) << "accepted what is no number";
          double got =
              whole ? static_cast<double>(option->as<std::int64_t>()) : option->as<double>();
          EXPECT_EQ(std::memcmp(&got, &*want, sizeof got), 0) << got << " " << *want;
        }
      }
    }
  }
  EXPECT_GT(accepted, 100);
  EXPECT_GT(refused, 1000);
}

// `--opt=` with nothing after it is an empty value, refused, not a way to
// take the next argument as the value; and an option that takes one value,
// given twice, is a usage error, whichever the option.
TEST(CommandLine, AnEmptyValueOrAnOptionGivenTwiceIsAUsageErrorForEveryOption) {
  const std::string candidates[] = {"1", "3",       "64",  "auto",  "never", "text", "pov",
                                    "8", "0,0,1,1", "0/1", "x.png", "cpu",   "none"};
  int checked = 0;
  for (const ToolCommandLine& tool : allTools()) {
    for (const std::string& name : valueOptions(tool, false)) {
      SCOPED_TRACE(tool.name + " " + name);
      std::vector<std::string> tail = tool.arguments;
      for (std::vector<std::string> args : {std::vector<std::string>{tool.name, name + "=", "5"},
                                            std::vector<std::string>{tool.name, name, ""}}) {
        args.insert(args.end(), tail.begin(), tail.end());
        auto app = tool.make();
        ParseOutcome r = parse(*app, args);
        EXPECT_EQ(r.status, ExitCode::Usage);
        EXPECT_TRUE(r.err.find(name + ": '' ") != std::string::npos ||
                    r.err.find(name + ": the value is empty") != std::string::npos)
            << r.err;
      }
      // A value the option takes, found among a few.
      std::optional<std::string> good;
      for (const std::string& value : candidates) {
        std::vector<std::string> args{tool.name, name, value};
        args.insert(args.end(), tail.begin(), tail.end());
        auto app = tool.make();
        if (!parse(*app, args).status) {
          good = value;
          break;
        }
      }
      ASSERT_TRUE(good) << "no candidate value";
      for (int times : {2, 3}) {
        std::vector<std::string> args{tool.name};
        for (int i = 0; i < times; ++i) args.insert(args.end(), {name, *good});
        args.insert(args.end(), tail.begin(), tail.end());
        auto app = tool.make();
        ParseOutcome r = parse(*app, args);
        EXPECT_EQ(r.status, ExitCode::Usage);
        EXPECT_EQ(firstLine(r.err),
                  tool.name + ": error: " + name + " given " + (times == 2 ? "twice" : "3 times"));
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 30);
}

}  // namespace
}  // namespace tools
