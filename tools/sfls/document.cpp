#include "tools/sfls/document.h"

#include <algorithm>
#include <cstring>

namespace sfls {
namespace {

bool isContinuation(unsigned char byte) {
  return (byte & 0xC0) == 0x80;
}

// The length of the well-formed UTF-8 sequence at `pos` of `text` (1 to 4),
// or 0 where the byte starts none (a stray continuation, an overlong form, a
// surrogate, a sequence cut short): such a byte counts as one unit alone,
// as editors show it (one replacement character).
std::size_t sequenceLength(std::string_view text, std::size_t pos) {
  auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[pos + i]); };
  unsigned char lead = byte(0);
  if (lead < 0x80) return 1;
  std::size_t length = lead >= 0xC2 && lead <= 0xDF   ? 2
                       : lead >= 0xE0 && lead <= 0xEF ? 3
                       : lead >= 0xF0 && lead <= 0xF4 ? 4
                                                      : 0;
  if (length == 0 || pos + length > text.size()) return 0;
  for (std::size_t i = 1; i < length; ++i) {
    if (!isContinuation(byte(i))) return 0;
  }
  // The second byte's range excludes overlong forms, surrogates and code
  // points past U+10FFFF (RFC 3629's table).
  unsigned char second = byte(1);
  if ((lead == 0xE0 && second < 0xA0) || (lead == 0xED && second > 0x9F) ||
      (lead == 0xF0 && second < 0x90) || (lead == 0xF4 && second > 0x8F)) {
    return 0;
  }
  return length;
}

// How a run of `line` takes up UTF-16 code units, one code point at a time.
struct CodePoint {
  std::size_t bytes;
  std::uint32_t units;
};

CodePoint codePointAt(std::string_view line, std::size_t pos) {
  std::size_t length = sequenceLength(line, pos);
  if (length == 0) return {1, 1};
  return {length, length == 4 ? 2u : 1u};
}

// The bytes of `line` before UTF-16 unit `character`; the line's size past
// its end. A character inside a surrogate pair is the pair's start.
std::size_t bytesBefore(std::string_view line, std::uint32_t character) {
  std::size_t pos = 0;
  std::uint32_t units = 0;
  while (pos < line.size()) {
    CodePoint point = codePointAt(line, pos);
    if (units + point.units > character) break;
    units += point.units;
    pos += point.bytes;
  }
  return pos;
}

// The UTF-16 units of `line`'s first `bytes` bytes.
std::uint32_t unitsBefore(std::string_view line, std::size_t bytes) {
  bytes = std::min(bytes, line.size());
  std::size_t pos = 0;
  std::uint32_t units = 0;
  while (pos < bytes) {
    CodePoint point = codePointAt(line, pos);
    units += point.units;
    pos += point.bytes;
  }
  return units;
}

// The offsets just past each '\n' of `text`, each plus `base`, appended.
void appendLineStarts(std::string_view text, std::size_t base, std::vector<std::size_t>& starts) {
  const char* begin = text.data();
  const char* end = begin + text.size();
  for (const char* p = begin; p < end;) {
    const void* newline = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
    if (newline == nullptr) break;
    p = static_cast<const char*>(newline) + 1;
    starts.push_back(base + static_cast<std::size_t>(p - begin));
  }
}

}  // namespace

Document::Document(std::string uri, std::int64_t version, std::string text)
    : uri_(std::move(uri)),
      version_(version),
      text_(std::make_shared<std::string>(std::move(text))) {
  indexLines();
}

void Document::indexLines() {
  lineStarts_.assign(1, 0);
  appendLineStarts(*text_, 0, lineStarts_);
}

