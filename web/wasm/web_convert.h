// The module's convert(): sfconvert --to TO's output for one text.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace web {

struct WebConversion {
  // The bytes sfconvert --to TO - - writes; nothing where it refuses (errors
  // in the scene, an unknown format name).
  std::optional<std::string> output;
  // An .obj's MTL file, where convertText was given its name; else empty.
  std::string materialLibrary;
  bool binary = false;      // the output is a binary format's (glb)
  std::string diagnostics;  // sfconvert --format json's diagnostics, a JSON array
};

// Converts `text`, named `name` in diagnostics, to the format whose --to
// name is `to`. A .gltf holds its buffer (a data: URI), as sfconvert writes
// one to standard output. An .obj names `materialLibrary` (`mtllib`) and
// comes with that MTL file, as `sfconvert - NAME.obj` writes them; without
// a name, it is standard output's: no MTL, the materials in its comments.
WebConversion convertText(std::string_view text, const std::string& name, const std::string& to,
                          const std::string& materialLibrary = "");

}  // namespace web
