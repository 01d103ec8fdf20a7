#include "libscene/formats/pov/pov_lexer.h"

#include <cstdio>

#include "libscene/text/number.h"

namespace scene {

namespace {

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}
bool isWordStart(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool isWordChar(char c) {
  return isWordStart(c) || isDigit(c);
}
bool isPovSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

constexpr std::string_view kSymbols = "{}<>()[],;=+-*/!?:.&|";

std::string describeByte(unsigned char byte) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "0x%02X", byte);
  return std::string("byte ") + buffer;
}

}  // namespace

PovLexer::PovLexer(std::string_view text, DiagnosticList& out) : text_(text), out_(out) {
  if (text_.starts_with("\xEF\xBB\xBF")) pos_ = lineStart_ = 3;
}

SourceSpan PovLexer::spanAt(std::size_t offset, std::size_t length) const {
  return SourceSpan{line_, static_cast<std::uint32_t>(offset - lineStart_ + 1),
                    static_cast<std::uint32_t>(length)};
}

PovToken PovLexer::make(PovTokenKind kind, std::size_t start, std::size_t end) {
  PovToken token;
  token.kind = kind;
  token.text = text_.substr(start, end - start);
  token.span = spanAt(start, end - start);
  token.offset = start;
  token.exactComment = pendingComment_;
  pendingComment_ = -1;
  if (kind != PovTokenKind::End) ++tokenCount_;
  return token;
}

void PovLexer::skipBlanksAndComments() {
  while (pos_ < text_.size()) {
    char c = text_[pos_];
    if (c == '\n') {
      ++pos_;
      ++line_;
      lineStart_ = pos_;
    } else if (isPovSpace(c)) {
      ++pos_;
    } else if (text_.compare(pos_, 2, "//") == 0) {
      std::size_t end = text_.find('\n', pos_);
      if (end == std::string_view::npos) end = text_.size();
      std::string_view comment = text_.substr(pos_, end - pos_);
      if (comment.starts_with(kPovExactComment)) {
        exactComments_.push_back(
            {comment.substr(kPovExactComment.size()), spanAt(pos_, comment.size())});
        pendingComment_ = static_cast<int>(exactComments_.size() - 1);
      }
      pos_ = end;
    } else if (text_.compare(pos_, 2, "/*") == 0) {
      // POV-Ray's block comments nest.
      SourceSpan open = spanAt(pos_, 2);
      int depth = 0;
      while (pos_ < text_.size()) {
        if (text_.compare(pos_, 2, "/*") == 0) {
          ++depth;
          pos_ += 2;
        } else if (text_.compare(pos_, 2, "*/") == 0) {
          pos_ += 2;
          if (--depth == 0) break;
        } else {
          if (text_[pos_] == '\n') {
            ++line_;
            lineStart_ = pos_ + 1;
          }
          ++pos_;
        }
      }
      if (depth != 0) {
        out_.error(DiagnosticCode::PovSyntax, open, "the comment opened here is never closed")
            .hint = "close it with */ (block comments nest in POV-Ray)";
      }
    } else {
      return;
    }
  }
}

PovToken PovLexer::next() {
  for (;;) {
    skipBlanksAndComments();
    if (pos_ >= text_.size()) return make(PovTokenKind::End, text_.size(), text_.size());
    std::size_t start = pos_;
    char c = text_[pos_];
    if (isDigit(c) || (c == '.' && pos_ + 1 < text_.size() && isDigit(text_[pos_ + 1]))) {
      while (pos_ < text_.size() && isDigit(text_[pos_])) ++pos_;
      if (pos_ < text_.size() && text_[pos_] == '.') {
        ++pos_;
        while (pos_ < text_.size() && isDigit(text_[pos_])) ++pos_;
      }
      // An exponent only when digits follow: "2e" is 2 and the word e.
      if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
        std::size_t p = pos_ + 1;
        if (p < text_.size() && (text_[p] == '+' || text_[p] == '-')) ++p;
        if (p < text_.size() && isDigit(text_[p])) {
          pos_ = p;
          while (pos_ < text_.size() && isDigit(text_[pos_])) ++pos_;
        }
      }
      PovToken token = make(PovTokenKind::Number, start, pos_);
      ParsedNumber parsed = parseNumber(token.text);
      token.number = parsed.value;
      if (parsed.status != NumberStatus::Ok) {
        token.number = 0.0;
        out_.error(DiagnosticCode::NumberOutOfRange, token.span,
                   "'" + std::string(token.text.substr(0, 40)) +
                       (parsed.status == NumberStatus::Underflow ? "' is too small for a double"
                                                                 : "' is too large for a double"));
      }
      return token;
    }
    if (isWordStart(c)) {
      while (pos_ < text_.size() && isWordChar(text_[pos_])) ++pos_;
      return make(PovTokenKind::Word, start, pos_);
    }
    if (c == '#') {
      std::size_t p = pos_ + 1;
      while (p < text_.size() && (text_[p] == ' ' || text_[p] == '\t')) ++p;
      std::size_t wordStart = p;
      while (p < text_.size() && isWordChar(text_[p])) ++p;
      if (p == wordStart) {
        pos_ = start + 1;
        out_.error(DiagnosticCode::PovSyntax, spanAt(start, 1),
                   "'#' must be followed by a directive such as #declare or #include");
        continue;
      }
      pos_ = p;
      PovToken token = make(PovTokenKind::Directive, start, pos_);
      token.text = text_.substr(wordStart, p - wordStart);
      return token;
    }
    if (c == '"') {
      ++pos_;
      while (pos_ < text_.size() && text_[pos_] != '"' && text_[pos_] != '\n') {
        pos_ += text_[pos_] == '\\' && pos_ + 1 < text_.size() && text_[pos_ + 1] != '\n' ? 2 : 1;
      }
      if (pos_ >= text_.size() || text_[pos_] != '"') {
        out_.error(DiagnosticCode::PovSyntax, spanAt(start, 1),
                   "the string opened here is not closed on its line");
        PovToken token = make(PovTokenKind::String, start, pos_);
        token.text = text_.substr(start + 1, pos_ - start - 1);
        return token;
      }
      ++pos_;
      PovToken token = make(PovTokenKind::String, start, pos_);
      token.text = text_.substr(start + 1, pos_ - start - 2);
      return token;
    }
    if (kSymbols.find(c) != std::string_view::npos) {
      ++pos_;
      return make(PovTokenKind::Symbol, start, pos_);
    }
    // Anything else is no token of the language: reported, then skipped
    // (a run of non-ASCII bytes once, as one character of UTF-8 would be).
    unsigned char byte = static_cast<unsigned char>(c);
    if (byte >= 0x80 || byte < 0x20 || byte == 0x7F) {
      std::size_t end = pos_ + 1;
      while (end < text_.size() && static_cast<unsigned char>(text_[end]) >= 0x80) ++end;
      out_.error(DiagnosticCode::InvalidByte, spanAt(start, 1),
                 "a " + describeByte(byte) + " outside a comment or a string")
          .hint = "POV-Ray scene files are ASCII text but for comments and strings";
      pos_ = end;
    } else {
      ++pos_;
      out_.error(DiagnosticCode::PovSyntax, spanAt(start, 1),
                 std::string("unexpected character '") + c + "'");
    }
  }
}

}  // namespace scene
