// The editors' grammars name the line formats' keywords again, by hand: in
// the regular expressions of editors/vscode/syntaxes and the keyword lists
// of editors/nvim/syntax. Held here to the library's one table, so that a
// keyword added, renamed or dropped there shows in every editor alike.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "scenefile/keywords.h"
#include "tools/sfls/feature_test_support.h"

namespace sfls {
namespace {

using feature_test::readSource;
using feature_test::sourcePath;
using scene::Format;
using scene::KeywordInfo;
using scene::KeywordPlace;
using WordSet = std::set<std::string>;

struct EditorFile {
  const char* path;
  Format format;
};

constexpr EditorFile kTextMateGrammars[] = {
    {"editors/vscode/syntaxes/scenefile.tmLanguage.json", Format::SceneFile},
    {"editors/vscode/syntaxes/instructions.tmLanguage.json", Format::InstructionFile},
};

constexpr EditorFile kVimSyntaxes[] = {
    {"editors/nvim/syntax/scenefile.vim", Format::SceneFile},
    {"editors/nvim/syntax/scenefile_instructions.vim", Format::InstructionFile},
};

WordSet tableWords(Format format) {
  WordSet words;
  for (const KeywordInfo& row : scene::keywords()) {
    if (row.format == format) words.emplace(row.word);
  }
  return words;
}

std::string listed(const WordSet& words) {
  std::string out;
  for (const std::string& word : words) out += (out.empty() ? "" : " ") + word;
  return out.empty() ? "(none)" : out;
}

// What `a` has that `b` lacks.
WordSet without(const WordSet& a, const WordSet& b) {
  WordSet out;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::inserter(out, out.end()));
  return out;
}

// The scopes that editors' themes show as keywords. Words the grammars mark
// wrong (invalid.*) or as numbers and names (constant.*, string.*) are not.
bool isKeywordScope(const std::string& scope) {
  for (const char* family : {"keyword.", "entity.", "support.", "storage."}) {
    if (scope.rfind(family, 0) == 0) return true;
  }
  return false;
}

// ---- TextMate grammars ------------------------------------------------------

// One `match` or `begin` expression of a grammar, with the scope of the
// whole match and of each numbered capture.
struct GrammarRule {
  std::string key;  // where it stands in the grammar, for messages
  std::string regex;
  std::string scope;
  std::map<std::size_t, std::string> captureScopes;
};

void collectRules(const nlohmann::json& rule, const std::string& key,
                  std::vector<GrammarRule>& out) {
  for (const char* field : {"match", "begin", "end"}) {
    if (!rule.contains(field)) continue;
    GrammarRule collected{key + "." + field, rule[field], rule.value("name", ""), {}};
    // `captures` serves begin and end alike where they have none their own.
    std::string own = field == std::string("match") ? "captures" : field + std::string("Captures");
    for (const std::string& capturesKey : {own, std::string("captures")}) {
      if (!rule.contains(capturesKey)) continue;
      for (const auto& [number, capture] : rule[capturesKey].items()) {
        collected.captureScopes.emplace(std::stoul(number), capture.value("name", ""));
      }
    }
    out.push_back(std::move(collected));
  }
  if (rule.contains("patterns")) {
    for (std::size_t i = 0; i < rule["patterns"].size(); ++i) {
      collectRules(rule["patterns"][i], key + ".patterns[" + std::to_string(i) + "]", out);
    }
  }
}

// Every expression of the grammar, in its repository and its patterns.
std::vector<GrammarRule> allRules(const nlohmann::json& grammar) {
  std::vector<GrammarRule> out;
  collectRules(grammar, "patterns", out);
  if (!grammar.contains("repository")) return out;
  for (const auto& [name, rule] : grammar["repository"].items()) collectRules(rule, name, out);
  return out;
}

// The top level's `match` rules in the order the tokenizer tries them (the
// grammars have no begin/end rule; one would go untried here).
std::vector<GrammarRule> topLevelRules(const nlohmann::json& grammar) {
  std::vector<GrammarRule> out;
  for (const nlohmann::json& pattern : grammar.at("patterns")) {
    std::string include = pattern.value("include", "");
    const nlohmann::json& rule =
        include.empty() ? pattern
                        : grammar.at("repository").at(include.substr(include.find('#') + 1));
    if (!rule.contains("match")) continue;
    std::vector<GrammarRule> collected;
    collectRules(rule, include, collected);
    out.push_back(collected.front());
  }
  return out;
}

// A group of an expression that is an alternation of plain words: `(A|B)`,
// `(?:A|B)`, `(?i:A|B)`.
struct WordGroup {
  WordSet words;
  std::string scope;  // of the innermost capture around it that has one
  bool inLookaround = false;
};

struct OpenGroup {
  std::size_t start;
  std::optional<std::size_t> capture;
  bool lookaround;
};

std::optional<WordSet> wordsOf(std::string body) {
  static const std::regex kFlagPrefix(R"(^\?[imx-]*:)");
  body = std::regex_replace(body, kFlagPrefix, "");
  static const std::regex kAlternation(R"([A-Za-z_][A-Za-z0-9_]*(\|[A-Za-z_][A-Za-z0-9_]*)*)");
  if (!std::regex_match(body, kAlternation)) return std::nullopt;
  WordSet words;
  std::stringstream alternatives(body);
  for (std::string word; std::getline(alternatives, word, '|');) words.insert(word);
  return words;
}

std::string scopeAround(const GrammarRule& rule, const std::vector<OpenGroup>& open) {
  for (auto group = open.rbegin(); group != open.rend(); ++group) {
    if (!group->capture) continue;
    auto found = rule.captureScopes.find(*group->capture);
    if (found != rule.captureScopes.end() && !found->second.empty()) return found->second;
  }
  return rule.scope;
}

// The word groups of `rule`'s expression, read from its text: escapes and
// character classes skipped, each plain `(` numbered as a capture.
std::vector<WordGroup> wordGroups(const GrammarRule& rule) {
  const std::string& re = rule.regex;
  std::vector<WordGroup> out;
  std::vector<OpenGroup> open;
  std::size_t captures = 0;
  for (std::size_t i = 0; i < re.size(); ++i) {
    if (re[i] == '\\') {
      ++i;
    } else if (re[i] == '[') {
      i += re.compare(i, 2, "[^") == 0 ? 2 : 1;  // a ']' first is literal
      while (i < re.size() && re[i] != ']') i += re[i] == '\\' ? 2 : 1;
    } else if (re[i] == '(') {
      bool plain = re.compare(i + 1, 1, "?") != 0;
      bool lookaround =
          !plain && (re.compare(i + 1, 2, "?=") == 0 || re.compare(i + 1, 2, "?!") == 0 ||
                     re.compare(i + 1, 3, "?<=") == 0 || re.compare(i + 1, 3, "?<!") == 0);
      open.push_back({i, plain ? std::optional(++captures) : std::nullopt, lookaround});
    } else if (re[i] == ')' && !open.empty()) {
      OpenGroup group = open.back();
      std::optional<WordSet> words = wordsOf(re.substr(group.start + 1, i - group.start - 1));
      if (words) {
        bool inLookaround =
            std::any_of(open.begin(), open.end(), [](const OpenGroup& g) { return g.lookaround; });
        out.push_back({*words, scopeAround(rule, open), inLookaround});
      }
      open.pop_back();
    }
  }
  return out;
}

// Oniguruma's \x{HHHH} in the terms of std::regex (ECMAScript). The test's
// lines are ASCII, so any one non-ASCII byte stands in for a code point
// above it (the grammars' byte-order mark).
std::string ecmaScriptOf(const std::string& oniguruma) {
  static const std::regex kCodePoint(R"(\\x\{([0-9A-Fa-f]+)\})");
  std::string out;
  auto last = oniguruma.cbegin();
  for (std::sregex_iterator it(oniguruma.begin(), oniguruma.end(), kCodePoint), end; it != end;
       ++it) {
    out.append(last, (*it)[0].first);
    unsigned long point = std::stoul((*it)[1].str(), nullptr, 16);
    char hex[8];
    std::snprintf(hex, sizeof hex, "\\x%02lX", point < 0x80 ? point : 0xFFul);
    out += hex;
    last = (*it)[0].second;
  }
  out.append(last, oniguruma.cend());
  return out;
}

struct Token {
  std::size_t begin;
  std::size_t end;
  std::string scope;
};

struct CompiledRule {
  const GrammarRule* rule;
  std::regex regex;
};

// The tokens of one line as a TextMate tokenizer finds them for `match`
// rules: at each place the rule matching first wins, the earlier listed on
// a tie; each match gives its captures' scopes and its own.
std::vector<Token> tokenize(const std::vector<CompiledRule>& rules, const std::string& line) {
  std::vector<Token> tokens;
  for (std::size_t at = 0; at < line.size();) {
    std::optional<std::pair<const CompiledRule*, std::smatch>> first;
    for (const CompiledRule& rule : rules) {
      std::smatch match;
      auto flags =
          at == 0 ? std::regex_constants::match_default : std::regex_constants::match_prev_avail;
      if (!std::regex_search(line.cbegin() + at, line.cend(), match, rule.regex, flags)) continue;
      if (!first || match.position(0) < first->second.position(0)) first.emplace(&rule, match);
    }
    if (!first) break;
    const auto& [rule, match] = *first;
    for (const auto& [number, scope] : rule->rule->captureScopes) {
      if (number < match.size() && match[number].matched && !scope.empty()) {
        std::size_t begin = at + match.position(number);
        tokens.push_back({begin, begin + match.length(number), scope});
      }
    }
    std::size_t begin = at + match.position(0);
    if (!rule->rule->scope.empty())
      tokens.push_back({begin, begin + match.length(0), rule->rule->scope});
    at = begin + std::max<std::size_t>(match.length(0), 1);
  }
  return tokens;
}

// A line where `row`'s word stands, and where the word begins in it: after
// what comes before it at its place, followed by its first argument.
std::pair<std::string, std::size_t> lineWith(const KeywordInfo& row) {
  std::string before;
  if (row.place == KeywordPlace::BlockName || row.place == KeywordPlace::SectionName) {
    before = "START ";
  } else if (row.place == KeywordPlace::ObjectKindName) {
    before = "START OBJECT ";
  }
  std::string_view argument = row.arguments.substr(0, row.arguments.find(" | "));
  std::string line = before + std::string(row.word);
  if (!argument.empty()) line += " " + std::string(argument);
  return {line, before.size()};
}

nlohmann::json readGrammar(const EditorFile& file) {
  return nlohmann::json::parse(readSource(file.path));
}

TEST(EditorGrammars, EveryGrammarOfTheEditorsIsHeldToTheTable) {
  std::set<std::string> held;
  for (const EditorFile& file : kTextMateGrammars) held.insert(file.path);
  for (const EditorFile& file : kVimSyntaxes) held.insert(file.path);
  for (const char* folder : {"editors/vscode/syntaxes", "editors/nvim/syntax"}) {
    for (const auto& entry : std::filesystem::directory_iterator(sourcePath(folder))) {
      std::string path = std::string(folder) + "/" + entry.path().filename().string();
      EXPECT_TRUE(held.count(path)) << path << " is not held to the keyword table here";
    }
  }
}

TEST(EditorGrammars, TextMateKeywordsAreTheTables) {
  for (const EditorFile& file : kTextMateGrammars) {
    SCOPED_TRACE(file.path);
    WordSet table = tableWords(file.format);
    WordSet marked;
    for (const GrammarRule& rule : allRules(readGrammar(file))) {
      for (const WordGroup& group : wordGroups(rule)) {
        EXPECT_EQ(without(group.words, table), WordSet{})
            << rule.key << " names words the keyword table does not have";
        if (isKeywordScope(group.scope) && !group.inLookaround) {
          marked.insert(group.words.begin(), group.words.end());
        }
      }
    }
    EXPECT_EQ(listed(without(table, marked)), "(none)") << "keywords no rule marks as keywords";
    EXPECT_EQ(listed(without(marked, table)), "(none)") << "keywords the table does not have";
  }
}

TEST(EditorGrammars, TextMateGrammarsTokenizeEveryKeywordAtItsPlace) {
  for (const EditorFile& file : kTextMateGrammars) {
    SCOPED_TRACE(file.path);
    nlohmann::json grammar = readGrammar(file);
    std::vector<GrammarRule> rules = topLevelRules(grammar);
    std::vector<CompiledRule> compiled;
    for (const GrammarRule& rule : rules) {
      try {
        compiled.push_back({&rule, std::regex(ecmaScriptOf(rule.regex), std::regex::ECMAScript)});
      } catch (const std::regex_error&) {
        // Lookbehind and (?i:...) are Oniguruma's only: the number and the
        // wrong-case rules go untried, which no keyword's line needs.
        bool marksKeywords = isKeywordScope(rule.scope);
        for (const auto& [number, scope] : rule.captureScopes)
          marksKeywords |= isKeywordScope(scope);
        EXPECT_FALSE(marksKeywords) << rule.key << " marks keywords but std::regex cannot read it";
      }
    }
    for (const KeywordInfo& row : scene::keywords()) {
      if (row.format != file.format) continue;
      auto [line, wordBegin] = lineWith(row);
      // Named apart: clang before 16 captures no structured binding.
      const auto begin = wordBegin;
      std::vector<Token> tokens = tokenize(compiled, line);
      bool keyword = std::any_of(tokens.begin(), tokens.end(), [&](const Token& token) {
        return token.begin == begin && token.end == begin + row.word.size() &&
               isKeywordScope(token.scope);
      });
      EXPECT_TRUE(keyword) << row.word << " is no keyword in the line \"" << line << "\"";
    }
  }
}

// ---- Vim syntax files -------------------------------------------------------

// The words of every `syntax keyword` command, continuation lines joined.
WordSet vimKeywords(const std::string& text) {
  std::vector<std::string> commands;
  std::stringstream lines(text);
  static const std::regex kContinuation(R"(^\s*\\(.*)$)");
  for (std::string line; std::getline(lines, line);) {
    std::smatch continued;
    if (!commands.empty() && std::regex_match(line, continued, kContinuation)) {
      commands.back() += " " + continued[1].str();
    } else {
      commands.push_back(line);
    }
  }
  static const std::regex kKeywordCommand(R"(^\s*syn(?:tax)?\s+keyword\s+\S+\s+(.*)$)");
  static const std::regex kWord(R"([A-Za-z_][A-Za-z0-9_]*)");
  static const WordSet kOptions = {"contained", "transparent", "skipwhite", "skipnl",
                                   "skipempty", "conceal",     "display"};
  WordSet words;
  for (const std::string& command : commands) {
    std::smatch keyword;
    if (!std::regex_match(command, keyword, kKeywordCommand)) continue;
    std::stringstream list(keyword[1].str());
    for (std::string word; list >> word;) {
      if (std::regex_match(word, kWord) && !kOptions.count(word)) words.insert(word);
    }
  }
  return words;
}

TEST(EditorGrammars, VimKeywordsAreTheTables) {
  for (const EditorFile& file : kVimSyntaxes) {
    SCOPED_TRACE(file.path);
    WordSet table = tableWords(file.format);
    WordSet keywords = vimKeywords(readSource(file.path));
    EXPECT_EQ(listed(without(table, keywords)), "(none)") << "keywords Vim does not show";
    EXPECT_EQ(listed(without(keywords, table)), "(none)") << "keywords the table does not have";
  }
}

}  // namespace
}  // namespace sfls
