#include "renderer/material_maxima.h"

#include <cmath>

namespace render {

void MaterialMaxima::takeShininess(double shininess) {
  shininess_ = shininess;
  highlight_ = std::pow(kUnitDotMax, shininess);
}

void MaterialMaxima::merge(const MaterialMaxima& other) {
  inRange_ = inRange_ && other.inRange_;
  for (int c = 0; c < 3; ++c) {
    surfaceFactor_[c] = std::max(surfaceFactor_[c], other.surfaceFactor_[c]);
  }
  branchWeight_ = std::max(branchWeight_, other.branchWeight_);
}

}  // namespace render
