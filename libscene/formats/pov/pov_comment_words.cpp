#include "libscene/formats/pov/pov_comment_words.h"

#include "libscene/text/number.h"

namespace scene {

PovCommentWords::PovCommentWords(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r')) ++i;
    std::size_t start = i;
    while (i < text.size() && text[i] != ' ' && text[i] != '\t' && text[i] != '\r') ++i;
    if (i > start) words_.push_back(text.substr(start, i - start));
  }
}

bool PovCommentWords::word(std::string_view w) {
  if (next_ < words_.size() && words_[next_] == w) {
    ++next_;
    return true;
  }
  return false;
}

std::optional<std::string_view> PovCommentWords::any() {
  if (next_ >= words_.size()) return std::nullopt;
  return words_[next_++];
}

bool PovCommentWords::number(double& out) {
  if (next_ >= words_.size()) return false;
  ParsedNumber parsed = parseNumber(words_[next_]);
  if (parsed.status != NumberStatus::Ok) return false;
  out = parsed.value;
  ++next_;
  return true;
}

bool PovCommentWords::matrix(glm::dmat4& out) {
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      if (!number(out[c][r])) return false;
    }
  }
  return true;
}

}  // namespace scene
