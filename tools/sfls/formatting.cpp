// textDocument/formatting and rangeFormatting: the edits that turn the text
// into its canonical layout (scene::canonicalLayout). Layout changes only
// blanks, line breaks and a keyword's case, so the two texts are walked side
// by side, word by word, and each run of blanks or word that differs becomes
// one edit of just the bytes that differ: the cursor and the rest of the
// line stay where they were.
#include <string>
#include <string_view>

#include "scenefile/layout.h"
#include "tools/sfls/features.h"
#include "tools/sfls/lsp_json.h"

namespace sfls {
namespace {

bool isBlank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

std::size_t skipBlanks(std::string_view text, std::size_t at) {
  while (at < text.size() && isBlank(text[at])) ++at;
  return at;
}

std::size_t skipWord(std::string_view text, std::size_t at) {
  while (at < text.size() && !isBlank(text[at])) ++at;
  return at;
}

// The protocol position of byte `offset` of the document's text.
LspPosition positionOf(const Document& document, std::size_t offset) {
  std::uint32_t low = 0;
  std::uint32_t high = document.lineCount();
  while (high - low > 1) {
    std::uint32_t middle = low + (high - low) / 2;
    if (document.lineOffset(middle) <= offset) {
      low = middle;
    } else {
      high = middle;
    }
  }
  std::size_t column = offset - document.lineOffset(low) + 1;
  return document.toLsp(low + 1, static_cast<std::uint32_t>(column));
}

class EditList {
 public:
  explicit EditList(const Document& document) : document_(document) {}

  // Bytes [oldBegin, oldEnd) of the document, a run of blanks or a word,
  // become `blanks`; only the bytes between their common start and common
  // end are replaced.
  void replaceRun(std::size_t oldBegin, std::size_t oldEnd, std::string_view blanks) {
    std::string_view old = std::string_view(document_.text()).substr(oldBegin, oldEnd - oldBegin);
    if (old == blanks) return;
    std::size_t prefix = 0;
    while (prefix < old.size() && prefix < blanks.size() && old[prefix] == blanks[prefix]) {
      ++prefix;
    }
    std::size_t suffix = 0;
    while (suffix < old.size() - prefix && suffix < blanks.size() - prefix &&
           old[old.size() - 1 - suffix] == blanks[blanks.size() - 1 - suffix]) {
      ++suffix;
    }
    // No edit may start or end between a CR and its LF: the protocol has
    // no position there.
    if (prefix > 0 && old[prefix - 1] == '\r') --prefix;
    if (suffix > 0 && old.size() > suffix && old[old.size() - suffix - 1] == '\r') --suffix;
    std::size_t begin = oldBegin + prefix;
    std::size_t end = oldEnd - suffix;
    std::string_view newText = blanks.substr(prefix, blanks.size() - prefix - suffix);
    edits_.push_back({{"range", LspRange{positionOf(document_, begin), positionOf(document_, end)}},
                      {"newText", newText}});
  }

  // One edit that replaces the whole text.
  void replaceAll(std::string_view text) {
    edits_ = nlohmann::json::array();
    edits_.push_back({{"range", LspRange{{}, positionOf(document_, document_.text().size())}},
                      {"newText", text}});
  }

  nlohmann::json& edits() { return edits_; }

 private:
  const Document& document_;
  nlohmann::json edits_ = nlohmann::json::array();
};

// The edits from the document's text to `layout`, which holds the same
// words in the same order.
nlohmann::json editsTo(const Document& document, std::string_view layout) {
  std::string_view text = document.text();
  EditList edits(document);
  std::size_t at = 0;
  std::size_t to = 0;
  for (;;) {
    std::size_t atWord = skipBlanks(text, at);
    std::size_t toWord = skipBlanks(layout, to);
    edits.replaceRun(at, atWord, layout.substr(to, toWord - to));
    at = atWord;
    to = toWord;
    if (at == text.size() || to == layout.size()) break;
    std::size_t atEnd = skipWord(text, at);
    std::size_t toEnd = skipWord(layout, to);
    // A keyword in another case becomes the table's spelling.
    edits.replaceRun(at, atEnd, layout.substr(to, toEnd - to));
    at = atEnd;
    to = toEnd;
  }
  // Words left over on one side would be a layout that changed more than
  // blanks and words: then the text is replaced whole rather than edited
  // out of place.
  if (at != text.size() || to != layout.size()) edits.replaceAll(layout);
  return std::move(edits.edits());
}

bool within(const nlohmann::json& edit, const LspRange& range) {
  LspRange edited = edit.at("range").get<LspRange>();
  // An edit that ends at the start of the line after the range removes
  // or adds line breaks of the range's last line.
  bool endsInside = edited.end.line <= range.end.line ||
                    (edited.end.line == range.end.line + 1 && edited.end.character == 0);
  return edited.start.line >= range.start.line && endsInside;
}

}  // namespace

nlohmann::json formattingEdits(const Document& document, const Analysis& analysis,
                               const std::optional<LspRange>& range) {
  nlohmann::json kept = nlohmann::json::array();
  // A broken text's structure is a guess, and a check of another version
  // says nothing of this one.
  if (!analysis.format || analysis.version != document.version() ||
      analysis.result.diagnostics.hasErrors()) {
    return kept;
  }
  std::optional<std::string> layout = scene::canonicalLayout(document.text(), *analysis.format);
  if (!layout || *layout == document.text()) return kept;
  nlohmann::json edits = editsTo(document, *layout);
  if (!range) return edits;
  for (nlohmann::json& edit : edits) {
    if (within(edit, *range)) kept.push_back(std::move(edit));
  }
  return kept;
}

}  // namespace sfls
