#include "scenefile/srgb.h"

#include <algorithm>
#include <cmath>

namespace scene {

double srgbToLinear(double display) {
  if (!(display > kSrgbDisplayKnee)) return std::max(display, 0.0) / 12.92;
  return std::pow((display + 0.055) / 1.055, 2.4);
}

double linearToSrgb(double linear) {
  if (!(linear > kSrgbLinearKnee)) return std::max(linear, 0.0) * 12.92;
  return 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

}  // namespace scene
