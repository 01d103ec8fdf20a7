#include "libscene/formats/instruction/instruction_layout.h"

#include "libscene/formats/instruction/instruction_reader.h"
#include "libscene/text/line_layout.h"
#include "libscene/text/reader_support.h"
#include "scenefile/scene.h"
#include "scenefile/spelling.h"

namespace scene {

namespace {

bool isSection(std::string_view block) {
  return block == "MATERIAL" || block == "TRANSFORMATION";
}

// The object kinds' names, for their canonical case.
std::optional<std::string_view> objectKindWord(std::string_view word) {
  for (ObjectKind kind : kObjectKinds) {
    std::string_view name = objectKindName(kind);
    if (equalsIgnoringCase(word, name)) return name;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> instructionFileLayout(std::string_view text) {
  LineLayout layout(text);
  LineCursor cursor(text);
  std::size_t depth = 0;  // the blocks the next line stands in
  while (cursor.next()) {
    if (cursor.blank()) continue;
    std::string_view keywords[3];
    std::optional<std::string_view> first =
        keywordInOtherCase(cursor.token(0).text, instructionLineKeywords());
    if (first) keywords[0] = *first;
    std::optional<std::string_view> block;
    if (cursor.storedTokens() > 1 && (keywords[0] == "START" || keywords[0] == "END")) {
      block = keywordInOtherCase(cursor.token(1).text, instructionBlockNames());
      if (block) keywords[1] = *block;
    }
    if (block == "OBJECT" && keywords[0] == "START" && cursor.storedTokens() > 2) {
      if (auto kind = objectKindWord(cursor.token(2).text)) keywords[2] = *kind;
    }
    std::size_t indent = depth;
    if (block) {
      // A block's START and END stand at its own level, its lines one in.
      indent = isSection(*block) ? 1 : 0;
      depth = keywords[0] == "START" ? indent + 1 : indent;
    }
    bool topLevel =
        keywords[0] == "OUTPUT_FILE" || (block && indent == 0 && keywords[0] == "START");
    if (topLevel) layout.blankLine();
    if (!layout.line(cursor, indent, keywords)) return std::nullopt;
  }
  return layout.take();
}

}  // namespace scene
