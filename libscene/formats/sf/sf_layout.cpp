#include "libscene/formats/sf/sf_layout.h"

#include "libscene/formats/sf/sf_reader.h"
#include "libscene/text/line_layout.h"
#include "libscene/text/reader_support.h"

namespace scene {

std::optional<std::string> sceneFileLayout(std::string_view text) {
  LineLayout layout(text);
  LineCursor cursor(text);
  while (cursor.next()) {
    if (cursor.blank()) continue;
    std::string_view keywords[3];
    if (auto name = keywordInOtherCase(cursor.token(0).text, sceneFileRecordNames())) {
      keywords[0] = *name;
      layout.blankLine();
    }
    if (!layout.line(cursor, 0, keywords)) return std::nullopt;
  }
  return layout.take();
}

}  // namespace scene
