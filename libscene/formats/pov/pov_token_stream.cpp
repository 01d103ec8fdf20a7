#include "libscene/formats/pov/pov_token_stream.h"

#include <algorithm>

#include "libscene/formats/pov/pov_keywords.h"
#include "libscene/formats/pov/pov_limits.h"
#include "libscene/formats/pov/pov_names.h"

namespace scene {

PovTokenStream::PovTokenStream(std::string_view text, const ReadOptions& options,
                               DiagnosticList& out)
    : PovReports(options, out), lexer_(text, out) {}

const PovToken& PovTokenStream::readAhead(std::size_t k) {
  while (ahead_.size() <= k) {
    ahead_.push_back(lexer_.next());
    if (lexer_.tokenCount() > kMaxPovTokens) {
      out_.error(DiagnosticCode::PovLimit, ahead_.back().span,
                 "the file has more than " + std::to_string(kMaxPovTokens) + " tokens: refused");
      throw PovStopReading{};
    }
  }
  return ahead_[k];
}

void PovTokenStream::bracesTooDeep(const PovToken& brace) {
  out_.error(DiagnosticCode::PovLimit, brace.span,
             "blocks nest more than " + std::to_string(kMaxBraceDepth) + " deep: refused");
  throw PovStopReading{};
}

PovToken PovTokenStream::expectSymbol(char c, std::string_view where) {
  if (!peek().isSymbol(c)) {
    fail(peek().span,
         std::string("expected '") + c + "' " + std::string(where) + ", found " + describe(peek()));
  }
  return take();
}

std::string PovTokenStream::describe(const PovToken& t) {
  switch (t.kind) {
    case PovTokenKind::End:
      return "the end of the file";
    case PovTokenKind::String:
      return "a string";
    case PovTokenKind::Directive:
      return "'#" + std::string(t.text) + "'";
    default:
      break;
  }
  return "'" + std::string(t.text.substr(0, 40)) + "'";
}

void PovTokenStream::forgetStrayBrace() {
  depth_ = std::max(depth_, 0);
}

// Whether the token, met while skipping, would make POV-Ray read a file.
void PovTokenStream::checkFileReading(const PovToken& t) {
  if (t.kind == PovTokenKind::Word && isPovFileType(t.text) &&
      peek().kind == PovTokenKind::String) {
    out_.error(DiagnosticCode::PovRefused, t.span,
               "'" + std::string(t.text) + " \"" + std::string(peek().text.substr(0, 60)) +
                   "\"' would read another file: refused")
        .hint = "this reader reads no file but the scene itself";
  }
}

// A file is refused for what it would read even where this reader skips.
void PovTokenStream::checkDirectiveWhileSkipping(const PovToken& t) {
  if (t.text == "include" && peek().kind == PovTokenKind::String &&
      !isPovStandardInclude(peek().text)) {
    out_.error(DiagnosticCode::PovRefused, t.span,
               "'#include \"" + std::string(peek().text.substr(0, 60)) +
                   "\"' would read another file: refused")
        .hint = "only POV-Ray's standard include files may be included";
  } else if (t.text == "fopen" || t.text == "read") {
    out_.error(DiagnosticCode::PovRefused, t.span,
               "'#" + std::string(t.text) + "' reads files: refused");
  }
}

void PovTokenStream::skipBlockAfter() {
  if (!peek().isSymbol('{')) return;
  int depth = depth_;
  take();
  while (depth_ > depth && peek().kind != PovTokenKind::End) {
    PovToken t = take();
    checkFileReading(t);
    if (t.kind == PovTokenKind::Directive) checkDirectiveWhileSkipping(t);
  }
}

void PovTokenStream::skipToBlockEnd() {
  int depth = depth_;
  while (peek().kind != PovTokenKind::End && !(depth_ == depth && peek().isSymbol('}'))) {
    PovToken t = take();
    checkFileReading(t);
  }
}

void PovTokenStream::skipParentheses() {
  int level = 0;
  while (peek().kind != PovTokenKind::End) {
    PovToken t = take();
    if (t.isSymbol('(')) ++level;
    if (t.isSymbol(')') && --level <= 0) return;
  }
}

void PovTokenStream::skipDirectiveBlock() {
  int level = 1;
  while (peek().kind != PovTokenKind::End) {
    PovToken t = take();
    checkFileReading(t);
    if (t.kind != PovTokenKind::Directive) continue;
    checkDirectiveWhileSkipping(t);
    std::string_view n = t.text;
    if (n == "if" || n == "ifdef" || n == "ifndef" || n == "switch" || n == "while" || n == "for" ||
        n == "macro") {
      ++level;
    } else if (n == "end" && --level == 0) {
      return;
    }
  }
}

// The end of a statement (see the statement loop) is out of the blocks
// opened since it began, or else what can start a statement.
void PovTokenStream::recover(int depth0) {
  bool inside = depth_ > depth0;
  while (peek().kind != PovTokenKind::End) {
    if (depth_ > depth0) {
      take();
      continue;
    }
    if (inside) return;
    const PovToken& t = peek();
    if (t.kind == PovTokenKind::Directive) return;
    if (t.kind == PovTokenKind::Word &&
        (isPovStatement(t.text) || isPovUnsupportedStatement(t.text))) {
      return;
    }
    if (t.isSymbol('}') && depth_ == depth0) return;  // the end of an enclosing block
    if (t.isSymbol('{')) inside = true;
    take();
  }
}

}  // namespace scene