void Document::applyChange(const std::optional<LspRange>& range, std::string_view newText) {
  // Only this document holds the text: no check or analysis can see it
  // change. (use_count is exact at 1: no other owner can appear from
  // another thread, since only this one hands the text out.)
  bool unshared = text_.use_count() == 1;
  if (!range) {
    if (unshared) {
      text_->assign(newText);
    } else {
      text_ = std::make_shared<std::string>(newText);
    }
    indexLines();
    return;
  }
  std::size_t start = offsetOf(range->start);
  std::size_t end = std::max(start, offsetOf(range->end));
  if (unshared) {
    text_->replace(start, end - start, newText);
  } else {
    const std::string& old = *text_;
    auto text = std::make_shared<std::string>();
    text->reserve(old.size() - (end - start) + newText.size());
    text->append(old, 0, start).append(newText).append(old, end, std::string::npos);
    text_ = std::move(text);
  }

  // Only the lines from the change on move: those that started inside the
  // replaced bytes go, the new text's come in, the later ones shift. A
  // whole reindex would cost a scan of the text on every keystroke.
  auto first = std::upper_bound(lineStarts_.begin(), lineStarts_.end(), start);
  auto last = std::upper_bound(first, lineStarts_.end(), end);
  std::vector<std::size_t> inserted;
  appendLineStarts(newText, start, inserted);
  std::size_t tail = static_cast<std::size_t>(last - lineStarts_.begin());
  std::size_t firstIndex = static_cast<std::size_t>(first - lineStarts_.begin());
  for (std::size_t i = tail; i < lineStarts_.size(); ++i) {
    lineStarts_[i] = lineStarts_[i] - end + start + newText.size();
  }
  lineStarts_.erase(lineStarts_.begin() + static_cast<std::ptrdiff_t>(firstIndex),
                    lineStarts_.begin() + static_cast<std::ptrdiff_t>(tail));
  lineStarts_.insert(lineStarts_.begin() + static_cast<std::ptrdiff_t>(firstIndex),
                     inserted.begin(), inserted.end());
}

std::size_t Document::lineOffset(std::uint32_t line0) const {
  return line0 < lineStarts_.size() ? lineStarts_[line0] : text_->size();
}

std::string_view Document::lineText(std::uint32_t line0) const {
  if (line0 >= lineStarts_.size()) return {};
  std::size_t begin = lineStarts_[line0];
  std::size_t end = line0 + 1 < lineStarts_.size() ? lineStarts_[line0 + 1] - 1 : text_->size();
  std::string_view line(text_->data() + begin, end - begin);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

std::size_t Document::bytesBeforeColumns(std::uint32_t line0) const {
  return line0 == 0 && text_->starts_with("\xEF\xBB\xBF") ? 3 : 0;
}

SourcePosition Document::toSource(LspPosition position) const {
  if (position.line >= lineCount()) {
    std::uint32_t last = lineCount() - 1;
    std::size_t size = lineText(last).size() - bytesBeforeColumns(last);
    return {last + 1, static_cast<std::uint32_t>(size) + 1};
  }
  std::size_t bytes = bytesBefore(lineText(position.line), position.character);
  std::size_t skipped = bytesBeforeColumns(position.line);
  return {position.line + 1, static_cast<std::uint32_t>(bytes - std::min(bytes, skipped)) + 1};
}

LspPosition Document::toLsp(std::uint32_t line, std::uint32_t column) const {
  if (line == 0) return {};
  std::uint32_t line0 = std::min(line - 1, lineCount() - 1);
  std::size_t bytes = (column == 0 ? 0 : column - 1) + bytesBeforeColumns(line0);
  return {line0, unitsBefore(lineText(line0), bytes)};
}

LspRange Document::toLsp(const scene::SourceSpan& span) const {
  if (!span.known()) return {};
  return {toLsp(span.line, span.column), toLsp(span.line, span.column + span.length)};
}

std::size_t Document::offsetOf(LspPosition position) const {
  if (position.line >= lineCount()) return text_->size();
  return lineStarts_[position.line] + bytesBefore(lineText(position.line), position.character);
}

}  // namespace sfls
