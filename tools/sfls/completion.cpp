// textDocument/completion: the keywords that may stand at the cursor, from
// the library's keyword table and the place around the cursor, and whole
// records and blocks as snippets where the client takes them.
#include <algorithm>
#include <string>
#include <vector>

#include "scenefile/keywords.h"
#include "tools/sfls/document_place.h"
#include "tools/sfls/features.h"
#include "tools/sfls/lsp_json.h"

namespace sfls {
namespace {

using scene::KeywordPlace;

// The protocol's CompletionItemKind and InsertTextFormat.
constexpr int kKeywordItem = 14;
constexpr int kSnippetItem = 15;
constexpr int kPlainText = 1;
constexpr int kSnippet = 2;

// What the completion replaces: the word typed so far, up to the cursor.
struct Typed {
  std::size_t index = 0;  // the word's index on its line
  scene::SourceSpan span;
};

Typed typedWord(const DocumentPlace& at) {
  const scene::TextPlace& place = at.place;
  std::uint32_t cursor = at.source.column;
  if (place.wordIndex < place.words.size()) {
    const scene::SourceSpan& word = place.words[place.wordIndex].span;
    return {place.wordIndex, {at.source.line, word.column, cursor - std::min(cursor, word.column)}};
  }
  std::size_t before = 0;
  while (before < place.words.size() && place.words[before].span.column < cursor) ++before;
  return {before, {at.source.line, cursor, 0}};
}

// Whether a keyword's arguments are values a user types ("x y z", "name"),
// not words of the format ("CAMERA | LIGHT | OBJECT kind", END's block).
bool takesValues(const scene::KeywordInfo& info) {
  if (info.arguments.empty() || info.place == KeywordPlace::BlockName) return false;
  return std::none_of(info.arguments.begin(), info.arguments.end(),
                      [](char c) { return (c >= 'A' && c <= 'Z') || c == '|'; });
}

class Items {
 public:
  Items(const Document& document, const Typed& typed, bool snippets)
      : range_(document.toLsp(typed.span)), snippets_(snippets) {}

  bool snippets() const { return snippets_; }

  // A keyword, with its arguments as tab stops where the client takes
  // snippets; `text` is what is inserted for the word ("END CAMERA").
  void keyword(const scene::KeywordInfo& info, std::string_view text) {
    std::string newText(text);
    bool withStops = snippets_ && takesValues(info);
    if (withStops) {
      int stop = 0;
      for (std::string_view name : argumentNames(info.arguments)) {
        newText += " ${" + std::to_string(++stop) + ":" + std::string(name) + "}";
      }
    }
    std::string documentation(info.meaning);
    if (!info.range.empty()) documentation += "\n\nValid: " + std::string(info.range) + ".";
    nlohmann::json item = entry(std::string(text), kKeywordItem, newText, withStops, "0");
    item["detail"] =
        std::string(text) + (info.arguments.empty() ? "" : " ") + std::string(info.arguments);
    item["documentation"] = {{"kind", "markdown"}, {"value", documentation}};
    items_.push_back(std::move(item));
  }

  // A whole record or block; `word` is what it is found by as typed.
  void snippet(std::string_view word, std::string_view label, std::string_view body,
               std::string_view documentation) {
    nlohmann::json item = entry(std::string(label), kSnippetItem, std::string(body), true, "1");
    item["filterText"] = std::string(word);
    item["detail"] = std::string(documentation);
    items_.push_back(std::move(item));
  }

  nlohmann::json list() && { return {{"isIncomplete", false}, {"items", std::move(items_)}}; }

 private:
  nlohmann::json entry(std::string label, int kind, std::string newText, bool snippet,
                       std::string_view order) {
    nlohmann::json item = {{"label", label},
                           {"kind", kind},
                           {"sortText", std::string(order) + label},
                           {"insertTextFormat", snippet ? kSnippet : kPlainText},
                           {"textEdit", {{"range", range_}, {"newText", std::move(newText)}}}};
    return item;
  }

