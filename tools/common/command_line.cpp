#include "tools/common/command_line.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <string_view>
#include <vector>

#include "scenefile/spelling.h"
#include "tools/common/option_checks.h"

namespace tools {

namespace {

std::string upperCase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

bool takesValue(const CLI::Option& option) {
  return option.get_expected_max() != 0;
}

bool takesMany(const CLI::Option& option) {
  return option.get_expected_max() == CLI::detail::expected_max_vector_size;
}

// The word --help shows for an option's value: the option's own
// (option_text, "FILE"), else one for its type.
std::string metavariable(const CLI::Option& option) {
  if (!option.get_option_text().empty()) return option.get_option_text();
  std::string type = option.get_type_name();
  type = type.substr(0, type.find(':'));
  if (type == "INT" || type == "UINT") return "N";
  if (type == "FLOAT") return "X";
  return type.empty() ? "VALUE" : type;
}

// The width help is wrapped to, as GNU tools do.
constexpr std::size_t kHelpWidth = 79;

// `text` in lines of at most `width` characters, broken at spaces, each
// after the first indented by `indent` spaces.
std::string wrap(const std::string& text, std::size_t width, std::size_t indent) {
  std::string wrapped;
  std::size_t lineLength = 0;
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t end = text.find(' ', at);
    if (end == std::string::npos) end = text.size();
    std::string word = text.substr(at, end - at);
    if (lineLength > 0 && lineLength + 1 + word.size() > width) {
      wrapped += "\n" + std::string(indent, ' ');
      lineLength = 0;
    } else if (lineLength > 0) {
      wrapped += ' ';
      ++lineLength;
    }
    wrapped += word;
    lineLength += word.size();
    at = end + 1;
  }
  return wrapped;
}

// Help in the GNU layout, which help2man turns into a man page:
//   -o, --output FILE         the image to write; its extension picks the
//                             format (default: ...)
class HelpFormatter : public CLI::Formatter {
 public:
  HelpFormatter() {
    column_width(28);
    label("Positionals", "Arguments");
  }

  // Usage first, then what the tool does, as GNU tools and help2man have it.
  std::string make_help(const CLI::App* app, std::string name, CLI::AppFormatMode) const override {
    return make_usage(app, name) + "\n" + wrap(app->get_description(), kHelpWidth, 0) + "\n" +
           make_positionals(app) + make_groups(app, CLI::AppFormatMode::Normal) + "\n" +
           make_footer(app);
  }

  std::string make_option(const CLI::Option* option, bool positional) const override {
    std::string left = "  " + make_option_name(option, positional) + make_option_opts(option);
    std::size_t column = get_column_width();
    std::string line = left;
    if (left.size() + 2 > column) {
      line += "\n" + std::string(column, ' ');
    } else {
      line += std::string(column - left.size(), ' ');
    }
    return line + wrap(make_option_desc(option), kHelpWidth - column, column) + "\n";
  }

  std::string make_option_name(const CLI::Option* option, bool positional) const override {
    if (positional) return make_option_usage(option);
    return optionDisplayName(*option);
  }

  std::string make_option_opts(const CLI::Option* option) const override {
    if (option->get_positional() || !takesValue(*option)) return "";
    return " " + metavariable(*option);
  }

  std::string make_option_desc(const CLI::Option* option) const override {
    std::string text = option->get_description();
    if (!option->get_positional() && takesValue(*option) && !option->get_default_str().empty()) {
      text += " (default: " + option->get_default_str() + ")";
    }
    return text;
  }

  std::string make_option_usage(const CLI::Option* option) const override {
    std::string name = upperCase(option->get_name());
    if (takesMany(*option)) name += "...";
    return option->get_required() ? name : "[" + name + "]";
  }
};

bool looksNumeric(std::string_view text) {
  double value = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size();
}

// Every name of every option, for the did-you-mean of an unknown one.
std::vector<std::string> optionNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* option : app.get_options()) {
    for (const std::string& n : option->get_lnames()) names.push_back("--" + n);
  }
  return names;
}

