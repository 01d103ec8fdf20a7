// The MTL side of an OBJ: the scene's Phong material as MTL's terms, written
// and read back (docs/OBJ.md, "Materials").
//   Kd  COLOUR * DIFFUSE       Ka  COLOUR * AMBIENT      Ks  SPECULAR (grey)
//   Ns  SHININESS (at most 1000)  Ni  RI  d  1 - TRANSPARENCY
//   illum 2 plain, 3 reflective, 6 transparent (refraction, ray-traced
//   reflection: MTL's glass that bends light)
// REFLECTIVITY has no MTL number: it rides in the object's comment.
#pragma once

#include <glm/vec3.hpp>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "scenefile/diagnostic.h"
#include "scenefile/scene.h"

namespace scene {

// One `newmtl` block's values; a statement the block lacks is unset.
struct MtlMaterial {
  std::optional<glm::dvec3> ka, kd, ks;
  std::optional<double> ns, ni, d, tr;
  std::optional<int> illum;
};

// What the writer writes for `material`.
MtlMaterial mtlOf(const Material& material);
// `name`'s `newmtl` block, ending in a blank line.
std::string mtlBlock(const std::string& name, const MtlMaterial& values);
// Whether the block read back still holds what the writer wrote for a
// material: every value within the agreement of glTF extras.
bool sameMtl(const MtlMaterial& read, const MtlMaterial& written);
// The scene's material nearest an MTL block of any program: COLOUR is Kd,
// DIFFUSE 1, SPECULAR Ks's mean, SHININESS Ns, RI Ni, TRANSPARENCY 1 - d
// (or Tr); each held to its range. AMBIENT and REFLECTIVITY keep their
// defaults: programs disagree on Ka (Blender writes 1 1 1 whatever the
// material), and MTL has no reflectivity number.
Material materialOf(const MtlMaterial& values);

// The blocks of MTL text by name. Statements other than the Phong terms
// (maps, Tf, sharpness, ...) are skipped; a term whose numbers do not read
// is an obj-material warning, and the term is left unset.
std::map<std::string, MtlMaterial> parseMtl(std::string_view text, std::string_view fileName,
                                            DiagnosticList& out);

}  // namespace scene
