#include "libscene/text/nearby_lines.h"

namespace scene {

bool LinesBefore::previous() {
  std::size_t bom = text_.starts_with("\xEF\xBB\xBF") ? 3 : 0;
  if (start_ <= bom || start_ > text_.size() || lineNumber_ <= 1) return false;
  std::size_t end = start_ - 1;  // the newline that ends the line before
  std::size_t begin = end;
  while (begin > bom && text_[begin - 1] != '\n') --begin;
  std::size_t length = end - begin;
  if (length > 0 && text_[begin + length - 1] == '\r') --length;
  line_ = text_.substr(begin, length);
  start_ = begin;
  --lineNumber_;
  return true;
}

LineCursor cursorAt(std::string_view text, std::size_t lineStart, std::uint32_t line) {
  LineCursor cursor(text.substr(std::min(lineStart, text.size())), line);
  cursor.next();
  return cursor;
}

LineHead lineHead(std::string_view line, int count) {
  std::string_view words[3];
  std::size_t i = 0;
  for (int k = 0; k < count && k < 3; ++k) {
    std::string_view& word = words[k];
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    word = line.substr(start, i - start);
  }
  return LineHead{words[0], words[1], words[2]};
}

void placeWords(const LineCursor& cursor, std::uint32_t column, TextPlace& place) {
  place.words.clear();
  place.wordIndex = cursor.storedTokens();
  for (std::size_t i = 0; i < cursor.storedTokens(); ++i) {
    const Token& token = cursor.token(i);
    place.words.push_back(Word{token.text, cursor.tokenSpan(i)});
    std::uint32_t end = token.column + static_cast<std::uint32_t>(token.text.size());
    if (place.wordIndex == cursor.storedTokens() && column >= token.column && column <= end) {
      place.wordIndex = i;
    }
  }
}

}  // namespace scene