std::string unknownOptionMessage(const CLI::App& app, const std::string& name) {
  std::vector<std::string> names = optionNames(app);
  std::vector<std::string_view> candidates(names.begin(), names.end());
  std::string message = "unknown option '" + name + "'";
  if (auto closest = scene::suggestSpelling(name, candidates)) {
    message += "; did you mean '" + std::string(*closest) + "'?";
  }
  return message;
}

// The option named at the start of one of CLI11's messages ("--width: ...").
std::string leadingName(const std::string& message) {
  std::size_t colon = message.find(':');
  return colon == std::string::npos ? std::string() : message.substr(0, colon);
}

std::string lowerFirst(std::string text) {
  if (!text.empty()) text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
  return text;
}

std::string describeRequired(const CLI::App& app, const std::string& message) {
  std::string name = message.substr(0, message.find(" is required"));
  const CLI::Option* option = app.get_option_no_throw(name);
  if (option && option->get_positional()) return "missing " + upperCase(option->get_name());
  return "missing " + name;
}

// The arguments as App::parse takes them, last first, with "--name=" (an
// option that takes a value, nothing after the '=') made "--name" and an
// empty value: CLI11 would drop the empty value and take the next argument
// instead (--width= 5 as --width 5), where the option's checks refuse ''.
std::vector<std::string> parserArguments(const CLI::App& app, int argc, const char* const* argv) {
  std::vector<std::string> args;
  bool onlyArguments = false;  // after "--"
  for (int i = 1; i < argc; ++i) {
    std::string word = argv[i];
    onlyArguments = onlyArguments || word == "--";
    if (!onlyArguments && word.size() > 3 && word.starts_with("--") && word.back() == '=') {
      word.pop_back();
      const CLI::Option* option = app.get_option_no_throw(word);
      if (option && takesValue(*option)) {
        args.push_back(word);
        args.emplace_back();
        continue;
      }
      word += '=';
    }
    args.push_back(word);
  }
  std::reverse(args.begin(), args.end());
  return args;
}

// No option's value may be empty: what a number, a choice or a region check
// says of '' comes first, and an option with no check of its own (-o "")
// says this.
void refuseEmptyValues(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    if (option->get_positional() || !takesValue(*option)) continue;
    option->check(CLI::Validator(
        [](std::string& value) { return value.empty() ? "the value is empty" : std::string(); }, "",
        "not empty"));
  }
}

}  // namespace

std::string optionDisplayName(const CLI::Option& option) {
  if (option.get_positional()) return upperCase(option.get_name());
  std::string names;
  for (const std::string& s : option.get_snames()) names += (names.empty() ? "-" : ", -") + s;
  for (const std::string& l : option.get_lnames()) names += (names.empty() ? "--" : ", --") + l;
  return names;
}

std::unique_ptr<CLI::App> makeToolApp(const std::string& name, const std::string& description,
                                      CommonFlags& flags) {
  auto app = std::make_unique<CLI::App>(description, name);
  app->formatter(std::make_shared<HelpFormatter>());
  app->option_defaults()->always_capture_default();
  app->set_help_flag("-h,--help", "print this help and exit");
  app->set_version_flag("-V,--version", std::string(name) + " " + SCENEFILE_VERSION,
                        "print the version and exit");
  CLI::Option* quiet = app->add_flag("-q,--quiet", flags.quiet, "print only errors");
  CLI::Option* verbose = app->add_flag("-v,--verbose", flags.verbose,
                                       "also print what was decided and how long each step took");
  quiet->excludes(verbose);
  app->add_option("--color", flags.color,
                  "colour in diagnostics: auto (on a terminal, unless NO_COLOR is set), always "
                  "or never")
      ->option_text("WHEN")
      ->check(oneOf({"auto", "always", "never"}));
  app->footer(exitStatusHelp());
  return app;
}

std::string exitStatusHelp() {
  return "Exit status:\n"
         "  0  success (warnings allowed)\n"
         "  1  the input is invalid, or the work cannot be done as asked\n"
         "  2  the command line is wrong\n"
         "  3  a file could not be read or written\n"
         "  4  memory or threads ran out";
}

