// The parts of a scene as the POV-Ray reader gathers them, statement by
// statement, before the scene is built from them: transforms, materials,
// pending objects and lights, and the camera's vectors. They hold what
// POV-Ray's language says (a left-handed world, a texture over #default
// over POV-Ray's defaults); pov_scene_builder.h turns them into the model.
#pragma once

#include <cstddef>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scenefile/diagnostic.h"
#include "scenefile/scene.h"

namespace scene {

// A transformation built up operation by operation. An untouched one is
// exactly the identity, so that a lone `matrix` keeps every bit (even -0).
struct PovTransform {
  glm::dmat4 m{1.0};
  bool identity = true;

  void then(const glm::dmat4& t) {
    if (identity) {
      m = t;
      identity = false;
    } else {
      m = t * m;
    }
  }
  void then(const PovTransform& t) {
    if (!t.identity) then(t.m);
  }
};

inline glm::dmat4 povTranslation(const glm::dvec3& v) {
  glm::dmat4 m(1.0);
  m[3] = glm::dvec4(v, 1.0);
  return m;
}

inline glm::dmat4 povScaling(const glm::dvec3& v) {
  glm::dmat4 m(1.0);
  m[0][0] = v.x;
  m[1][1] = v.y;
  m[2][2] = v.z;
  return m;
}

// What pigment, finish, interior and texture statements set; unset values
// come from what was set before (an object's own over #default over
// POV-Ray's defaults).
// A pigment pattern read as its mean colour (pov_pattern_mean.h): a loss
// reported for each object whose colour it gives.
struct PovPatternMean {
  std::string pattern;
  SourceSpan span;
};

struct PovMaterialPatch {
  std::optional<glm::dvec3> colour;
  std::optional<PovPatternMean> pattern;  // where `colour` is a pattern's mean
  std::optional<double> filter, transmit;
  std::optional<double> ambient, diffuse, phong, phongSize, specular, roughness, reflection, ior;

  // Each value that `later` sets replaces this one's.
  void merge(const PovMaterialPatch& later);
};

// POV-Ray 3.7's default texture and interior: every value set.
PovMaterialPatch povDefaultMaterial();

// An object statement, or a declared object, as read.
struct PovPendingObject {
  ObjectKind kind = ObjectKind::Sphere;
  PovTransform transform;
  PovMaterialPatch patch;
  SourceSpan span;
  std::size_t end = 0;    // the offset of the brace that closes it
  int exactComment = -1;  // its exact-value comment (PovToken::exactComment)
};

struct PovPendingLight {
  glm::dmat4 matrix{1.0};
  glm::dvec3 colour{1.0};
  SourceSpan span;
  int exactComment = -1;
};

// The camera vectors as POV-Ray keeps them between camera statements.
struct PovCameraState {
  glm::dvec3 location{0.0};
  glm::dvec3 direction{0.0, 0.0, 1.0};
  glm::dvec3 up{0.0, 1.0, 0.0};
  glm::dvec3 right{1.33, 0.0, 0.0};
  glm::dvec3 sky{0.0, 1.0, 0.0};
};

// What the statements of a file gathered, in file order.
struct PovSceneParts {
  PovCameraState camera;
  SourceSpan cameraSpan;  // of the last camera statement; unknown without one
  int cameraComment = -1;
  std::vector<PovPendingLight> lights;
  std::vector<PovPendingObject> objects;
};

}  // namespace scene
