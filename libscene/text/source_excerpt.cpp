#include "scenefile/source_excerpt.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include "libscene/text/source_quote.h"
#include "scenefile/printable_text.h"

namespace scene {

namespace {

// A line up to this long is quoted whole; a longer one (a minified glTF, a
// hostile input of one huge line) only around the column, from
// kContextBefore bytes before it, so that a quote costs bounded memory and
// fits a terminal.
constexpr std::size_t kWholeLine = 200;
constexpr std::size_t kContextBefore = 60;
constexpr std::size_t kWindow = 160;
constexpr std::size_t kTabStop = 8;
constexpr const char* kCut = "...";

using Key = std::pair<std::string, std::pair<std::uint32_t, std::uint32_t>>;

// Where each wanted line starts, one pass over the text.
struct WantedLine {
  std::uint32_t line;
  std::uint32_t column;
};

void want(const SourceSpan& span, std::vector<WantedLine>& wanted) {
  if (span.known()) wanted.push_back({span.line, span.column});
}

// Whether a line is bytes rather than text (a .glb, garbage): a NUL, or
// more than one byte in eight (and more than four) that would print as
// \xNN. Its quote would be a wall of escapes that helps nobody.
bool looksBinary(std::string_view line) {
  std::size_t unshown = 0;
  for (std::size_t i = 0; i < line.size();) {
    if (line[i] == '\0') return true;
    std::size_t length = utf8CharacterLength(line.substr(i));
    if (line[i] != '\t' && !showsAsItIs(line.substr(i), length)) {
      ++unshown;
      ++i;
    } else {
      i += length;
    }
  }
  return unshown > 4 && unshown * 8 > line.size();
}

// The part of `whole` (one line, without its end) to keep for `column`.
SourceLine excerpt(std::string_view whole, std::uint32_t column) {
  SourceLine line;
  if (whole.size() <= kWholeLine) {
    line.text = std::string(whole);
    return line;
  }
  std::size_t at = column > 0 ? column - 1 : 0;
  std::size_t begin = at > kContextBefore ? at - kContextBefore : 0;
  begin = std::min(begin, whole.size());
  // Never start inside a UTF-8 character.
  while (begin > 0 && begin < whole.size() &&
         (static_cast<unsigned char>(whole[begin]) & 0xC0) == 0x80) {
    --begin;
  }
  std::size_t end = std::min(whole.size(), begin + kWindow);
  line.text = std::string(whole.substr(begin, end - begin));
  line.firstColumn = static_cast<std::uint32_t>(begin + 1);
  line.cutBefore = begin > 0;
  line.cutAfter = end < whole.size();
  return line;
}

// The shown form of a line and the display column of each of its bytes
// (and of the end), so that the caret stands under the byte it points at.
struct ShownLine {
  std::string text;
  std::vector<std::size_t> columnOfByte;
};

ShownLine show(const SourceLine& line) {
  ShownLine shown;
  std::string_view bytes = line.text;
  shown.columnOfByte.assign(bytes.size() + 1, 0);
  std::size_t width = 0;
  if (line.cutBefore) {
    shown.text = kCut;
    width = std::strlen(kCut);
  }
  for (std::size_t i = 0; i < bytes.size();) {
    std::string_view rest = bytes.substr(i);
    std::size_t length = utf8CharacterLength(rest);
    if (bytes[i] == '\t') {
      std::size_t spaces = kTabStop - width % kTabStop;
      shown.text.append(spaces, ' ');
      shown.columnOfByte[i++] = width;
      width += spaces;
    } else if (!showsAsItIs(rest, length)) {
      shown.text += printableText(rest.substr(0, 1));
      shown.columnOfByte[i++] = width;
      width += 4;  // \xNN
    } else {
      shown.text.append(rest.substr(0, length));
      for (std::size_t k = 0; k < length; ++k) shown.columnOfByte[i + k] = width;
      i += length;
      width += 1;
    }
  }
  shown.columnOfByte[bytes.size()] = width;
  if (line.cutAfter) shown.text += kCut;
  return shown;
}

// The display column of `column` of the whole line within the shown line.
std::size_t displayColumn(const ShownLine& shown, const SourceLine& line, std::uint32_t column) {
  std::size_t byte = column >= line.firstColumn ? column - line.firstColumn : 0;
  return shown.columnOfByte[std::min(byte, shown.columnOfByte.size() - 1)];
}

}  // namespace

void SourceExcerpts::capture(std::string_view file, std::string_view text,
                             const DiagnosticList& list) {
  std::vector<WantedLine> wanted;
  for (const Diagnostic& d : list.items()) {
    if (d.file != file) continue;  // a file it includes, say
    want(d.span, wanted);
    for (const DiagnosticNote& note : d.notes) want(note.span, wanted);
    if (d.fixIt) want(d.fixIt->span, wanted);
  }
  if (wanted.empty()) return;
  std::sort(wanted.begin(), wanted.end(), [](const WantedLine& a, const WantedLine& b) {
    return a.line != b.line ? a.line < b.line : a.column < b.column;
  });
  std::uint32_t lineNumber = 1;
  std::size_t start = 0;
  for (const WantedLine& w : wanted) {
    // Step forward to the wanted line's start.
    while (lineNumber < w.line && start <= text.size()) {
      const void* newline = std::memchr(text.data() + start, '\n', text.size() - start);
      if (!newline) {
        start = text.size() + 1;
        break;
      }
      start = static_cast<std::size_t>(static_cast<const char*>(newline) - text.data()) + 1;
      ++lineNumber;
    }
    if (lineNumber != w.line || start > text.size()) break;
    std::string_view rest = text.substr(start);
    std::string_view whole = rest.substr(0, rest.find('\n'));
    if (!whole.empty() && whole.back() == '\r') whole.remove_suffix(1);
    // The readers skip a byte-order mark, and their columns count from
    // after it.
    if (w.line == 1 && whole.starts_with("\xEF\xBB\xBF")) whole.remove_prefix(3);
    std::uint32_t keyColumn = whole.size() <= kWholeLine ? 0 : w.column;
    Key key{std::string(file), {w.line, keyColumn}};
    if (lines_.contains(key)) continue;
    // Whether it is text is judged on what would be quoted, not the whole
    // line: a hostile line of 100 MB costs a look at 160 bytes, not a pass
    // over all of it (a check of one: 1.68 -> 0.25 s, 22 -> 0.8 s under
    // the sanitizers).
    SourceLine line = excerpt(whole, w.column);
    if (looksBinary(line.text)) continue;
    lines_.emplace(std::move(key), std::move(line));
  }
}

const SourceLine* SourceExcerpts::find(std::string_view file, const SourceSpan& span) const {
  if (!span.known()) return nullptr;
  for (std::uint32_t column : {std::uint32_t{0}, span.column}) {
    auto found = lines_.find(Key{std::string(file), {span.line, column}});
    if (found != lines_.end()) return &found->second;
  }
  return nullptr;
}

std::vector<std::string> quoteSourceLine(const SourceLine& line, const SourceSpan& span,
                                         const FixIt* fixIt, const TerminalPaint& style) {
  ShownLine shown = show(line);
  std::string number = std::to_string(span.line);
  std::size_t gutter = std::max<std::size_t>(5, number.size() + 1);
  std::string blank(gutter, ' ');
  std::vector<std::string> quoted;
  quoted.push_back(std::string(gutter - number.size(), ' ') + number + " | " + shown.text);

  std::size_t from = displayColumn(shown, line, span.column);
  std::size_t to = displayColumn(shown, line, span.column + span.length);
  std::string caret = "^" + std::string(to > from + 1 ? to - from - 1 : 0, '~');
  quoted.push_back(blank + " | " + std::string(from, ' ') + style.caret(caret));

  if (fixIt && fixIt->span.line == span.line && fixIt->span.column >= line.firstColumn) {
    std::size_t at = displayColumn(shown, line, fixIt->span.column);
    quoted.push_back(blank + " | " + std::string(at, ' ') +
                     style.fixIt(printableText(fixIt->replacement)));
  }
  return quoted;
}

}  // namespace scene
