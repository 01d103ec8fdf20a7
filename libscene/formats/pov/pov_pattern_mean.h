// The mean colour of a POV-Ray pigment pattern: what the scene model, one
// colour an object, can hold of checker, hexagon, brick and the patterns
// that pick from a colour_map. Colours are POV-Ray's five components (red,
// green, blue, filter, transmit).
#pragma once

#include <glm/vec3.hpp>
#include <span>
#include <string_view>
#include <vector>

#include "libscene/formats/pov/pov_value.h"

namespace scene {

// A colour_map entry: the colour at a pattern value.
struct PovMapEntry {
  double value = 0.0;
  PovValue colour;
};

// POV-Ray's limit on a colour_map's entries.
inline constexpr std::size_t kPovMaxMapEntries = 256;

// checker, hexagon, brick: patterns of a list of colours.
bool isPovListPattern(std::string_view word);
// How many colours a list pattern takes (2, or 3 for hexagon).
std::size_t povListPatternSize(std::string_view pattern);
// The colours POV-Ray gives a list pattern without a list (checker blue and
// green; hexagon blue, green and red; brick grey mortar and red brick).
std::vector<PovValue> povDefaultListColours(std::string_view pattern);
// Patterns whose value in [0, 1] picks a colour from a colour_map (gradient,
// marble, bozo, wood, ...).
bool isPovMapPattern(std::string_view word);

// The mean of a colour map over the pattern values [0, 1]: POV-Ray
// interpolates linearly between entries, in ascending order, and holds the
// first and last colours beyond them. Finite for finite entries.
PovValue povColourMapMean(std::span<const PovMapEntry> entries);
// The mean of colours that each cover the same share (checker, hexagon).
PovValue povEqualShareMean(std::span<const PovValue> colours);
// brick's mean on a wall facing z: mortar of width `mortar` along x and y of
// each brick_size cell, brick the rest.
PovValue povBrickMean(const PovValue& mortarColour, const PovValue& brickColour,
                      const glm::dvec3& brickSize, double mortar);

}  // namespace scene
