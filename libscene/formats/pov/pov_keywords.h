// The words of POV-Ray's language sorted by what the reader does with them:
// the statements it converts, those it skips with their block, the
// patterns that make a pigment more than one colour, and the words that
// make POV-Ray read a file. The parser's recovery, its statements and
// looksLikePov use the same lists, so that they agree on what starts a
// statement.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "scenefile/scene.h"

namespace scene {

// The POV-Ray object that `kind` is read from and written as: sphere, box,
// cylinder or plane (scenefile/object_kinds.def).
std::string_view povObjectKeyword(ObjectKind kind);
// The kind whose POV-Ray object `word` names, if any.
std::optional<ObjectKind> povObjectKind(std::string_view word);

// A statement the reader converts or reads: camera, light_source, the four
// shapes, object, global_settings, background.
bool isPovStatement(std::string_view word);
// Those statements, for a did-you-mean.
std::span<const std::string_view> povStatements();

// A shape or statement of POV-Ray outside the subset (union, mesh, fog,
// ...): skipped with its block.
bool isPovUnsupportedStatement(std::string_view word);

// A pattern or pattern modifier of a pigment, normal or texture (checker,
// gradient, color_map, turbulence, ...).
bool isPovPattern(std::string_view word);

// A word that names a file's type before its name (png "a.png"): POV-Ray
// would read the file.
bool isPovFileType(std::string_view word);

// A directive that may open a POV-Ray file (#version, #include, #declare,
// ...), without its '#'.
bool isPovDirectiveName(std::string_view word);

// translate, rotate, scale, matrix or transform. Inline: every modifier of
// every object is asked.
inline bool isPovTransformWord(std::string_view w) {
  return w == "translate" || w == "rotate" || w == "scale" || w == "matrix" || w == "transform";
}

}  // namespace scene
