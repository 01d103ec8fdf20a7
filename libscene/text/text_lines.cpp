#include "libscene/text/text_lines.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <string>

namespace scene {

LineCursor::LineCursor(std::string_view text, std::uint32_t firstLine)
    : text_(text), lineNumber_(firstLine - 1) {
  if (firstLine == 1 && text_.starts_with("\xEF\xBB\xBF")) offset_ = 3;
}

bool LineCursor::nextLine() {
  if (offset_ >= text_.size()) return false;
  ++lineNumber_;
  tokenCount_ = 0;
  invalidByteColumn_.reset();
  // Columns count from the start of the line; the BOM belongs to no column.
  const char* begin = text_.data() + offset_;
  std::size_t remaining = text_.size() - offset_;
  const void* newline = std::memchr(begin, '\n', remaining);
  std::size_t length = newline ? static_cast<const char*>(newline) - begin : remaining;
  offset_ += newline ? length + 1 : length;
  if (length > 0 && begin[length - 1] == '\r') --length;
  line_ = std::string_view(begin, length);
  return true;
}

void LineCursor::passLine(std::size_t length, std::size_t next) {
  ++lineNumber_;
  tokenCount_ = 0;
  invalidByteColumn_.reset();
  line_ = std::string_view(text_.data() + offset_, length);
  offset_ += next;
}

void LineCursor::tokenize() {
  const char* begin = line_.data();
  std::size_t length = line_.size();
  tokenCount_ = 0;
  invalidByteColumn_.reset();
  std::size_t i = 0;
  while (i < length) {
    unsigned char c = static_cast<unsigned char>(begin[i]);
    if (c == ' ' || c == '\t') {
      ++i;
      continue;
    }
    std::size_t start = i;
    while (i < length) {
      c = static_cast<unsigned char>(begin[i]);
      if (c == ' ' || c == '\t') break;
      if ((c < 0x20 || c > 0x7E) && !invalidByteColumn_) {
        invalidByteColumn_ = static_cast<std::uint32_t>(i + 1);
        invalidByte_ = c;
      }
      ++i;
    }
    if (tokenCount_ < kMaxTokens) {
      tokens_[tokenCount_] =
          Token{std::string_view(begin + start, i - start), static_cast<std::uint32_t>(start + 1)};
    }
    ++tokenCount_;
  }
}

void LineCursor::cutAtInvalidByte() {
  if (!invalidByteColumn_) return;
  std::uint32_t cut = *invalidByteColumn_;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < storedTokens(); ++i) {
    Token& token = tokens_[i];
    if (token.column >= cut) break;
    std::size_t room = cut - token.column;
    if (token.text.size() > room) token.text = token.text.substr(0, room);
    ++kept;
  }
  tokenCount_ = kept;
  line_ = line_.substr(0, cut - 1);
}

SourceSpan LineCursor::endOfLine() const {
  return SourceSpan{lineNumber_, static_cast<std::uint32_t>(line_.size() + 1), 0};
}

SourceSpan LineCursor::lineSpan() const {
  if (tokenCount_ == 0) return endOfLine();
  const Token& first = tokens_[0];
  const Token& last = tokens_[storedTokens() - 1];
  return SourceSpan{lineNumber_, first.column,
                    static_cast<std::uint32_t>(last.column + last.text.size() - first.column)};
}

std::string describeInvalidByte(unsigned char byte) {
  char buffer[64];
  if (byte == 0) return "NUL byte";
  if (byte == '\r') return "carriage return not followed by a line feed";
  if (byte < 0x20 || byte == 0x7F) {
    std::snprintf(buffer, sizeof buffer, "control character 0x%02X", byte);
  } else {
    std::snprintf(buffer, sizeof buffer, "byte 0x%02X, which is not ASCII", byte);
  }
  return buffer;
}

}  // namespace scene

namespace scene {

std::optional<std::string_view> firstWordOutsideComments(std::string_view text) {
  // Only the first word of a line is looked at, so the rest is not split
  // into tokens: a hostile first line of 100 MB would cost a pass per
  // format that detects itself by it.
  LineCursor cursor(text);
  auto blank = [](char c) { return c == ' ' || c == '\t'; };
  while (cursor.nextLine()) {
    std::string_view line = cursor.line();
    std::size_t start = 0;
    while (start < line.size() && blank(line[start])) ++start;
    if (start == line.size()) continue;
    std::size_t end = start;
    while (end < line.size() && !blank(line[end])) ++end;
    std::string_view first = line.substr(start, end - start);
    // Comments are errors in both line formats, which the reader reports;
    // they say nothing about which format this is.
    if (first.starts_with("#") || first.starts_with("//")) continue;
    return first;
  }
  return std::nullopt;
}

SourceSpan LineColumnCounter::at(std::size_t byte) {
  byte = std::min(byte, text_.size());
  if (byte < scanned_) *this = LineColumnCounter(text_);
  while (const void* newline = std::memchr(text_.data() + scanned_, '\n', byte - scanned_)) {
    scanned_ = static_cast<std::size_t>(static_cast<const char*>(newline) - text_.data()) + 1;
    lineStart_ = scanned_;
    ++line_;
  }
  scanned_ = byte;
  return SourceSpan{line_, static_cast<std::uint32_t>(byte - lineStart_ + 1), 0};
}

bool startsWithIgnoringCase(std::string_view text, std::string_view prefix) {
  if (text.size() < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i) {
    if (std::toupper(static_cast<unsigned char>(text[i])) != prefix[i]) return false;
  }
  return true;
}

}  // namespace scene
