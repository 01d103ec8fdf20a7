// An open document of the language server: its text, its version, where
// its lines start, and positions both as the protocol counts them (0-based
// lines, UTF-16 code units) and as the library does (SourceSpan: 1-based
// lines, byte columns).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scenefile/diagnostic.h"

namespace sfls {

// A position as the protocol counts: line from 0, character in UTF-16 code
// units from 0.
struct LspPosition {
  std::uint32_t line = 0;
  std::uint32_t character = 0;
  friend bool operator==(const LspPosition&, const LspPosition&) = default;
};

struct LspRange {
  LspPosition start;
  LspPosition end;
  friend bool operator==(const LspRange&, const LspRange&) = default;
};

// A place in the text as the library counts: line from 1, byte column from
// 1, the first line's columns counted after a byte-order mark, as the
// readers count them (the protocol counts the mark as a character).
struct SourcePosition {
  std::uint32_t line = 1;
  std::uint32_t column = 1;
};

class Document {
 public:
  Document(std::string uri, std::int64_t version, std::string text);

  const std::string& uri() const { return uri_; }
  std::int64_t version() const { return version_; }
  const std::string& text() const { return *text_; }
  // The text, shared with the checks that read it while the document
  // changes: a change copies it only while it is shared, and otherwise
  // edits it in place (a 100 MB text is not copied on every keystroke).
  std::shared_ptr<const std::string> sharedText() const { return text_; }

  // One entry of didChange's contentChanges: `range` replaced by `newText`,
  // or the whole text when there is no range. A range past the end is
  // clamped to it, as the protocol says.
  void applyChange(const std::optional<LspRange>& range, std::string_view newText);
  void setVersion(std::int64_t version) { version_ = version; }

  std::uint32_t lineCount() const { return static_cast<std::uint32_t>(lineStarts_.size()); }
  // The byte offset where line `line0` (from 0) starts; the text's size past
  // the last line.
  std::size_t lineOffset(std::uint32_t line0) const;
  // Line `line0`'s text, without its line ending.
  std::string_view lineText(std::uint32_t line0) const;

  // The protocol's position in the library's terms; a character past the
  // line's end is its end.
  SourcePosition toSource(LspPosition position) const;
  // The library's position (line, byte column) in the protocol's terms.
  LspPosition toLsp(std::uint32_t line, std::uint32_t column) const;
  // A span (on one line; a length of 0 is a point) as a range. An unknown
  // span (line 0) is the start of the document.
  LspRange toLsp(const scene::SourceSpan& span) const;
  // The byte offset of a protocol position.
  std::size_t offsetOf(LspPosition position) const;

 private:
  void indexLines();
  // The bytes of line `line0` before the library's first column: a
  // byte-order mark's three on the first line, none elsewhere.
  std::size_t bytesBeforeColumns(std::uint32_t line0) const;

  std::string uri_;
  std::int64_t version_ = 0;
  std::shared_ptr<std::string> text_;
  std::vector<std::size_t> lineStarts_;
};

}  // namespace sfls
