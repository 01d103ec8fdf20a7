#include "libscene/formats/instruction/instruction_outline.h"

#include <algorithm>
#include <vector>

#include "libscene/formats/instruction/instruction_reader.h"
#include "libscene/text/nearby_lines.h"
#include "libscene/text/reader_support.h"
#include "libscene/text/text_lines.h"
#include "scenefile/spelling.h"

namespace scene {

namespace {

// How far placeAt looks each way: far past any block a person writes, and
// bounded for a text that is one endless block.
constexpr int kMostLinesLooked = 4096;

constexpr std::string_view kLineStarts[] = {"OUTPUT_FILE", "START", "END"};

// The keyword a line starts with, in any case: OUTPUT_FILE, START, END, or
// the word itself.
std::string_view lineKeyword(std::string_view word) {
  std::optional<std::string_view> keyword = keywordInOtherCase(word, kLineStarts);
  return keyword ? *keyword : word;
}

// The outline kind of a block name in any case.
std::optional<OutlineKind> blockKind(std::string_view word) {
  std::span<const std::string_view> names = instructionBlockNames();
  std::optional<std::string_view> name = keywordInOtherCase(word, names);
  if (!name) return std::nullopt;
  constexpr OutlineKind kKinds[] = {OutlineKind::Camera, OutlineKind::Light, OutlineKind::Object,
                                    OutlineKind::Material, OutlineKind::Transformation};
  auto index =
      static_cast<std::size_t>(std::find(names.begin(), names.end(), *name) - names.begin());
  return kKinds[index];
}

bool isSection(OutlineKind kind) {
  return kind == OutlineKind::Material || kind == OutlineKind::Transformation;
}

std::string_view blockName(OutlineKind kind) {
  return instructionBlockNames()[static_cast<std::size_t>(kind) -
                                 static_cast<std::size_t>(OutlineKind::Camera)];
}

std::optional<ObjectKind> objectKindNamed(std::string_view word) {
  for (ObjectKind kind : kObjectKinds) {
    if (equalsIgnoringCase(word, objectKindName(kind))) return kind;
  }
  return std::nullopt;
}

std::uint32_t columnOf(std::string_view line, std::string_view word) {
  return static_cast<std::uint32_t>(word.data() - line.data() + 1);
}

bool isComment(std::string_view word) {
  return word.starts_with("#") || word.starts_with("//");
}

class OutlineBuilder {
 public:
  explicit OutlineBuilder(std::string_view text) : cursor_(text) {
    // An object's block and its sections take some 450 bytes as the writer
    // writes them: room for most files' items in one allocation.
    outline_.items.reserve(std::min<std::size_t>(text.size() / 128, std::size_t{1} << 24));
  }

  Outline run() {
    while (cursor_.nextLine()) {
      std::string_view line = cursor_.line();
      LineHead head = lineHead(line, 1);
      if (head.first.empty() || isComment(head.first)) continue;
      std::string_view keyword = lineKeyword(head.first);
      if (keyword == "START" || keyword == "END") head = lineHead(line);
      if (keyword == "OUTPUT_FILE" && open_.empty()) {
        add(OutlineKind::OutputFile, SourceSpan{cursor_.lineNumber(), columnOf(line, head.first),
                                                static_cast<std::uint32_t>(head.first.size())});
        outline_.items.back().complete = true;
      } else if (keyword == "START") {
        start(line, head);
      } else if (keyword == "END") {
        end(head);
      }
      lastContentLine_ = cursor_.lineNumber();
    }
    while (!open_.empty()) closeInnermost(false);
    return std::move(outline_);
  }

 private:
  void add(OutlineKind kind, SourceSpan name) {
    OutlineItem item;
    item.kind = kind;
    item.firstLine = item.lastLine = cursor_.lineNumber();
    item.name = name;
    item.parent = open_.empty() ? Outline::kNoParent : open_.back();
    if (kind == OutlineKind::Light) item.number = ++lights_;
    if (kind == OutlineKind::Object) item.number = ++objects_;
    outline_.items.push_back(item);
  }

  void start(std::string_view line, const LineHead& head) {
    std::optional<OutlineKind> kind = blockKind(head.second);
    if (!kind) return;
    while (!open_.empty() &&
           !(isSection(*kind) && outline_.items[open_.back()].kind == OutlineKind::Object)) {
      closeInnermost(false);
    }
    std::string_view last =
        *kind == OutlineKind::Object && !head.third.empty() ? head.third : head.second;
    std::uint32_t column = columnOf(line, head.first);
    add(*kind, SourceSpan{cursor_.lineNumber(), column,
                          static_cast<std::uint32_t>(columnOf(line, last) + last.size() - column)});
    if (*kind == OutlineKind::Object)
      outline_.items.back().objectKind = objectKindNamed(head.third);
    open_.push_back(static_cast<std::uint32_t>(outline_.items.size() - 1));
  }