  LspRange range_;
  bool snippets_;
  nlohmann::json items_ = nlohmann::json::array();
};

// A scene file record with an identity matrix, its colour and translation
// as tab stops.
std::string recordSnippet(std::string_view name) {
  std::string colour = name == "CAMERA" ? "0" : "1";
  return std::string(name) + "\n${1:" + colour + "} ${2:" + colour + "} ${3:" + colour +
         "}\n1 0 0 ${4:0}\n0 1 0 ${5:0}\n0 0 1 ${6:0}\n0 0 0 1\n$0";
}

// Whether the checked text has its one camera on another line than
// `line`: a second one would be an error, so none is offered.
bool cameraElsewhere(const Analysis* analysis, std::uint32_t line) {
  if (!analysis) return false;
  const std::vector<scene::OutlineItem>& items = analysis->outline.items;
  return std::any_of(items.begin(), items.end(), [&](const scene::OutlineItem& item) {
    return item.kind == scene::OutlineKind::Camera && item.firstLine != line;
  });
}

void sceneFileItems(const DocumentPlace& at, const Typed& typed, bool cameraTaken, Items& items) {
  const scene::TextPlace& place = at.place;
  bool recordStarts = !place.block || place.recordLine == 0u;
  if (typed.index != 0 || !recordStarts) return;
  std::vector<const scene::KeywordInfo*> records =
      scene::keywordsAt(at.format, KeywordPlace::Record);
  if (cameraTaken) std::erase_if(records, [](auto* info) { return info->word == "CAMERA"; });
  for (const scene::KeywordInfo* info : records) items.keyword(*info, info->word);
  if (!items.snippets()) return;
  for (const scene::KeywordInfo* info : records) {
    items.snippet(info->word, std::string(info->word) + " record", recordSnippet(info->word),
                  "a whole record: name, colour and matrix");
  }
}

// Whether every line before `line0` (from 0) is blank: OUTPUT_FILE may
// stand only first. The walk stops at the first word, so it costs only the
// blank lines above.
bool onlyBlankLinesBefore(const Document& document, std::uint32_t line0) {
  for (std::uint32_t line = line0; line-- > 0;) {
    std::string_view text = document.lineText(line);
    if (line == 0 && text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    if (text.find_first_not_of(" \t\r") != std::string_view::npos) return false;
  }
  return true;
}

bool givenInBlock(const scene::TextPlace& place, std::string_view word) {
  for (std::string_view given : place.keywordsInBlock) {
    if (given == word) return true;
  }
  return false;
}

void blockSnippets(KeywordPlace where, const scene::TextPlace& place, bool cameraTaken,
                   Items& items) {
  if (where == KeywordPlace::TopLevel) {
    std::string kinds;
    for (scene::ObjectKind kind : scene::kObjectKinds) {
      kinds += (kinds.empty() ? "" : ",") + std::string(scene::objectKindName(kind));
    }
    if (!cameraTaken) {
      items.snippet("START CAMERA", "START CAMERA block",
                    "START CAMERA\n  LOCATION ${1:0} ${2:0} ${3:5}\n  LOOK_AT ${4:0} ${5:0} "
                    "${6:0}\nEND CAMERA\n$0",
                    "a camera: where it stands and where it looks");
    }
    items.snippet("START LIGHT", "START LIGHT block",
                  "START LIGHT\n  LOCATION ${1:5} ${2:5} ${3:5}\n  COLOUR ${4:1} ${5:1} "
                  "${6:1}\nEND LIGHT\n$0",
                  "a point light");
    items.snippet("START OBJECT", "START OBJECT block",
                  "START OBJECT ${1|" + kinds +
                      "|}\n  START MATERIAL\n    COLOUR ${2:1} ${3:1} ${4:1}\n  END "
                      "MATERIAL\n  START TRANSFORMATION\n    TRANSLATE ${5:0} ${6:0} ${7:0}\n  "
                      "END TRANSFORMATION\nEND OBJECT\n$0",
                  "an object with a colour and a place");
    return;
  }
  if (where != KeywordPlace::Object) return;
  if (!givenInBlock(place, "MATERIAL")) {
    items.snippet("START MATERIAL", "START MATERIAL section",
                  "START MATERIAL\n  COLOUR ${1:1} ${2:1} ${3:1}\nEND MATERIAL$0",
                  "the object's material");
  }
  if (!givenInBlock(place, "TRANSFORMATION")) {
    items.snippet("START TRANSFORMATION", "START TRANSFORMATION section",
                  "START TRANSFORMATION\n  TRANSLATE ${1:0} ${2:0} ${3:0}\nEND TRANSFORMATION$0",
                  "the object's operations, applied in order");
  }
}

void instructionItems(const Document& document, const DocumentPlace& at, const Typed& typed,
                      bool cameraTaken, Items& items) {
  const scene::TextPlace& place = at.place;
  WordRole role = instructionWordRole(place, typed.index);
  if (!role.place || role.argument) return;
  KeywordPlace where = *role.place;
  // Inside a block, the keywords each given once are left out once given
  // (an OBJECT's sections too: placeAt lists them by name).
  bool once = where == KeywordPlace::Camera || where == KeywordPlace::Light ||
              where == KeywordPlace::Material || where == KeywordPlace::SectionName;
  for (const scene::KeywordInfo* info : scene::keywordsAt(at.format, where)) {
    if (info->word == "OUTPUT_FILE" && !onlyBlankLinesBefore(document, at.source.line - 1)) {
      continue;
    }
    if (info->word == "END" && typed.index == 0 && place.block) {
      items.keyword(*info, "END " + std::string(blockWord(*place.block)));
      continue;
    }
    if (once && givenInBlock(place, info->word)) continue;
    // After END, the name of the block it closes alone.
    if (typed.index == 1 && place.block && info->word != blockWord(*place.block) &&
        !place.words.empty() && place.words[0].text == "END") {
      continue;
    }
    if (where == KeywordPlace::BlockName && info->word == "CAMERA" && cameraTaken) continue;
    if (where == KeywordPlace::Object && info->word == "START" && givenInBlock(place, "MATERIAL") &&
        givenInBlock(place, "TRANSFORMATION")) {
      continue;
    }
    items.keyword(*info, info->word);
  }
  if (items.snippets() && typed.index == 0) blockSnippets(where, place, cameraTaken, items);
}

}  // namespace

nlohmann::json completion(const Document& document, const Analysis* analysis, LspPosition position,
                          bool snippets) {
  std::optional<DocumentPlace> at = placeInDocument(document, analysis, position);
  if (!at) return {{"isIncomplete", false}, {"items", nlohmann::json::array()}};
  Typed typed = typedWord(*at);
  Items items(document, typed, snippets);
  bool cameraTaken = cameraElsewhere(analysis, at->source.line);
  if (at->format == scene::Format::SceneFile) {
    sceneFileItems(*at, typed, cameraTaken, items);
  } else {
    instructionItems(document, *at, typed, cameraTaken, items);
  }
  return std::move(items).list();
}

}  // namespace sfls
