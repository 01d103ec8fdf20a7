// What a POV-Ray name is declared as (#declare, #local): a value that
// expressions read, or a pigment, finish, texture, interior, material,
// transform or object that the blocks of those kinds take by name.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "libscene/formats/pov/pov_scene_parts.h"
#include "libscene/formats/pov/pov_value.h"

namespace scene {

enum class PovSymbolKind {
  Value,
  Pigment,
  Finish,
  Texture,
  Interior,
  Material,
  Transform,
  Object,
  Other
};

struct PovSymbol {
  PovSymbolKind kind = PovSymbolKind::Value;
  PovValue value;
  PovMaterialPatch patch;
  PovTransform transform;
  // For Object: the object as declared, which each placement copies.
  std::shared_ptr<const PovPendingObject> object;
  std::string what;  // for Other: what was declared ("a union", "a string")
  // The value's expression failed (0 / 0, a syntax error): that error was
  // reported, and a use of the name fails without a second one.
  bool failed = false;
};

// What an error message calls a kind: "a pigment", "an object", ...
std::string_view povSymbolKindName(PovSymbolKind kind);

}  // namespace scene
