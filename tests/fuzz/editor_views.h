// What an editor asks of a line-format text, on any bytes: its outline and
// the place at each of its first lines answer without a crash, its layout
// laid out again is unchanged, and an accepted text's layout reads to the
// same scene.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "scenefile/layout.h"
#include "scenefile/outline.h"
#include "scenefile/read.h"
#include "tests/fuzz/fuzz_input.h"

namespace fuzz {

inline void checkEditorViews(std::string_view text, scene::Format format,
                             const scene::ReadResult& read) {
  scene::Outline outline = scene::outlineOf(text, format);
  for (const scene::OutlineItem& item : outline.items) {
    if (item.firstLine > item.lastLine || outline.innermostAt(item.firstLine) != &item) {
      propertyFailed("an outline item out of place", std::string(text));
    }
  }
  std::size_t lineStart = 0;
  for (std::uint32_t line = 1; line <= 64 && lineStart <= text.size(); ++line) {
    scene::TextPlace place = scene::placeAt(text, format, lineStart, line, line % 9 + 1);
    if (place.wordIndex > place.words.size()) {
      propertyFailed("a place's word past its line's words", std::string(text));
    }
    std::size_t newline = text.find('\n', lineStart);
    if (newline == std::string_view::npos) break;
    lineStart = newline + 1;
  }
  std::optional<std::string> laid = scene::canonicalLayout(text, format);
  if (!laid) return;
  if (scene::canonicalLayout(*laid, format) != laid) {
    propertyFailed("a layout laid out again changes", *laid);
  }
  if (!read.ok()) return;
  scene::ReadResult again = scene::parseSceneAs(format, *laid, "laid-out");
  if (!again.ok() || !(again.scene == read.scene)) {
    propertyFailed("an accepted text laid out reads otherwise", *laid);
  }
}

}  // namespace fuzz
