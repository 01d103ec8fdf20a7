#include "tools/completion/bash_completion.h"

#include <CLI/CLI.hpp>
#include <sstream>

#include "tools/common/option_checks.h"

namespace tools {

namespace {

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& w : words) text += (text.empty() ? "" : " ") + w;
  return text;
}

// Every name of the option as typed: "-o|--output".
std::vector<std::string> spellings(const CLI::Option& option) {
  std::vector<std::string> names;
  for (const std::string& s : option.get_snames()) names.push_back("-" + s);
  for (const std::string& l : option.get_lnames()) names.push_back("--" + l);
  return names;
}

std::string casePattern(const CLI::Option& option) {
  std::string pattern;
  for (const std::string& name : spellings(option)) pattern += (pattern.empty() ? "" : "|") + name;
  return pattern;
}

// The case branch for an option that takes a value: its choices or files
// of its extensions; empty for one with nothing to offer (a number).
std::string valueBranch(const CLI::Option& option, const CompletedFiles& files) {
  std::vector<std::string> choices = choicesOf(option);
  auto fileOption = files.options.find("--" + option.get_lnames().front());
  std::string completion;
  if (!choices.empty()) {
    completion = "COMPREPLY=($(compgen -W '" + joined(choices) + "' -- \"$cur\"))";
  } else if (fileOption != files.options.end()) {
    completion = "_scenefile_files '" + joined(fileOption->second) + "'";
  } else {
    return {};
  }
  return "    " + casePattern(option) + ")\n      " + completion + "\n      return ;;\n";
}

}  // namespace

std::string bashCompletionScript(const CLI::App& app, const CompletedFiles& files) {
  const std::string name = app.get_name();
  std::vector<std::string> flags;
  std::string branches;
  std::string numbers;  // the options whose value is typed, not chosen
  for (const CLI::Option* option : app.get_options()) {
    if (option->get_positional()) continue;
    for (const std::string& spelling : spellings(*option)) flags.push_back(spelling);
    if (option->get_expected_max() == 0) continue;
    std::string branch = valueBranch(*option, files);
    if (branch.empty()) {
      numbers += (numbers.empty() ? "" : "|") + casePattern(*option);
    } else {
      branches += branch;
    }
  }
  if (!numbers.empty()) branches += "    " + numbers + ")\n      return ;;\n";
  std::ostringstream script;
  script << "# bash completion for " << name
         << ", made from its command line by make_completions;\n"
         << "# installed in share/bash-completion/completions, where bash-completion finds it.\n\n"
         << "# Folders, and the files with one of the extensions in $1.\n"
         << "_scenefile_files() {\n"
         << "  local ext IFS=$'\\n'\n"
         << "  COMPREPLY=($(compgen -d -- \"$cur\"))\n"
         << "  for ext in ${1// /$'\\n'}; do\n"
         << "    COMPREPLY+=($(compgen -f -X \"!*.$ext\" -- \"$cur\"))\n"
         << "  done\n"
         << "}\n\n"
         << "_" << name << "() {\n"
         << "  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}\n"
         << "  # --opt=value: bash splits it at the '=' (COMP_WORDBREAKS).\n"
         << "  if [[ $cur == = ]]; then\n"
         << "    prev=${COMP_WORDS[COMP_CWORD-1]}; cur=\n"
         << "  elif [[ $prev == = ]]; then\n"
         << "    prev=${COMP_WORDS[COMP_CWORD-2]}\n"
         << "  fi\n"
         << "  case $prev in\n"
         << branches << "  esac\n"
         << "  if [[ $cur == -* ]]; then\n"
         << "    COMPREPLY=($(compgen -W '" << joined(flags) << "' -- \"$cur\"))\n"
         << "    return\n"
         << "  fi\n"
         << "  _scenefile_files '" << joined(files.arguments) << "'\n"
         << "}\n"
         << "complete -o filenames -F _" << name << " " << name << "\n";
  return script.str();
}

}  // namespace tools
