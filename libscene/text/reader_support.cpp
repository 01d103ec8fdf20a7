#include "libscene/text/reader_support.h"

#include <string>
#include <vector>

#include "libscene/text/number.h"
#include "scenefile/spelling.h"

namespace scene {

namespace {

std::string plural(std::size_t n, std::string_view word) {
  return std::to_string(n) + " " + std::string(word) + (n == 1 ? "" : "s");
}

}  // namespace

bool reportInvalidByte(const LineCursor& cursor, DiagnosticList& out) {
  auto column = cursor.invalidByteColumn();
  if (!column) return false;
  out.error(DiagnosticCode::InvalidByte, SourceSpan{cursor.lineNumber(), *column, 1},
            "line contains a " + describeInvalidByte(cursor.invalidByte()))
      .hint = "scene and instruction files are plain ASCII text";
  return true;
}

bool reportComment(const LineCursor& cursor, DiagnosticList& out) {
  if (!cursor.blank()) {
    std::string_view first = cursor.token(0).text;
    if (first.starts_with("#") || first.starts_with("//")) {
      out.error(DiagnosticCode::CommentNotAllowed, cursor.tokenSpan(0),
                "comments are not allowed: neither format has them")
          .hint = "remove the line";
      return true;
    }
  }
  return false;
}

bool readNumbers(const LineCursor& cursor, std::size_t first, std::size_t count, double* values,
                 std::string_view what, DiagnosticList& out) {
  std::size_t found = cursor.tokenCount() - first;
  if (found != count) {
    SourceSpan where = found < count ? cursor.endOfLine() : cursor.tokenSpan(first + count);
    out.error(DiagnosticCode::TokenCount, where,
              std::string(what) + " takes " + plural(count, "number") + ", found " +
                  std::to_string(found));
    return false;
  }
  bool ok = true;
  for (std::size_t i = 0; i < count; ++i) {
    const Token& token = cursor.token(first + i);
    ParsedNumber parsed = parseNumber(token.text);
    SourceSpan span = token.span(cursor.lineNumber());
    switch (parsed.status) {
      case NumberStatus::Ok:
        values[i] = parsed.value;
        break;
      case NumberStatus::Syntax: {
        // Long tokens are cut in the message; the span still covers them.
        std::string shown(token.text.substr(0, 40));
        if (token.text.size() > 40) shown += "...";
        Diagnostic& d =
            out.error(DiagnosticCode::InvalidNumber, span, "'" + shown + "' is not a number");
        d.hint = numberSyntaxReason(token.text);
        ok = false;
        break;
      }
      case NumberStatus::Overflow:
        out.error(DiagnosticCode::NumberOutOfRange, span,
                  "number is too large for a 64-bit double");
        ok = false;
        break;
      case NumberStatus::Underflow:
        out.error(DiagnosticCode::NumberOutOfRange, span,
                  "number is too small for a 64-bit double: it would round to 0");
        ok = false;
        break;
    }
  }
  return ok;
}

namespace {

bool isBlank(char c) {
  return c == ' ' || c == '\t';
}

// The line ends as LineCursor::nextLine ends it: at "\n", "\r\n", or the
// text's end, a '\r' there dropped too. `at` is where the blanks after its
// last number end; false where something else follows them.
bool passLineEndingAt(LineCursor& cursor, std::string_view text, std::size_t at) {
  std::size_t length = at;
  if (at < text.size() && text[at] == '\r') ++at;
  if (at < text.size()) {
    if (text[at] != '\n') return false;
    ++at;
  }
  cursor.passLine(length, at);
  return true;
}

}  // namespace

bool readPlainNumberLine(LineCursor& cursor, std::size_t count, double* values, SourceSpan* spans) {
  // The line's end is found as its numbers are read: no search for it first.
  std::string_view text = cursor.rest();
  const std::uint32_t lineNumber = cursor.lineNumber() + 1;
  std::size_t i = 0;
  for (std::size_t k = 0; k < count; ++k) {
    while (i < text.size() && isBlank(text[i])) ++i;
    if (i == text.size()) return false;
    // Every byte must belong to a number or a blank, so a line read here
    // holds no invalid byte, comment or keyword either.
    std::size_t length = 0;
    ParsedNumber parsed = parseLeadingNumberInText(text.substr(i), length);
    if (parsed.status != NumberStatus::Ok) return false;
    values[k] = parsed.value;
    spans[k] = SourceSpan{lineNumber, static_cast<std::uint32_t>(i + 1),
                          static_cast<std::uint32_t>(length)};
    i += length;
  }
  while (i < text.size() && isBlank(text[i])) ++i;
  return passLineEndingAt(cursor, text, i);
}

std::optional<std::string_view> keywordInOtherCase(std::string_view word,
                                                   std::span<const std::string_view> candidates) {
  for (std::string_view c : candidates) {
    if (equalsIgnoringCase(word, c)) return c;
  }
  return std::nullopt;
}

std::optional<std::string_view> suggestKeyword(std::string_view word,
                                               std::span<const std::string_view> candidates) {
  return suggestSpelling(word, candidates);
}

void reportUnknownKeyword(const LineCursor& cursor, std::size_t tokenIndex,
                          std::span<const std::string_view> candidates, std::string_view expected,
                          DiagnosticList& out) {
  const Token& token = cursor.token(tokenIndex);
  std::string shown(token.text.substr(0, 40));
  if (token.text.size() > 40) shown += "...";
  SourceSpan span = token.span(cursor.lineNumber());
  Diagnostic& d = out.error(DiagnosticCode::UnknownKeyword, span,
                            "unknown keyword '" + shown + "', expected " + std::string(expected));
  if (auto suggestion = suggestKeyword(token.text, candidates)) {
    d.hint = "did you mean '" + std::string(*suggestion) + "'?";
    if (equalsIgnoringCase(token.text, *suggestion)) {
      d.hint = "keywords are upper case: did you mean '" + std::string(*suggestion) + "'?";
    }
    d.fixIt = FixIt{span, std::string(*suggestion)};
  }
}

Diagnostic& reportTooManyObjects(SourceSpan span, std::size_t maxObjects, DiagnosticList& out) {
  Diagnostic& d = out.error(DiagnosticCode::TooManyObjects, span,
                            "the file has more than " + std::to_string(maxObjects) +
                                " objects and lights: reading stops here");
  d.hint = "raise the limit with {0} if the scene is meant to be this large";
  d.remedies = {{Setting::MaxObjects, ""}};
  return d;
}

}  // namespace scene
