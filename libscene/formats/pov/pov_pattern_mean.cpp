#include "libscene/formats/pov/pov_pattern_mean.h"

#include <algorithm>
#include <cmath>

namespace scene {

namespace {

constexpr std::string_view kMapPatterns[] = {
    "agate",    "boxed",     "bozo",    "bumps",   "cells",   "crackle", "cylindrical", "dents",
    "gradient", "granite",   "leopard", "marble",  "onion",   "planar",  "quilted",     "radial",
    "ripples",  "spherical", "spiral1", "spiral2", "spotted", "waves",   "wood",        "wrinkles",
};

// a * wa + b * wb, weights in [0, 1]: no sum of two large colours overflows.
PovValue weighted(const PovValue& a, double wa, const PovValue& b, double wb) {
  PovValue out = PovValue::colour(0.0, 0.0, 0.0);
  for (int i = 0; i < 5; ++i) out.v[i] = a.v[i] * wa + b.v[i] * wb;
  return out;
}

void addScaled(PovValue& sum, const PovValue& c, double w) {
  for (int i = 0; i < 5; ++i) sum.v[i] += c.v[i] * w;
}

// The colour at pattern value t between two entries.
PovValue between(const PovMapEntry& a, const PovMapEntry& b, double t) {
  if (!(b.value > a.value)) return b.colour;
  double f = std::clamp((t - a.value) / (b.value - a.value), 0.0, 1.0);
  return weighted(a.colour, 1.0 - f, b.colour, f);
}

}  // namespace

bool isPovListPattern(std::string_view word) {
  return word == "checker" || word == "hexagon" || word == "brick";
}

std::size_t povListPatternSize(std::string_view pattern) {
  return pattern == "hexagon" ? 3 : 2;
}

std::vector<PovValue> povDefaultListColours(std::string_view pattern) {
  PovValue blue = PovValue::colour(0.0, 0.0, 1.0);
  PovValue green = PovValue::colour(0.0, 1.0, 0.0);
  if (pattern == "checker") return {blue, green};
  if (pattern == "hexagon") return {blue, green, PovValue::colour(1.0, 0.0, 0.0)};
  return {PovValue::colour(0.5, 0.5, 0.5), PovValue::colour(0.6, 0.15, 0.15)};
}

bool isPovMapPattern(std::string_view word) {
  return std::find(std::begin(kMapPatterns), std::end(kMapPatterns), word) !=
         std::end(kMapPatterns);
}

PovValue povColourMapMean(std::span<const PovMapEntry> entries) {
  PovValue sum = PovValue::colour(0.0, 0.0, 0.0);
  if (entries.empty()) return sum;
  // Below the first entry and above the last, their colours hold.
  addScaled(sum, entries.front().colour, std::clamp(entries.front().value, 0.0, 1.0));
  addScaled(sum, entries.back().colour, 1.0 - std::clamp(entries.back().value, 0.0, 1.0));
  for (std::size_t i = 0; i + 1 < entries.size(); ++i) {
    double lo = std::clamp(entries[i].value, 0.0, 1.0);
    double hi = std::clamp(entries[i + 1].value, 0.0, 1.0);
    if (!(hi > lo)) continue;
    // Linear between the entries: the trapezoid over [lo, hi].
    addScaled(sum, between(entries[i], entries[i + 1], lo), (hi - lo) / 2.0);
    addScaled(sum, between(entries[i], entries[i + 1], hi), (hi - lo) / 2.0);
  }
  return sum;
}

PovValue povEqualShareMean(std::span<const PovValue> colours) {
  PovValue sum = PovValue::colour(0.0, 0.0, 0.0);
  for (const PovValue& c : colours) addScaled(sum, c, 1.0 / static_cast<double>(colours.size()));
  return sum;
}

PovValue povBrickMean(const PovValue& mortarColour, const PovValue& brickColour,
                      const glm::dvec3& brickSize, double mortar) {
  // The share of a cell's side that is brick, none when mortar fills it.
  auto brickShare = [mortar](double size) {
    size = std::abs(size);
    double m = std::max(mortar, 0.0);
    return size > m ? 1.0 - m / size : 0.0;
  };
  double brick = brickShare(brickSize.x) * brickShare(brickSize.y);
  return weighted(mortarColour, 1.0 - brick, brickColour, brick);
}

}  // namespace scene
