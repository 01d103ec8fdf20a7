#include "libscene/text/line_layout.h"

namespace scene {

LineLayout::LineLayout(std::string_view text) {
  if (text.starts_with("\xEF\xBB\xBF")) {
    out_ = "\xEF\xBB\xBF";
    bom_ = 3;
  }
  std::size_t newline = text.find('\n');
  newline_ =
      newline != std::string_view::npos && newline > 0 && text[newline - 1] == '\r' ? "\r\n" : "\n";
  out_.reserve(text.size() + 64);
}

bool LineLayout::line(const LineCursor& cursor, std::size_t indent, std::string_view keywords[3]) {
  if (cursor.tokenCount() > cursor.storedTokens()) return false;
  // A carriage return that ends the last word would end the line once a
  // newline follows it: the text would read otherwise laid out.
  if (!cursor.blank() && cursor.token(cursor.storedTokens() - 1).text.ends_with('\r')) {
    return false;
  }
  // Nor may a first word that starts like a byte-order mark start the text.
  if (out_.empty() && !cursor.blank() && cursor.token(0).text.starts_with("\xEF\xBB\xBF")) {
    return false;
  }
  out_.append(indent * 2, ' ');
  for (std::size_t i = 0; i < cursor.storedTokens(); ++i) {
    if (i) out_ += ' ';
    bool replaced = keywords && i < 3 && !keywords[i].empty();
    out_ += replaced ? keywords[i] : cursor.token(i).text;
  }
  out_ += newline_;
  return true;
}

void LineLayout::blankLine() {
  if (out_.size() > bom_) out_ += newline_;
}

}  // namespace scene
