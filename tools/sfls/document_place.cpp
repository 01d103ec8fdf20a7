#include "tools/sfls/document_place.h"

#include "scenefile/read.h"
#include "scenefile/scene.h"

namespace sfls {

using scene::KeywordPlace;
using scene::OutlineKind;

std::optional<scene::Format> documentFormat(const Document& document, const Analysis* analysis) {
  if (analysis) return analysis->format;
  // Recognition reads the first words, past any blank or comment lines:
  // a prefix bounds what a text of nothing else costs each request. The
  // URI's extension decides what the words leave open.
  constexpr std::size_t kRecognitionPrefix = 4096;
  std::string_view text = document.text();
  return scene::detectFormat(text.substr(0, kRecognitionPrefix), document.uri());
}

std::optional<DocumentPlace> placeInDocument(const Document& document, const Analysis* analysis,
                                             LspPosition position) {
  std::optional<scene::Format> format = documentFormat(document, analysis);
  if (!format ||
      (*format != scene::Format::SceneFile && *format != scene::Format::InstructionFile)) {
    return std::nullopt;
  }
  if (position.line >= document.lineCount()) return std::nullopt;
  DocumentPlace at;
  at.format = *format;
  at.source = document.toSource(position);
  at.place = scene::placeAt(document.text(), *format, document.lineOffset(position.line),
                            at.source.line, at.source.column);
  return at;
}

KeywordPlace placeInside(OutlineKind kind) {
  switch (kind) {
    case OutlineKind::Camera:
      return KeywordPlace::Camera;
    case OutlineKind::Light:
      return KeywordPlace::Light;
    case OutlineKind::Object:
      return KeywordPlace::Object;
    case OutlineKind::Material:
      return KeywordPlace::Material;
    case OutlineKind::Transformation:
      return KeywordPlace::Transformation;
    case OutlineKind::OutputFile:
      break;
  }
  return KeywordPlace::TopLevel;
}

std::string_view blockWord(OutlineKind kind) {
  switch (kind) {
    case OutlineKind::OutputFile:
      return "OUTPUT_FILE";
    case OutlineKind::Camera:
      return "CAMERA";
    case OutlineKind::Light:
      return "LIGHT";
    case OutlineKind::Object:
      return "OBJECT";
    case OutlineKind::Material:
      return "MATERIAL";
    case OutlineKind::Transformation:
      return "TRANSFORMATION";
  }
  return "";
}

namespace {

bool isSection(OutlineKind kind) {
  return kind == OutlineKind::Material || kind == OutlineKind::Transformation;
}

bool wordIs(const scene::TextPlace& place, std::size_t index, std::string_view text) {
  return index < place.words.size() && place.words[index].text == text;
}

// Where the line's first word stands. placeAt's block is the one the line
// is in: for a START line, the one it opens the block in.
KeywordPlace firstWordPlace(const scene::TextPlace& place) {
  return place.block ? placeInside(*place.block) : KeywordPlace::TopLevel;
}

}  // namespace

WordRole instructionWordRole(const scene::TextPlace& place, std::size_t index) {
  KeywordPlace first = firstWordPlace(place);
  if (index == 0) return {first, false};
  if (index == 1 && wordIs(place, 0, "START")) {
    if (first == KeywordPlace::TopLevel) return {KeywordPlace::BlockName, false};
    if (first == KeywordPlace::Object) return {KeywordPlace::SectionName, false};
    return {};
  }
  if (index == 1 && wordIs(place, 0, "END")) {
    if (!place.block) return {};
    return {isSection(*place.block) ? KeywordPlace::SectionName : KeywordPlace::BlockName, false};
  }
  if (index == 2 && wordIs(place, 0, "START") && wordIs(place, 1, "OBJECT") &&
      first == KeywordPlace::TopLevel) {
    return {KeywordPlace::ObjectKindName, false};
  }
  if (wordIs(place, 0, "START") || wordIs(place, 0, "END")) return {};
  return {first, true};
}

std::vector<std::string_view> argumentNames(std::string_view arguments) {
  std::vector<std::string_view> names;
  while (!arguments.empty()) {
    std::size_t space = arguments.find(' ');
    if (space != 0) names.push_back(arguments.substr(0, space));
    if (space == std::string_view::npos) break;
    arguments.remove_prefix(space + 1);
  }
  return names;
}

const scene::OutlineItem* itemStartingAt(const Analysis& analysis, std::uint32_t firstLine) {
  const scene::OutlineItem* item = analysis.outline.innermostAt(firstLine);
  while (item && item->firstLine != firstLine) {
    if (item->parent == scene::Outline::kNoParent) return nullptr;
    item = &analysis.outline.items[item->parent];
  }
  return item;
}

std::optional<OutlineKind> blockNamed(std::string_view word) {
  for (OutlineKind kind : {OutlineKind::Camera, OutlineKind::Light, OutlineKind::Object,
                           OutlineKind::Material, OutlineKind::Transformation}) {
    if (blockWord(kind) == word) return kind;
  }
  return std::nullopt;
}

std::string itemName(OutlineKind kind, std::optional<scene::ObjectKind> objectKind,
                     std::uint32_t number) {
  std::string name(kind == OutlineKind::Object && objectKind ? scene::objectKindName(*objectKind)
                                                             : blockWord(kind));
  if (number != 0) name += " " + std::to_string(number);
  return name;
}

}  // namespace sfls
