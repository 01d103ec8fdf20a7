#include "libscene/formats/sf/sf_outline.h"

#include <algorithm>

#include "libscene/formats/sf/sf_reader.h"
#include "libscene/text/nearby_lines.h"
#include "libscene/text/reader_support.h"
#include "libscene/text/text_lines.h"

namespace scene {

namespace {

constexpr std::uint32_t kBodyLines = 5;

// The first word of a line and where it starts; empty for a blank line.
struct FirstWord {
  std::string_view text;
  std::uint32_t column = 0;
};

FirstWord firstWord(std::string_view line) {
  std::string_view word = lineHead(line, 1).first;
  return FirstWord{word, static_cast<std::uint32_t>(word.data() - line.data() + 1)};
}

bool isLetter(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}

bool isComment(std::string_view word) {
  return word.starts_with("#") || word.starts_with("//");
}

// The record a name line starts: the outline kind and object kind of the
// name in any case (the reader reads "sphere" as the SPHERE it means).
struct RecordName {
  OutlineKind kind = OutlineKind::Camera;
  std::optional<ObjectKind> objectKind;
};

std::optional<RecordName> recordName(std::string_view word) {
  std::optional<std::string_view> name = keywordInOtherCase(word, sceneFileRecordNames());
  if (!name) return std::nullopt;
  if (*name == "CAMERA") return RecordName{OutlineKind::Camera, std::nullopt};
  if (*name == "LIGHT") return RecordName{OutlineKind::Light, std::nullopt};
  return RecordName{OutlineKind::Object, objectKindFromName(*name)};
}

// Whether a line inside a record ends it: a record name as written.
bool endsRecord(std::string_view word) {
  if (word.empty() || !isLetter(word[0])) return false;
  std::span<const std::string_view> names = sceneFileRecordNames();
  return std::find(names.begin(), names.end(), word) != names.end();
}

}  // namespace

Outline sceneFileOutline(std::string_view text) {
  Outline outline;
  // A record takes some 120 bytes in a typical file: room for most files'
  // records in one allocation, and no more than the text's size for any.
  outline.items.reserve(std::min<std::size_t>(text.size() / 96, std::size_t{1} << 24));
  LineCursor cursor(text);
  std::uint32_t lights = 0;
  std::uint32_t objects = 0;
  OutlineItem* open = nullptr;  // the record whose body is being read
  std::uint32_t bodyLines = 0;
  bool inNamelessRecord = false;  // the body of a line of an unknown word
  while (cursor.nextLine()) {
    FirstWord word = firstWord(cursor.line());
    if (word.text.empty() || isComment(word.text)) continue;
    bool inBody = (open || inNamelessRecord) && bodyLines < kBodyLines && !endsRecord(word.text);
    if (inBody) {
      ++bodyLines;
      if (open) {
        open->lastLine = cursor.lineNumber();
        open->complete = bodyLines == kBodyLines;
      }
      continue;
    }
    open = nullptr;
    inNamelessRecord = false;
    if (!isLetter(word.text[0])) continue;  // stray numbers: no record
    bodyLines = 0;
    std::optional<RecordName> name = recordName(word.text);
    if (!name) {
      inNamelessRecord = true;
      continue;
    }
    OutlineItem item;
    item.kind = name->kind;
    item.objectKind = name->objectKind;
    if (item.kind == OutlineKind::Light) item.number = ++lights;
    if (item.kind == OutlineKind::Object) item.number = ++objects;
    item.firstLine = item.lastLine = cursor.lineNumber();
    item.name =
        SourceSpan{cursor.lineNumber(), word.column, static_cast<std::uint32_t>(word.text.size())};
    item.parent = Outline::kNoParent;
    outline.items.push_back(item);
    open = &outline.items.back();
  }
  return outline;
}

TextPlace sceneFilePlace(std::string_view text, std::size_t lineStart, std::uint32_t line,
                         std::uint32_t column) {
  TextPlace place;
  LineCursor cursor = cursorAt(text, lineStart, line);
  placeWords(cursor, column, place);
  if (cursor.blank()) return place;  // between records, or where one starts
  auto inRecord = [&](std::string_view name, std::uint32_t nameLine, std::uint32_t recordLine) {
    std::optional<RecordName> record = recordName(name);
    if (!record) return;
    place.block = record->kind;
    place.objectKind = record->objectKind;
    place.blockFirstLine = nameLine;
    place.recordLine = recordLine;
  };
  FirstWord here = firstWord(cursor.line());
  if (isLetter(here.text[0]) && recordName(here.text)) {
    inRecord(here.text, line, 0);
    return place;
  }
  // Back over the record's lines before this one; blank lines and comments
  // do not count, but a few dozen of them end the search.
  LinesBefore before(text, lineStart, line);
  std::uint32_t bodyLinesBefore = 0;
  for (int looked = 0; looked < 64 && bodyLinesBefore < kBodyLines && before.previous(); ++looked) {
    FirstWord word = firstWord(before.line());
    if (word.text.empty() || isComment(word.text)) continue;
    if (isLetter(word.text[0]) && recordName(word.text)) {
      inRecord(word.text, before.lineNumber(), bodyLinesBefore + 1);
      return place;
    }
    ++bodyLinesBefore;
  }
  return place;
}

}  // namespace scene
