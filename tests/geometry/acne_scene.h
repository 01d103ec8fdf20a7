// The acne scene of docs/ACCURACY.md: a plane, a sphere, a cube and a
// cylinder resting on it, a cylinder floating above, one white light, matte
// materials of distinct colours (AMBIENT 0.1, DIFFUSE 0.9, SPECULAR 0); laid
// out at several scales and distances from the origin. The reference
// caster says, per pixel, which surface is seen and whether it faces the
// light with a clear path; `evaluate` then counts the pixels of an image
// that are drawn at ambient level although they are lit.
//
// This library knows nothing of the renderer: images come in as plain
// linear RGB, so the same code judges the renderer and POV-Ray.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "scenefile/scene.h"

namespace acne {

inline constexpr int kWidth = 160;
inline constexpr int kHeight = 120;
inline constexpr double kFovDegrees = 60.0;

// The scene at unit scale spans about 10 units; each layout multiplies every
// coordinate by `scale` and then moves it by `offset`.
struct Layout {
  std::string label;
  double scale = 1.0;
  glm::dvec3 offset{0.0};
};

// 1e-6, 1e-3, 1, 1e3, 1e6 at the origin, and 1 and 1e-3 moved 1e6 away on
// every axis.
std::vector<Layout> layouts();

// The objects, in order: the plane and the primitives named here.
inline constexpr int kPrimitives = 5;
inline constexpr std::array<const char*, kPrimitives> kPrimitiveNames = {
    "plane", "sphere", "cube", "cylinder", "floating cylinder"};

scene::Scene buildScene(const Layout& layout);
// About 10 units at unit scale.
inline double sceneSize(const Layout& layout) {
  return 10.0 * layout.scale;
}

// What the reference says about one pixel.
struct PixelTruth {
  std::int32_t object = -1;
  bool nearSilhouette = false;  // the centre ray passes within 1e-6 rad of an outline
  double cosine = 0.0;          // between the light and the normal that faces the eye
  bool clearPath = false;       // nothing on the segment to the light, nor to it moved by 1e-6
  bool blockedPath = false;     // something on all those segments
  glm::dvec3 ambient{0.0};      // C * L * AMBIENT, the level of an unlit pixel
  glm::dvec3 lit{0.0};          // C * L * (AMBIENT + DIFFUSE * cosine), at least
  // A pixel that must not be drawn at ambient level: a clear path, facing
  // the light by more than 0.1, away from outlines.
  bool mustBeLit() const { return clearPath && cosine > 0.1 && !nearSilhouette; }
  // A pixel that must be drawn at ambient level: facing the light, but
  // the light is hidden from it whichever way it is moved by 1e-6.
  bool mustBeDark() const { return blockedPath && cosine > 0.1 && !nearSilhouette; }
};

// `sceneSize` scales the 1e-6 margin of the shadow test.
std::vector<PixelTruth> referencePixels(const scene::Scene& scene, double sceneSize);

// How an image compares, per primitive.
struct Counts {
  std::array<int, kPrimitives> lit{};       // pixels that must be lit
  std::array<int, kPrimitives> darkLit{};   // ... drawn at ambient level (acne) or below
  std::array<int, kPrimitives> blackLit{};  // ... of which black: no surface drawn at all
  std::array<int, kPrimitives> underLit{};  // ... darker than the ambient + diffuse floor
  std::array<int, kPrimitives> shadowed{};  // pixels that must be dark
  std::array<int, kPrimitives> leaks{};     // ... drawn brighter than ambient
  int nonFinite = 0;
};

// `rgb`: linear, three values a pixel, row by row from the top. A channel
// is at ambient level when it is at most ambient * (1 + relative) +
// absolute, which allows for the storage (float, or 8 bits).
Counts evaluate(const std::vector<PixelTruth>& truth, const std::vector<float>& rgb,
                double relative, double absolute);

// The object a pixel of an image shows, told by its colour: with matte
// materials a pixel is a multiple of its object's colour, so the object is
// the one whose colour points the same way; -1 for a pixel whose channels
// are all at most `black`.
std::int32_t objectByColour(const scene::Scene& scene, const float* rgb, double black);

}  // namespace acne
