/// @file
/// The shape of a scene file or an instruction file as an editor sees it:
/// where each record or block starts and ends (symbols, folding), and what
/// the words around a position are (hover, completion). Both come from the
/// text alone, so that they exist for a file with errors too.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "scenefile/diagnostic.h"
#include "scenefile/format.h"
#include "scenefile/scene.h"

namespace scene {

/// What an outline item is.
enum class OutlineKind : std::uint8_t {
  OutputFile,      ///< an instruction file's OUTPUT_FILE line
  Camera,          ///< a CAMERA record or block
  Light,           ///< a LIGHT record or block
  Object,          ///< an object's record, or its OBJECT block
  Material,        ///< an OBJECT's MATERIAL section
  Transformation,  ///< an OBJECT's TRANSFORMATION section
};

/// One record, block or section.
struct OutlineItem {
  OutlineKind kind = OutlineKind::Camera;
  /// An object's kind, where the text names a valid one.
  std::optional<ObjectKind> objectKind;
  /// Lights and objects count from 1, each in the order of the file, as
  /// Scene::lights and Scene::objects hold them once the file is read; 0 for
  /// the other kinds.
  std::uint32_t number = 0;
  /// The lines the item covers, 1-based and inclusive. An item cut short
  /// (a record of fewer than six lines, a block with no END) ends at its
  /// last line that belongs to it.
  std::uint32_t firstLine = 0;
  std::uint32_t lastLine = 0;
  /// The words that name it: a scene file's record name, an instruction
  /// file's `START X` (or `START OBJECT KIND`), OUTPUT_FILE.
  SourceSpan name;
  /// The index in Outline::items of the item that holds this one, or
  /// Outline::kNoParent.
  std::uint32_t parent = 0;
  /// The record has its six lines, the block its END.
  bool complete = false;
};

/// The items of a text in the order they start, each after the one that
/// holds it.
struct Outline {
  static constexpr std::uint32_t kNoParent = UINT32_MAX;
  std::vector<OutlineItem> items;

  /// The innermost item whose lines hold `line`, or nullptr; a binary search.
  const OutlineItem* innermostAt(std::uint32_t line) const;
};

/// The outline of `text` read as `format`. Scene files and instruction
/// files only; empty for any other format.
Outline outlineOf(std::string_view text, Format format);

/// A word of a line: a run of characters between blanks.
struct Word {
  std::string_view text;
  SourceSpan span;
};

/// What the text around a position is, found from the lines near it (a
/// few lines back in a scene file, back to the block's START in an
/// instruction file), at no cost that grows with the file.
struct TextPlace {
  /// The words of the position's line (the first LineCursor::kMaxTokens).
  std::vector<Word> words;
  /// The index in `words` of the word the position is in or at the end of;
  /// words.size() when it is in none (in blanks, on a blank line).
  std::size_t wordIndex = 0;
  /// The innermost record or block the line is in, where the text says:
  /// its kind, the object's kind, and the line it starts on. Nothing at
  /// the top level of an instruction file or between scene file records.
  /// A scene file's record name line is in its record (recordLine 0); an
  /// instruction file's START line is in the block around it, where the
  /// name it starts is completed, and an END line in the block it ends.
  std::optional<OutlineKind> block;
  std::optional<ObjectKind> objectKind;
  std::uint32_t blockFirstLine = 0;
  /// Scene files: the line's place in its record: 0 the name, 1 the colour,
  /// 2 to 5 the matrix's rows 1 to 4.
  std::optional<std::uint32_t> recordLine;
  /// Instruction files: the first words of the other lines of the block the
  /// line is in ("COLOUR", "AMBIENT", ...), as far as they were read; an
  /// OBJECT's sections by their names ("MATERIAL", "TRANSFORMATION").
  std::vector<std::string_view> keywordsInBlock;
};

/// The place at line `line` and byte column `column` (1-based; the column
/// may be one past the line's end) of `text` read as `format`. `lineStart`
/// is the byte offset of that line's first character, which an editor
/// already keeps. Scene files and instruction files only; an empty place
/// for any other format.
TextPlace placeAt(std::string_view text, Format format, std::size_t lineStart, std::uint32_t line,
                  std::uint32_t column);

}  // namespace scene