std::optional<std::string> unknownOption(const CLI::App& app, int argc, const char* const* argv) {
  for (int i = 1; i < argc; ++i) {
    std::string_view word = argv[i];
    if (word == "--") return std::nullopt;
    if (word.size() < 2 || word[0] != '-' || looksNumeric(word)) continue;
    if (word.starts_with("--")) {
      std::string name(word.substr(0, word.find('=')));
      const CLI::Option* option = app.get_option_no_throw(name);
      if (!option) return name;
      if (takesValue(*option) && word.find('=') == std::string_view::npos) ++i;
      continue;
    }
    // -x, -xVALUE, or short flags together (-qv).
    for (std::size_t k = 1; k < word.size(); ++k) {
      const CLI::Option* option = app.get_option_no_throw(std::string{'-', word[k]});
      if (!option) return k == 1 ? std::string(word) : std::string{'-', word[k]};
      if (takesValue(*option)) {
        if (k + 1 == word.size()) ++i;
        break;
      }
    }
  }
  return std::nullopt;
}

std::string describeCommandLineError(const CLI::App& app, int argc, const char* const* argv,
                                     const CLI::ParseError& error) {
  // An unknown flag first, whatever CLI11 found: "sfcheck --bogus" is not
  // missing its files so much as given a flag it does not know.
  if (std::optional<std::string> unknown = unknownOption(app, argc, argv)) {
    return unknownOptionMessage(app, *unknown);
  }
  std::string message = error.what();
  std::string name = leadingName(message);
  if (dynamic_cast<const CLI::RequiredError*>(&error)) return describeRequired(app, message);
  if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
    std::size_t colon = message.rfind(": ");
    return "unexpected argument '" + message.substr(colon + 2) + "'";
  }
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) && !name.empty()) {
    // CLI11 says "At Most 1 required but received 2" of an option given
    // twice: a tool that writes files has no "last one wins" to guess at.
    const CLI::Option* option = app.get_option_no_throw(name);
    if (option && !takesMany(*option) && option->count() > 1) {
      return name + " given " +
             (option->count() == 2 ? "twice" : std::to_string(option->count()) + " times");
    }
    return name + " needs a value";
  }
  if (const auto* excludes = dynamic_cast<const CLI::ExcludesError*>(&error)) {
    std::string text = excludes->what();
    std::size_t at = text.find(" excludes ");
    if (at != std::string::npos) {
      return text.substr(0, at) + " and " + text.substr(at + 10) + " cannot be used together";
    }
  }
  if (dynamic_cast<const CLI::ConversionError*>(&error)) {
    // "Could not convert: --seed = abc"
    std::size_t equals = message.find(" = ");
    std::size_t colon = message.find(": ");
    if (equals != std::string::npos && colon != std::string::npos) {
      return message.substr(colon + 2, equals - colon - 2) + ": '" + message.substr(equals + 3) +
             "' is not a valid value";
    }
  }
  return lowerFirst(message);
}

std::optional<ExitCode> parseCommandLine(CLI::App& app, int argc, const char* const* argv,
                                         std::ostream& out, std::ostream& err) {
  refuseEmptyValues(app);
  try {
    app.parse(parserArguments(app, argc, argv));
  } catch (const CLI::CallForHelp&) {
    out << app.help();
    return ExitCode::Success;
  } catch (const CLI::CallForAllHelp&) {
    out << app.help("", CLI::AppFormatMode::All);
    return ExitCode::Success;
  } catch (const CLI::CallForVersion&) {
    out << app.version() << "\n";
    return ExitCode::Success;
  } catch (const CLI::ParseError& e) {
    err << app.get_name() << ": error: " << describeCommandLineError(app, argc, argv, e) << "\n";
    err << "  hint: run '" << app.get_name() << " --help' for the options\n";
    return ExitCode::Usage;
  }
  return std::nullopt;
}

}  // namespace tools
