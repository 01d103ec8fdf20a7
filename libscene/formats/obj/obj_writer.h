// The OBJ writer: each object tessellated as the glTF writer does
// (scenefile/mesh.h) into a group of its own, its vertices in world space
// (OBJ has no transforms), normals for the curved shapes, and its Phong
// material in the MTL file beside it; the camera and the lights, which OBJ
// cannot hold, are losses. The exact scene rides in comments (obj_exact.h),
// so that the OBJ reader gives it back bit for bit.
#pragma once

#include <optional>
#include <string>

#include "scenefile/convert.h"

namespace scene {

// The OBJ text and the MTL text (empty when options.obj.materialLibrary is),
// or nothing when an error was reported: a loss under options.noLoss, or
// an object whose vertices in world space are not finite.
std::optional<ConvertedFiles> writeObj(const Scene& scene, const ConversionOptions& options,
                                       DiagnosticList& out);

// The group name (`o`) of object `index` (0 for the first): "SPHERE_1".
std::string objGroupName(const Object& object, std::size_t index);

}  // namespace scene
