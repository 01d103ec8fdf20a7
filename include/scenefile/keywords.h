/// @file
/// The words of the two line formats, what each means and what it takes:
/// one table, for an editor's hover and completion and for the docs.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "scenefile/format.h"
#include "scenefile/outline.h"

namespace scene {

/// Where a keyword may stand.
enum class KeywordPlace : std::uint8_t {
  Record,          ///< a scene file's record name, alone on its line
  TopLevel,        ///< an instruction file's top level: OUTPUT_FILE, START
  BlockName,       ///< after START at the top level: CAMERA, LIGHT, OBJECT
  ObjectKindName,  ///< after START OBJECT: PLANE, CUBE, SPHERE, CYLINDER
  Camera,          ///< inside a CAMERA block: LOCATION, LOOK_AT, END
  Light,           ///< inside a LIGHT block: LOCATION, COLOUR, END
  Object,          ///< inside an OBJECT block: START, END
  SectionName,     ///< after START inside an OBJECT: MATERIAL, TRANSFORMATION
  Material,        ///< inside MATERIAL: COLOUR, AMBIENT, ..., END
  Transformation,  ///< inside TRANSFORMATION: SCALE, ..., ROTATE_Z, END
};

struct KeywordInfo {
  std::string_view word;
  Format format = Format::SceneFile;
  KeywordPlace place = KeywordPlace::Record;
  /// What follows the word on its line: "x y z", "r g b", "radians", "".
  std::string_view arguments;
  /// One sentence: what it is or does.
  std::string_view meaning;
  /// The values it accepts, in words ("0 to 1"), or empty where any
  /// number is valid or it takes none.
  std::string_view range;
};

/// Every keyword of scene files and instruction files, each once per place
/// it may stand (COLOUR inside LIGHT and inside MATERIAL are two rows).
std::span<const KeywordInfo> keywords();

/// The keywords that may stand at `place`.
std::vector<const KeywordInfo*> keywordsAt(Format format, KeywordPlace place);

/// The row of `word` at `place`, or nullptr.
const KeywordInfo* findKeyword(std::string_view word, Format format, KeywordPlace place);

/// What entry `row`, `column` (1 to 4 each) of a scene file record's
/// matrix is for a record of `kind`: "translation along y" (objects),
/// "the eye's x" (the camera), "ignored" (a light's linear part), "must
/// be 0" (the last row).
std::string_view matrixEntryMeaning(OutlineKind kind, std::uint32_t row, std::uint32_t column);

}  // namespace scene
