// What POV-Ray's standard include files give a scene that this reader knows
// without reading them: the colour names of colors.inc, and the names of
// the standard include files themselves.
#pragma once

#include <array>
#include <string_view>

namespace scene {

struct PovNamedColour {
  std::string_view name;
  std::array<double, 4> rgbf;  // red, green, blue, filter (transmit is 0 for all)
};

// The colour declared under `name` by POV-Ray 3.7's colors.inc, or null.
const PovNamedColour* findPovColour(std::string_view name);

// Every colour of colors.inc, for did-you-mean.
std::array<std::string_view, 130> povColourNames();

// Whether `name` is one of the include files that POV-Ray 3.7 ships
// ("colors.inc", "textures.inc", ...): the only files a scene may include.
bool isPovStandardInclude(std::string_view name);

// Whether including `name` declares colors.inc's colours (colors.inc itself,
// and stdinc.inc, which includes it).
bool povIncludeDeclaresColours(std::string_view name);

}  // namespace scene
