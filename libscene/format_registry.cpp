// The format registry: the rows of libscene/formats/*/NAME_format.cpp in the
// order of scenefile/formats.def, and the lookups every tool uses.
#include <filesystem>
#include <string>

#include "libscene/formats/format_rows.h"
#include "scenefile/format.h"

namespace scene {

std::span<const FormatInfo> formats() {
  // Built once, on first use, and never changed: a table of constants.
  static const FormatInfo kRows[] = {
#define SCENEFILE_FORMAT(enumerator, name, folder, row) row(),
#include "scenefile/formats.def"
#undef SCENEFILE_FORMAT
  };
  return kRows;
}

const FormatInfo& formatInfo(Format format) {
  // The rows are in the enum's order: both are made from formats.def, and
  // libscene/format_registry_test.cpp checks each row's own format.
  return formats()[static_cast<std::size_t>(format)];
}

const FormatInfo* findFormatByName(std::string_view name) {
  for (const FormatInfo& row : formats()) {
    if (row.name == name) return &row;
  }
  return nullptr;
}

const FormatInfo* findFormatByExtension(std::string_view fileName) {
  std::string extension = std::filesystem::path(fileName).extension().string();
  if (extension.empty()) return nullptr;
  for (const FormatInfo& row : formats()) {
    for (std::string_view candidate : row.extensions) {
      if (candidate == extension) return &row;
    }
  }
  return nullptr;
}

std::string describeFormats() {
  std::span<const FormatInfo> rows = formats();
  std::string text;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i > 0) text += i + 1 == rows.size() ? " and " : ", ";
    text += rows[i].plural;
    text += " (";
    for (std::size_t e = 0; e < rows[i].extensions.size(); ++e) {
      if (e > 0) text += ", ";
      text += rows[i].extensions[e];
    }
    text += ")";
  }
  return text;
}

std::string formatNames() {
  std::string text;
  for (const FormatInfo& row : formats()) {
    if (!text.empty()) text += ", ";
    text += row.name;
  }
  return text;
}

}  // namespace scene