  void end(const LineHead& head) {
    std::optional<OutlineKind> kind = blockKind(head.second);
    if (!kind) return;
    auto match = std::find_if(open_.rbegin(), open_.rend(),
                              [&](std::uint32_t i) { return outline_.items[i].kind == *kind; });
    if (match == open_.rend()) return;
    std::size_t depth = static_cast<std::size_t>(open_.rend() - match);
    while (open_.size() > depth) closeInnermost(false);
    closeInnermost(true);
  }

  // An item cut short ends at the last line before the one that ends it.
  void closeInnermost(bool complete) {
    OutlineItem& item = outline_.items[open_.back()];
    open_.pop_back();
    item.complete = complete;
    item.lastLine = complete ? cursor_.lineNumber() : std::max(item.firstLine, lastContentLine_);
  }

  LineCursor cursor_;
  Outline outline_;
  std::vector<std::uint32_t> open_;  // the open blocks' items, outermost first
  std::uint32_t lastContentLine_ = 0;
  std::uint32_t lights_ = 0;
  std::uint32_t objects_ = 0;
};

// Back from the line to the START of each block it is in: the innermost's
// kind and first line, its other lines' first words, the object's kind.
void findBlockBefore(std::string_view text, std::size_t lineStart, std::uint32_t line,
                     TextPlace& place) {
  LinesBefore before(text, lineStart, line);
  std::vector<OutlineKind> closed;  // blocks whose END was passed, innermost last
  for (int looked = 0; looked < kMostLinesLooked && before.previous(); ++looked) {
    LineHead head = lineHead(before.line());
    if (head.first.empty() || isComment(head.first)) continue;
    std::string_view keyword = lineKeyword(head.first);
    if (keyword == "OUTPUT_FILE") return;
    std::optional<OutlineKind> kind = blockKind(head.second);
    bool found = place.block.has_value();
    if (keyword == "END" && kind) {
      if (closed.empty() && !isSection(*kind) && !found) return;  // between top-level blocks
      closed.push_back(*kind);
    } else if (keyword == "START" && kind) {
      if (!closed.empty()) {
        closed.pop_back();
        if (closed.empty() && !found && isSection(*kind)) {
          place.keywordsInBlock.push_back(blockName(*kind));
        }
        continue;
      }
      if (found && (!isSection(*place.block) || *kind != OutlineKind::Object)) return;
      if (*kind == OutlineKind::Object) place.objectKind = objectKindNamed(head.third);
      if (found) return;
      place.block = *kind;
      place.blockFirstLine = before.lineNumber();
      if (!isSection(*kind)) return;
    } else if (closed.empty() && !found) {
      place.keywordsInBlock.push_back(head.first);
    }
  }
}

// On from the line to its block's END: the first words of the block's lines.
void findBlockAfter(std::string_view text, std::size_t lineStart, std::uint32_t line,
                    TextPlace& place) {
  LineCursor cursor(text.substr(std::min(lineStart, text.size())), line);
  if (!cursor.nextLine()) return;
  LineHead here = lineHead(cursor.line());
  std::string_view hereKeyword = lineKeyword(here.first);
  if (hereKeyword == "END") return;
  int depth = hereKeyword == "START" && blockKind(here.second) ? 1 : 0;
  for (int looked = 0; looked < kMostLinesLooked && cursor.nextLine(); ++looked) {
    LineHead head = lineHead(cursor.line());
    if (head.first.empty() || isComment(head.first)) continue;
    std::string_view keyword = lineKeyword(head.first);
    std::optional<OutlineKind> kind = blockKind(head.second);
    if (keyword == "OUTPUT_FILE") return;
    if (keyword == "START" && kind) {
      if (!isSection(*kind)) return;  // a top-level block: this one had no END
      if (depth++ == 0) {
        place.keywordsInBlock.push_back(blockName(*kind));
      }
    } else if (keyword == "END" && kind) {
      if (depth-- == 0) return;
    } else if (depth == 0) {
      place.keywordsInBlock.push_back(head.first);
    }
  }
}

}  // namespace

Outline instructionFileOutline(std::string_view text) {
  return OutlineBuilder(text).run();
}

TextPlace instructionFilePlace(std::string_view text, std::size_t lineStart, std::uint32_t line,
                               std::uint32_t column) {
  TextPlace place;
  LineCursor cursor = cursorAt(text, lineStart, line);
  placeWords(cursor, column, place);
  findBlockBefore(text, lineStart, line, place);
  if (place.block) findBlockAfter(text, lineStart, line, place);
  return place;
}

}  // namespace scene
