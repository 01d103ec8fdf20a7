// What stands at a protocol position of a document, in the library's terms:
// the format, the words and the block around the position (scene::placeAt),
// and where each word of an instruction file's line may stand in the
// keyword table. Hover and completion start from here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scenefile/format.h"
#include "scenefile/keywords.h"
#include "scenefile/outline.h"
#include "tools/sfls/analysis.h"
#include "tools/sfls/document.h"

namespace sfls {

// The format of the document: the analysis's where there is one, else
// recognised from the text as the check will (scene::detectFormat).
std::optional<scene::Format> documentFormat(const Document& document, const Analysis* analysis);

struct DocumentPlace {
  scene::Format format = scene::Format::SceneFile;
  // The position in the library's terms.
  SourcePosition source;
  scene::TextPlace place;
};

// The place at `position`; nothing for a format without lines (glTF,
// POV-Ray) or text in no format.
std::optional<DocumentPlace> placeInDocument(const Document& document, const Analysis* analysis,
                                             LspPosition position);

// Where word `index` of an instruction file's line stands: a keyword at
// `place`, or an argument (number index - 1) of the line's first word, a
// keyword at `place`. Nothing where no word may stand. `index` may be
// words.size(): the word about to be typed.
struct WordRole {
  std::optional<scene::KeywordPlace> place;
  bool argument = false;
};
WordRole instructionWordRole(const scene::TextPlace& place, std::size_t index);

// The place of the lines inside a block of `kind` (its keywords).
scene::KeywordPlace placeInside(scene::OutlineKind kind);

// The block or section name an `END` of a block of `kind` takes: "CAMERA",
// "MATERIAL", ...
std::string_view blockWord(scene::OutlineKind kind);

// The words of a keyword's arguments (KeywordInfo::arguments): "x y z"
// gives x, y and z.
std::vector<std::string_view> argumentNames(std::string_view arguments);

// The block or section kind `word` names, if any.
std::optional<scene::OutlineKind> blockNamed(std::string_view word);

// The item of `analysis` that starts on `firstLine`, if the analysis's
// outline has one (a binary search).
const scene::OutlineItem* itemStartingAt(const Analysis& analysis, std::uint32_t firstLine);

// An item's name as the outline shows it: "CAMERA", "LIGHT 2", "SPHERE 3"
// ("SPHERE" where the number is not known: 0), "MATERIAL", "OUTPUT_FILE".
std::string itemName(scene::OutlineKind kind, std::optional<scene::ObjectKind> objectKind,
                     std::uint32_t number);

}  // namespace sfls
