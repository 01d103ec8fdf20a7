#include "libscene/formats/pov/pov_scene_parts.h"

namespace scene {

void PovMaterialPatch::merge(const PovMaterialPatch& later) {
  auto take = [](auto& mine, const auto& theirs) {
    if (theirs) mine = theirs;
  };
  if (later.colour) pattern = later.pattern;
  take(colour, later.colour);
  take(filter, later.filter);
  take(transmit, later.transmit);
  take(ambient, later.ambient);
  take(diffuse, later.diffuse);
  take(phong, later.phong);
  take(phongSize, later.phongSize);
  take(specular, later.specular);
  take(roughness, later.roughness);
  take(reflection, later.reflection);
  take(ior, later.ior);
}

PovMaterialPatch povDefaultMaterial() {
  PovMaterialPatch p;
  p.colour = glm::dvec3(0.0);
  p.filter = 0.0;
  p.transmit = 0.0;
  p.ambient = 0.1;
  p.diffuse = 0.6;
  p.phong = 0.0;
  p.phongSize = 40.0;
  p.specular = 0.0;
  p.roughness = 0.05;
  p.reflection = 0.0;
  p.ior = 1.0;
  return p;
}

}  // namespace scene
