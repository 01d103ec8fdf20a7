// textDocument/hover: what the word under the cursor is. A keyword says
// what it means and takes (the library's keyword table); a number of a
// scene file's record says which entry it is; and where the check of this
// version has read the scene, the record or block says what it made: an
// object's material and bounds, the camera's view, a light, a matrix.
#include <string>
#include <vector>

#include "scenefile/keywords.h"
#include "scenefile/transform.h"
#include "tools/sfls/document_place.h"
#include "tools/sfls/features.h"
#include "tools/sfls/lsp_json.h"
#include "tools/sfls/scene_description.h"

namespace sfls {
namespace {

using scene::KeywordPlace;
using scene::OutlineItem;
using scene::OutlineKind;

constexpr const char* kChannels[] = {"red", "green", "blue"};

// What the table says of a keyword; `titled`, after its name and arguments.
std::string keywordMarkdown(const scene::KeywordInfo& keyword, bool titled = true) {
  std::string out;
  if (titled) {
    out = "**" + std::string(keyword.word) + "**";
    if (!keyword.arguments.empty()) out += " `" + std::string(keyword.arguments) + "`";
    out += "\n\n";
  }
  out += std::string(keyword.meaning);
  if (!keyword.range.empty()) out += "\n\nValid: " + std::string(keyword.range) + ".";
  return out;
}

// What the check of this version knows of the block or record at the place.
struct Known {
  const Analysis* analysis = nullptr;
  const OutlineItem* item = nullptr;
};

Known knownAt(const Analysis* analysis, const scene::TextPlace& place) {
  if (!analysis || !place.block) return {};
  return {analysis, itemStartingAt(*analysis, place.blockFirstLine)};
}

bool spansItem(const scene::SourceSpan& span, const OutlineItem& item) {
  return span.line >= item.firstLine && span.line <= item.lastLine;
}

// The scene's object or light of an item, where the reader took it (a
// file with errors holds only the records it read cleanly, so the numbers
// are checked against the spans the reader recorded).
const scene::Object* objectOf(const Analysis& analysis, const OutlineItem& item) {
  const std::vector<scene::Object>& objects = analysis.result.scene.objects;
  if (item.kind != OutlineKind::Object || item.number == 0 || item.number > objects.size()) {
    return nullptr;
  }
  const scene::Object& object = objects[item.number - 1];
  return spansItem(object.span, item) ? &object : nullptr;
}

const scene::Light* lightOf(const Analysis& analysis, const OutlineItem& item) {
  const std::vector<scene::Light>& lights = analysis.result.scene.lights;
  if (item.kind != OutlineKind::Light || item.number == 0 || item.number > lights.size()) {
    return nullptr;
  }
  const scene::Light& light = lights[item.number - 1];
  return spansItem(light.span, item) ? &light : nullptr;
}

// What the scene holds of the item: empty where the check did not read it.
std::string itemDetails(const Known& known) {
  if (!known.item) return "";
  const Analysis& analysis = *known.analysis;
  switch (known.item->kind) {
    case OutlineKind::Object:
      if (const scene::Object* object = objectOf(analysis, *known.item)) {
        return describeObject(*object);
      }
      break;
    case OutlineKind::Light:
      if (const scene::Light* light = lightOf(analysis, *known.item)) return describeLight(*light);
      break;
    case OutlineKind::Camera:
      if (spansItem(analysis.result.scene.camera.span, *known.item)) {
        return describeCamera(analysis.result.scene);
      }
      break;
    default:
      break;
  }
  return "";
}

std::string label(const scene::TextPlace& place, const Known& known) {
  return itemName(*place.block, place.objectKind, known.item ? known.item->number : 0);
}

std::string joined(std::initializer_list<std::string> parts) {
  std::string out;
  for (const std::string& part : parts) {
    if (part.empty()) continue;
    if (!out.empty()) out += "\n\n";
    out += part;
  }
  return out;
}

std::string colourMeaning(OutlineKind kind) {
  switch (kind) {
    case OutlineKind::Camera:
      return "Ignored, but must be a number.";
    case OutlineKind::Light:
      return "The light's intensity in this channel: not negative, and may exceed 1.";
    default:
      return "Not negative; above 1 draws a warning.";
  }
}

std::string sceneFileHover(const DocumentPlace& at, const Analysis* analysis) {
  const scene::TextPlace& place = at.place;
  if (!place.block || !place.recordLine) return "";
  Known known = knownAt(analysis, place);
  std::string name = label(place, known);
  std::uint32_t recordLine = *place.recordLine;
  std::size_t index = place.wordIndex;
  if (recordLine == 0) {
    const scene::KeywordInfo* keyword =
        scene::findKeyword(place.words[index].text, at.format, KeywordPlace::Record);
    return joined(
        {"**" + name + "**", keyword ? keywordMarkdown(*keyword, false) : "", itemDetails(known)});
  }
  if (recordLine == 1) {
    if (index >= 3) return "";
    return name + ", colour: " + kChannels[index] + "\n\n" + colourMeaning(*place.block);
  }
  std::uint32_t row = recordLine - 1;
  std::uint32_t column = static_cast<std::uint32_t>(index) + 1;
  if (row > 4 || column > 4) return "";
  return name + ", row " + std::to_string(row) + ", column " + std::to_string(column) + ": " +
         std::string(scene::matrixEntryMeaning(*place.block, row, column));
}

// The operation of the TRANSFORMATION line `line` as the reader took it.
const scene::TransformOp* operationOn(const Known& known, std::uint32_t line) {
  if (!known.item || known.item->parent == scene::Outline::kNoParent) return nullptr;
  const OutlineItem& owner = known.analysis->outline.items[known.item->parent];
  const scene::Object* object = objectOf(*known.analysis, owner);
  if (!object || !object->transforms) return nullptr;
  for (const scene::TransformOp& op : *object->transforms) {
    if (op.span.line == line) return &op;
  }
  return nullptr;
}

// A block's START line: the block as the scene holds it, then the keyword.
std::string blockStartHover(const DocumentPlace& at, const Analysis* analysis,
                            const scene::KeywordInfo& keyword) {
  const std::vector<scene::Word>& words = at.place.words;
  Known known{analysis, analysis ? itemStartingAt(*analysis, at.source.line) : nullptr};
  std::optional<OutlineKind> kind =
      known.item ? std::optional(known.item->kind)
                 : (words.size() > 1 ? blockNamed(words[1].text) : std::nullopt);
  if (!kind) return keywordMarkdown(keyword);
  if (*kind == OutlineKind::Material) return keywordMarkdown(keyword);
  if (*kind == OutlineKind::Transformation) {
    std::string matrix;
    if (known.item && known.item->parent != scene::Outline::kNoParent) {
      const OutlineItem& owner = analysis->outline.items[known.item->parent];
      if (const scene::Object* object = objectOf(*analysis, owner)) {
        matrix =
            "The object's matrix, its operations composed:\n\n" + matrixMarkdown(object->matrix);
      }
    }
    return joined({matrix, keywordMarkdown(keyword)});
  }
  std::string name =
      known.item
          ? itemName(known.item->kind, known.item->objectKind, known.item->number)
          : itemName(*kind,
                     words.size() > 2 ? scene::objectKindFromName(words[2].text) : std::nullopt, 0);
  // The block's own name needs no second title.
  bool named = name.starts_with(keyword.word);
  return joined({"**" + name + "**", keywordMarkdown(keyword, !named), itemDetails(known)});
}

std::string instructionHover(const DocumentPlace& at, const Analysis* analysis) {
  const scene::TextPlace& place = at.place;
  WordRole role = instructionWordRole(place, place.wordIndex);
  if (!role.place) return "";
  std::string_view keywordWord = place.words[role.argument ? 0 : place.wordIndex].text;
  const scene::KeywordInfo* keyword = scene::findKeyword(keywordWord, at.format, *role.place);
  if (!keyword) return "";
  if (!role.argument && place.words[0].text == "START") {
    return blockStartHover(at, analysis, *keyword);
  }
  std::string matrix;
  if (*role.place == KeywordPlace::Transformation) {
    if (const scene::TransformOp* op = operationOn(knownAt(analysis, place), at.source.line)) {
      matrix = "The matrix it makes:\n\n" + matrixMarkdown(scene::transformMatrix(*op));
    }
  }
  if (!role.argument) return joined({keywordMarkdown(*keyword), matrix});

  std::vector<std::string_view> names = argumentNames(keyword->arguments);
  std::size_t argument = place.wordIndex - 1;
  if (argument >= names.size()) return "";
  std::string name = "`" + std::string(names[argument]) + "`";
  if (keyword->arguments == "r g b") name += std::string(" (") + kChannels[argument] + ")";
  return joined({name + " of **" + std::string(keyword->word) + "**",
                 keywordMarkdown(*keyword, false), matrix});
}

}  // namespace

nlohmann::json hover(const Document& document, const Analysis* analysis, LspPosition position) {
  std::optional<DocumentPlace> at = placeInDocument(document, analysis, position);
  if (!at || at->place.wordIndex >= at->place.words.size()) return nullptr;
  std::string text = at->format == scene::Format::SceneFile ? sceneFileHover(*at, analysis)
                                                            : instructionHover(*at, analysis);
  if (text.empty()) return nullptr;
  LspRange range = document.toLsp(at->place.words[at->place.wordIndex].span);
  return {{"contents", {{"kind", "markdown"}, {"value", text}}}, {"range", range}};
}

}  // namespace sfls
