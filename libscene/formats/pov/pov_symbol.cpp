#include "libscene/formats/pov/pov_symbol.h"

namespace scene {

std::string_view povSymbolKindName(PovSymbolKind kind) {
  switch (kind) {
    case PovSymbolKind::Value:
      return "a value";
    case PovSymbolKind::Pigment:
      return "a pigment";
    case PovSymbolKind::Finish:
      return "a finish";
    case PovSymbolKind::Texture:
      return "a texture";
    case PovSymbolKind::Interior:
      return "an interior";
    case PovSymbolKind::Material:
      return "a material";
    case PovSymbolKind::Transform:
      return "a transform";
    case PovSymbolKind::Object:
      return "an object";
    case PovSymbolKind::Other:
      break;
  }
  return "something else";
}

}  // namespace scene
