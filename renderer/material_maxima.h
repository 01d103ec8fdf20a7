// The largest material terms of a scene that RadianceBound needs, gathered
// while RenderScene makes its records (in parts, on its threads) rather than
// in a pass of their own before the render: at 1,000,000 objects that pass
// took 18 ms of one thread ahead of the first ray.
#pragma once

#include <algorithm>
#include <glm/vec3.hpp>
#include <limits>

#include "scenefile/scene.h"

namespace render {

// Whether `v` is a number at least 0 and finite: the ranges of FORMATS.md
// for a material's values and a light's colour.
inline bool finiteAndNotNegative(double v) {
  return v >= 0.0 && v <= std::numeric_limits<double>::max();
}

class MaterialMaxima {
 public:
  // Takes in one object's material. Inline: it runs once per object, in
  // the records' loop.
  void add(scene::ObjectKind kind, const scene::Material& m) {
    if (!inRangeOf(m)) {
      inRange_ = false;
      return;
    }
    if (!(m.shininess == shininess_)) takeShininess(m.shininess);
    for (int c = 0; c < 3; ++c) {
      double term = m.colour[c] * (m.ambient + m.diffuse * kUnitDotMax) + m.specular * highlight_;
      surfaceFactor_[c] = std::max(surfaceFactor_[c], term);
    }
    branchWeight_ = std::max(branchWeight_, branchWeightOf(kind, m));
  }
  // Takes in what another part gathered: the result is that of one pass
  // over both parts' objects, in any order (a maximum ignores order).
  void merge(const MaterialMaxima& other);

  // Whether every material added lies within the ranges of FORMATS.md
  // (finite and not negative); the figures below count only then.
  bool inRange() const { return inRange_; }
  // Per channel, the most of COLOUR * (AMBIENT + DIFFUSE * c) + SPECULAR *
  // c^SHININESS, with c the largest a dot product of unit vectors comes out
  // (kUnitDotMax): what one light of colour 1 adds to that channel at a hit,
  // at most. A term that is not a number (0 times an infinite highlight) is
  // passed over, as std::max(largest, term) passes it over.
  const glm::dvec3& surfaceFactor() const { return surfaceFactor_; }
  // The most the weights of one hit's reflected and refracted rays add up
  // to (RadianceBound::branchWeight).
  double branchWeight() const { return branchWeight_; }

  // Dot products of unit vectors, the diffuse cosine and the highlight's
  // base, come out at most this far above 1 (a few ulps of normalisation).
  static constexpr double kUnitDotMax = 1.0 + 1e-14;

 private:
  static bool inRangeOf(const scene::Material& m) {
    return finiteAndNotNegative(m.colour.r) && finiteAndNotNegative(m.colour.g) &&
           finiteAndNotNegative(m.colour.b) && finiteAndNotNegative(m.ambient) &&
           finiteAndNotNegative(m.diffuse) && finiteAndNotNegative(m.specular) &&
           finiteAndNotNegative(m.shininess) && finiteAndNotNegative(m.reflectivity) &&
           finiteAndNotNegative(m.transparency);
  }
  // The most the weights of a hit's reflected and refracted rays add up to
  // (RENDERING.md): R * REFLECTIVITY + (1 - R) * TRANSPARENCY with R in
  // [0, 1] when a solid has both, TRANSPARENCY alone for a plane with both
  // (its R is 0), and their plain sum when one of them is 0.
  static double branchWeightOf(scene::ObjectKind kind, const scene::Material& m) {
    if (m.reflectivity > 0.0 && m.transparency > 0.0) {
      if (kind == scene::ObjectKind::Plane) return m.transparency;
      return std::max(m.reflectivity, m.transparency);
    }
    return m.reflectivity + m.transparency;
  }
  // A new shininess, and its highlight max(0, x)^SHININESS for x up to
  // kUnitDotMax.
  void takeShininess(double shininess);

  bool inRange_ = true;
  glm::dvec3 surfaceFactor_{0.0};
  double branchWeight_ = 0.0;
  // The last shininess and its highlight: objects mostly share a few, and
  // std::pow for each of 1,000,000 objects took 20 ms of one thread.
  double shininess_ = std::numeric_limits<double>::quiet_NaN();
  double highlight_ = 0.0;
};

}  // namespace render
