// The tokens of POV-Ray's scene language, one at a time, with their spans.
//
// Comments of both kinds are skipped (block comments nest, as in POV-Ray);
// the comments that carry exact values (kPovExactComment) are kept aside
// and tied to the token that follows them. Tokens are made on demand, so a
// large file costs no memory for its tokens; a token limit bounds the time.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "scenefile/diagnostic.h"

namespace scene {

// The comment prefix under which the POV-Ray writer carries exact values
// (pov_writer.h lists the forms). These are the file format's words, kept
// as the files already written carry them: it names the tool that wrote
// them, and conversions stay byte for byte what they were.
inline constexpr std::string_view kPovExactComment = "// sfconvert:";

enum class PovTokenKind : std::uint8_t {
  End,        // the end of the text
  Number,     // a literal without sign: 1, 2.5, .5, 1e-3
  Word,       // a keyword or an identifier
  String,     // "...", text without the quotes and escapes as written
  Directive,  // #declare, #include, ...: text is the word without '#'
  Symbol,     // one character of punctuation: { } < > ( ) [ ] , ; = + - * / ! ? : . & |
};

struct PovToken {
  PovTokenKind kind = PovTokenKind::End;
  std::string_view text;
  double number = 0.0;
  SourceSpan span;
  std::size_t offset = 0;  // of the token's first byte in the text
  // The exact-value comment right before this token (its text after the
  // prefix), or -1: an index into PovLexer::exactComments().
  int exactComment = -1;

  bool is(PovTokenKind k, std::string_view t) const { return kind == k && text == t; }
  bool isSymbol(char c) const {
    return kind == PovTokenKind::Symbol && text.size() == 1 && text[0] == c;
  }
  bool isWord(std::string_view w) const { return kind == PovTokenKind::Word && text == w; }
};

class PovLexer {
 public:
  // Problems in the text (a bad byte, an unclosed comment or string, a number
  // out of range) are reported to `out` and the lexer reads on.
  PovLexer(std::string_view text, DiagnosticList& out);

  // The next token; End at the end, and for ever after.
  PovToken next();

  std::size_t tokenCount() const { return tokenCount_; }
  // A comment that carries exact values: its words after the prefix.
  struct ExactComment {
    std::string_view text;
    SourceSpan span;
  };
  // Those comments, in file order.
  const std::vector<ExactComment>& exactComments() const { return exactComments_; }

 private:
  void skipBlanksAndComments();
  SourceSpan spanAt(std::size_t offset, std::size_t length) const;
  PovToken make(PovTokenKind kind, std::size_t start, std::size_t end);

  std::string_view text_;
  DiagnosticList& out_;
  std::size_t pos_ = 0;
  std::uint32_t line_ = 1;
  std::size_t lineStart_ = 0;
  std::size_t tokenCount_ = 0;
  int pendingComment_ = -1;
  std::vector<ExactComment> exactComments_;
};

}  // namespace scene
