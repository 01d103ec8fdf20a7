// outlineOf and placeAt: each line format's own, through its registry row.
#include "scenefile/outline.h"

#include <algorithm>

namespace scene {

const OutlineItem* Outline::innermostAt(std::uint32_t line) const {
  // The last item to start at or before the line, then out through the
  // items that hold it: top-level items do not overlap, and an item's
  // parent holds every line the item holds.
  auto after =
      std::upper_bound(items.begin(), items.end(), line,
                       [](std::uint32_t l, const OutlineItem& item) { return l < item.firstLine; });
  if (after == items.begin()) return nullptr;
  std::uint32_t index = static_cast<std::uint32_t>(after - items.begin() - 1);
  while (index != kNoParent) {
    const OutlineItem& item = items[index];
    if (item.firstLine <= line && line <= item.lastLine) return &item;
    index = item.parent;
  }
  return nullptr;
}

Outline outlineOf(std::string_view text, Format format) {
  const FormatInfo& row = formatInfo(format);
  return row.outline ? row.outline(text) : Outline{};
}

TextPlace placeAt(std::string_view text, Format format, std::size_t lineStart, std::uint32_t line,
                  std::uint32_t column) {
  const FormatInfo& row = formatInfo(format);
  if (!row.place || line == 0) return TextPlace{};
  return row.place(text, lineStart, line, column);
}

}  // namespace scene
