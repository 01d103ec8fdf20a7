// The tokens of a POV-Ray scene as the parser reads them: lookahead over
// the lexer, the brace depth with its limit, and the skipping that recovers
// after an error or passes over what the reader does not convert. Skipping
// still refuses what would make POV-Ray read a file, so that a scene is
// refused for it whatever else is wrong with it.
#pragma once

#include <cstddef>
#include <deque>
#include <string>
#include <string_view>

#include "libscene/formats/pov/pov_lexer.h"
#include "libscene/formats/pov/pov_reports.h"

namespace scene {

class PovTokenStream : public PovReports {
 protected:
  PovTokenStream(std::string_view text, const ReadOptions& options, DiagnosticList& out);

  // The token k ahead, read from the lexer on demand; past the token limit
  // reading stops [pov-limit]. Inline, as take() is: every token passes here.
  const PovToken& peek(std::size_t k = 0) {
    if (ahead_.size() > k) return ahead_[k];
    return readAhead(k);
  }

  // The next token, taken. Braces are counted; past kMaxBraceDepth open
  // blocks reading stops [pov-limit].
  PovToken take() {
    PovToken token = peek();
    ahead_.pop_front();
    if (token.isSymbol('{')) {
      if (++depth_ > kMaxBraceDepth) bracesTooDeep(token);
    } else if (token.isSymbol('}')) {
      --depth_;
    }
    return token;
  }

  // Puts a taken token back in front (not a brace: the depth stays).
  void putBack(const PovToken& token) { ahead_.push_front(token); }

  bool acceptSymbol(char c) {
    if (!peek().isSymbol(c)) return false;
    take();
    return true;
  }

  bool acceptWord(std::string_view w) {
    if (!peek().isWord(w)) return false;
    take();
    return true;
  }

  // The symbol `c`, taken; else a syntax error naming `where` and what was
  // found.
  PovToken expectSymbol(char c, std::string_view where);

  // A token as an error message names it: 'sphere', a string, the end of
  // the file.
  static std::string describe(const PovToken& t);

  // The blocks open now.
  int depth() const { return depth_; }
  // After a '}' that closed no block: no block is open, as before it.
  void forgetStrayBrace();

  // --- Skipping ------------------------------------------------------------

  // After an unsupported keyword: its block, if one follows, is skipped.
  void skipBlockAfter();
  // Skips to the brace that closes the innermost open block.
  void skipToBlockEnd();
  // Skips a parenthesised list (a macro call's arguments), nested ones
  // included.
  void skipParentheses();
  // Skips a conditional, loop or macro up to its #end, nested ones included.
  void skipDirectiveBlock();
  // After an error: to the end of the statement it stands in, which began
  // at depth `depth0`.
  void recover(int depth0);

  const PovLexer& lexer() const { return lexer_; }

 private:
  static constexpr int kMaxBraceDepth = 256;

  const PovToken& readAhead(std::size_t k);
  [[noreturn]] void bracesTooDeep(const PovToken& brace);
  void checkFileReading(const PovToken& t);
  void checkDirectiveWhileSkipping(const PovToken& t);

  PovLexer lexer_;
  std::deque<PovToken> ahead_;
  int depth_ = 0;
};

}  // namespace scene
