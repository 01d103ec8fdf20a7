#include "libscene/formats/pov/pov_names.h"

#include <algorithm>

namespace scene {

namespace {

// Copied from the #declare lines of POV-Ray 3.7's colors.inc (numbers as
// written there, so that they read to the same doubles as POV-Ray reads).
constexpr PovNamedColour kColours[] = {
    {"Red", {1.0, 0.0, 0.0, 0.0}},
    {"Green", {0.0, 1.0, 0.0, 0.0}},
    {"Blue", {0.0, 0.0, 1.0, 0.0}},
    {"Yellow", {1.0, 1.0, 0.0, 0.0}},
    {"Cyan", {0.0, 1.0, 1.0, 0.0}},
    {"Magenta", {1.0, 0.0, 1.0, 0.0}},
    {"Clear", {1.0, 1.0, 1.0, 1.0}},
    {"White", {1.0, 1.0, 1.0, 0.0}},
    {"Black", {0.0, 0.0, 0.0, 0.0}},
    {"Gray05", {0.05, 0.05, 0.05, 0.0}},
    {"Gray10", {0.10, 0.10, 0.10, 0.0}},
    {"Gray15", {0.15, 0.15, 0.15, 0.0}},
    {"Gray20", {0.20, 0.20, 0.20, 0.0}},
    {"Gray25", {0.25, 0.25, 0.25, 0.0}},
    {"Gray30", {0.30, 0.30, 0.30, 0.0}},
    {"Gray35", {0.35, 0.35, 0.35, 0.0}},
    {"Gray40", {0.40, 0.40, 0.40, 0.0}},
    {"Gray45", {0.45, 0.45, 0.45, 0.0}},
    {"Gray50", {0.50, 0.50, 0.50, 0.0}},
    {"Gray55", {0.55, 0.55, 0.55, 0.0}},
    {"Gray60", {0.60, 0.60, 0.60, 0.0}},
    {"Gray65", {0.65, 0.65, 0.65, 0.0}},
    {"Gray70", {0.70, 0.70, 0.70, 0.0}},
    {"Gray75", {0.75, 0.75, 0.75, 0.0}},
    {"Gray80", {0.80, 0.80, 0.80, 0.0}},
    {"Gray85", {0.85, 0.85, 0.85, 0.0}},
    {"Gray90", {0.90, 0.90, 0.90, 0.0}},
    {"Gray95", {0.95, 0.95, 0.95, 0.0}},
    {"DimGray", {0.329412, 0.329412, 0.329412, 0.0}},
    {"DimGrey", {0.329412, 0.329412, 0.329412, 0.0}},
    {"Gray", {0.752941, 0.752941, 0.752941, 0.0}},
    {"Grey", {0.752941, 0.752941, 0.752941, 0.0}},
    {"LightGray", {0.658824, 0.658824, 0.658824, 0.0}},
    {"LightGrey", {0.658824, 0.658824, 0.658824, 0.0}},
    {"VLightGray", {0.80, 0.80, 0.80, 0.0}},
    {"VLightGrey", {0.80, 0.80, 0.80, 0.0}},
    {"Aquamarine", {0.439216, 0.858824, 0.576471, 0.0}},
    {"BlueViolet", {0.62352, 0.372549, 0.623529, 0.0}},
    {"Brown", {0.647059, 0.164706, 0.164706, 0.0}},
    {"CadetBlue", {0.372549, 0.623529, 0.623529, 0.0}},
    {"Coral", {1.0, 0.498039, 0.0, 0.0}},
    {"CornflowerBlue", {0.258824, 0.258824, 0.435294, 0.0}},
    {"DarkGreen", {0.184314, 0.309804, 0.184314, 0.0}},
    {"DarkOliveGreen", {0.309804, 0.309804, 0.184314, 0.0}},
    {"DarkOrchid", {0.6, 0.196078, 0.8, 0.0}},
    {"DarkSlateBlue", {0.119608, 0.137255, 0.556863, 0.0}},
    {"DarkSlateGray", {0.184314, 0.309804, 0.309804, 0.0}},
    {"DarkSlateGrey", {0.184314, 0.309804, 0.309804, 0.0}},
    {"DarkTurquoise", {0.439216, 0.576471, 0.858824, 0.0}},
    {"Firebrick", {0.556863, 0.137255, 0.137255, 0.0}},
    {"ForestGreen", {0.137255, 0.556863, 0.137255, 0.0}},
    {"Gold", {0.8, 0.498039, 0.196078, 0.0}},
    {"Goldenrod", {0.858824, 0.858824, 0.439216, 0.0}},
    {"GreenYellow", {0.576471, 0.858824, 0.439216, 0.0}},
    {"IndianRed", {0.309804, 0.184314, 0.184314, 0.0}},
    {"Khaki", {0.623529, 0.623529, 0.372549, 0.0}},
    {"LightBlue", {0.74902, 0.847059, 0.847059, 0.0}},
    {"LightSteelBlue", {0.560784, 0.560784, 0.737255, 0.0}},
    {"LimeGreen", {0.196078, 0.8, 0.196078, 0.0}},
    {"Maroon", {0.556863, 0.137255, 0.419608, 0.0}},
    {"MediumAquamarine", {0.196078, 0.8, 0.6, 0.0}},
    {"MediumBlue", {0.196078, 0.196078, 0.8, 0.0}},
    {"MediumForestGreen", {0.419608, 0.556863, 0.137255, 0.0}},
    {"MediumGoldenrod", {0.917647, 0.917647, 0.678431, 0.0}},
    {"MediumOrchid", {0.576471, 0.439216, 0.858824, 0.0}},
    {"MediumSeaGreen", {0.258824, 0.435294, 0.258824, 0.0}},
    {"MediumSlateBlue", {0.498039, 0.0, 1.0, 0.0}},
    {"MediumSpringGreen", {0.498039, 1.0, 0.0, 0.0}},
    {"MediumTurquoise", {0.439216, 0.858824, 0.858824, 0.0}},
    {"MediumVioletRed", {0.858824, 0.439216, 0.576471, 0.0}},
    {"MidnightBlue", {0.184314, 0.184314, 0.309804, 0.0}},
    {"Navy", {0.137255, 0.137255, 0.556863, 0.0}},
    {"NavyBlue", {0.137255, 0.137255, 0.556863, 0.0}},
    {"Orange", {1.0, 0.5, 0.0, 0.0}},
    {"OrangeRed", {1.0, 0.25, 0.0, 0.0}},
    {"Orchid", {0.858824, 0.439216, 0.858824, 0.0}},
    {"PaleGreen", {0.560784, 0.737255, 0.560784, 0.0}},
    {"Pink", {0.737255, 0.560784, 0.560784, 0.0}},
    {"Plum", {0.917647, 0.678431, 0.917647, 0.0}},
    {"Salmon", {0.435294, 0.258824, 0.258824, 0.0}},
    {"SeaGreen", {0.137255, 0.556863, 0.419608, 0.0}},
    {"Sienna", {0.556863, 0.419608, 0.137255, 0.0}},
    {"SkyBlue", {0.196078, 0.6, 0.8, 0.0}},
    {"SlateBlue", {0.0, 0.498039, 1.0, 0.0}},
    {"SpringGreen", {0.0, 1.0, 0.498039, 0.0}},
    {"SteelBlue", {0.137255, 0.419608, 0.556863, 0.0}},
    {"Tan", {0.858824, 0.576471, 0.439216, 0.0}},
    {"Thistle", {0.847059, 0.74902, 0.847059, 0.0}},
    {"Turquoise", {0.678431, 0.917647, 0.917647, 0.0}},
    {"Violet", {0.309804, 0.184314, 0.309804, 0.0}},
    {"VioletRed", {0.8, 0.196078, 0.6, 0.0}},
    {"Wheat", {0.847059, 0.847059, 0.74902, 0.0}},
    {"YellowGreen", {0.6, 0.8, 0.196078, 0.0}},
    {"SummerSky", {0.22, 0.69, 0.87, 0.0}},
    {"RichBlue", {0.35, 0.35, 0.67, 0.0}},
    {"Brass", {0.71, 0.65, 0.26, 0.0}},
    {"Copper", {0.72, 0.45, 0.20, 0.0}},
    {"Bronze", {0.55, 0.47, 0.14, 0.0}},
    {"Bronze2", {0.65, 0.49, 0.24, 0.0}},
    {"Silver", {0.90, 0.91, 0.98, 0.0}},
    {"BrightGold", {0.85, 0.85, 0.10, 0.0}},
    {"OldGold", {0.81, 0.71, 0.23, 0.0}},
    {"Feldspar", {0.82, 0.57, 0.46, 0.0}},
    {"Quartz", {0.85, 0.85, 0.95, 0.0}},
    {"Mica", {0.0, 0.0, 0.0, 0.0}},
    {"NeonPink", {1.00, 0.43, 0.78, 0.0}},
    {"DarkPurple", {0.53, 0.12, 0.47, 0.0}},
    {"NeonBlue", {0.30, 0.30, 1.00, 0.0}},
    {"CoolCopper", {0.85, 0.53, 0.10, 0.0}},
    {"MandarinOrange", {0.89, 0.47, 0.20, 0.0}},
    {"LightWood", {0.91, 0.76, 0.65, 0.0}},
    {"MediumWood", {0.65, 0.50, 0.39, 0.0}},
    {"DarkWood", {0.52, 0.37, 0.26, 0.0}},
    {"SpicyPink", {1.00, 0.11, 0.68, 0.0}},
    {"SemiSweetChoc", {0.42, 0.26, 0.15, 0.0}},
    {"BakersChoc", {0.36, 0.20, 0.09, 0.0}},
    {"Flesh", {0.96, 0.80, 0.69, 0.0}},
    {"NewTan", {0.92, 0.78, 0.62, 0.0}},
    {"NewMidnightBlue", {0.00, 0.00, 0.61, 0.0}},
    {"VeryDarkBrown", {0.35, 0.16, 0.14, 0.0}},
    {"DarkBrown", {0.36, 0.25, 0.20, 0.0}},
    {"DarkTan", {0.59, 0.41, 0.31, 0.0}},
    {"GreenCopper", {0.32, 0.49, 0.46, 0.0}},
    {"DkGreenCopper", {0.29, 0.46, 0.43, 0.0}},
    {"DustyRose", {0.52, 0.39, 0.39, 0.0}},
    {"HuntersGreen", {0.13, 0.37, 0.31, 0.0}},
    {"Scarlet", {0.55, 0.09, 0.09, 0.0}},
    {"Med_Purple", {0.73, 0.16, 0.96, 0.0}},
    {"Light_Purple", {0.87, 0.58, 0.98, 0.0}},
    {"Very_Light_Purple", {0.94, 0.81, 0.99, 0.0}},
};

// clang-format off
constexpr std::string_view kStandardIncludes[] = {
    "arrays.inc", "chars.inc", "colors.inc", "consts.inc", "debug.inc", "finish.inc",
    "functions.inc", "glass.inc", "glass_old.inc", "golds.inc", "ior.inc", "logo.inc",
    "makegrass.inc", "math.inc", "meshmaker.inc", "metals.inc", "rad_def.inc", "rand.inc",
    "screen.inc", "shapes.inc", "shapes2.inc", "shapes3.inc", "shapes_old.inc", "shapesq.inc",
    "skies.inc", "stage1.inc", "stars.inc", "stdcam.inc", "stdinc.inc", "stoneold.inc",
    "stones.inc", "stones1.inc", "stones2.inc", "strings.inc", "sunpos.inc", "textures.inc",
    "transforms.inc", "woodmaps.inc", "woods.inc",
};
// clang-format on

}  // namespace

const PovNamedColour* findPovColour(std::string_view name) {
  for (const PovNamedColour& colour : kColours) {
    if (colour.name == name) return &colour;
  }
  return nullptr;
}

std::array<std::string_view, 130> povColourNames() {
  static_assert(std::size(kColours) == 130);
  std::array<std::string_view, 130> names;
  for (std::size_t i = 0; i < names.size(); ++i) names[i] = kColours[i].name;
  return names;
}

bool isPovStandardInclude(std::string_view name) {
  return std::find(std::begin(kStandardIncludes), std::end(kStandardIncludes), name) !=
         std::end(kStandardIncludes);
}

bool povIncludeDeclaresColours(std::string_view name) {
  return name == "colors.inc" || name == "stdinc.inc";
}

}  // namespace scene
