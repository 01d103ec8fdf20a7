// The statements of OBJ text, checked and gathered: the vertices, the
// groups (`o` and `g`) with their triangles, materials and exact-value
// comments, and the MTL files named. Nothing is fitted here (obj_reader.h).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "libscene/formats/obj/obj_exact.h"
#include "scenefile/read.h"

namespace scene {

// One `o` or `g` group that has faces.
struct ObjGroup {
  std::string name;  // printable, at most 64 bytes: for messages
  SourceSpan span;   // its `o`/`g` line, or its first face
  std::optional<ObjectComment> comment;
  // Three corners a triangle (polygons split as fans), each an index into
  // ObjStatements::positions.
  std::vector<std::uint32_t> corners;
  // The `usemtl` in force at its first face; whether another came after.
  std::string material;
  SourceSpan materialSpan;
  bool severalMaterials = false;
};

struct ObjLibrary {
  std::string name;
  SourceSpan span;
};

struct ObjStatements {
  std::vector<glm::dvec3> positions;
  std::vector<ObjGroup> groups;
  std::vector<ObjLibrary> libraries;
  SceneComments comments;
};

// A name from the file as a message may quote it: printable ASCII (any
// other byte '?'), cut at 64 bytes.
std::string objPrintableName(std::string_view name);

// Reads every statement; errors (obj-syntax, invalid-number,
// number-out-of-range, obj-too-large, too-many-objects) go to `out`, and
// reading stops at a limit or once `out` is full.
ObjStatements readObjStatements(std::string_view text, const ReadOptions& options,
                                DiagnosticList& out);

}  // namespace scene
