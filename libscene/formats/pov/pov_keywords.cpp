#include "libscene/formats/pov/pov_keywords.h"

#include <algorithm>
#include <iterator>

namespace scene {

namespace {

constexpr std::string_view kObjectKeywords[] = {
#define SCENEFILE_OBJECT_KIND(enumerator, record, pov) #pov,
#include "scenefile/object_kinds.def"
#undef SCENEFILE_OBJECT_KIND
};

// The shapes stand in the order a did-you-mean prefers on a tie (sphere
// before plane), not in object_kinds.def's; statesEveryObject holds them to
// that list.
// clang-format off
constexpr std::string_view kStatements[] = {
    "camera", "light_source", "sphere", "box", "cylinder", "plane", "object", "global_settings",
    "background",
};

constexpr std::string_view kUnsupportedStatements[] = {
    "union", "difference", "intersection", "merge", "mesh", "mesh2", "torus", "cone", "disc",
    "triangle", "smooth_triangle", "polygon", "prism", "lathe", "sor", "superellipsoid", "blob",
    "height_field", "isosurface", "julia_fractal", "text", "quadric", "cubic", "quartic", "poly",
    "polynomial", "parametric", "bicubic_patch", "sphere_sweep", "ovus", "lemon", "light_group",
    "sky_sphere", "fog", "rainbow", "media", "photons", "radiosity", "spline", "function", "array",
    "dictionary",
};

constexpr std::string_view kPatterns[] = {
    "agate", "aoi", "average", "boxed", "brick", "bozo", "bumps", "cells", "checker", "crackle",
    "cubic", "cylindrical", "density_file", "dents", "facets", "function", "gradient", "granite",
    "hexagon", "julia", "leopard", "magnet", "mandel", "marble", "object", "onion", "pavement",
    "pigment_pattern", "planar", "quilted", "radial", "ripples", "slope", "spherical", "spiral1",
    "spiral2", "spotted", "square", "tiling", "triangular", "waves", "wood", "wrinkles",
    "color_map", "colour_map", "pigment_map", "normal_map", "slope_map", "turbulence", "warp",
    "octaves", "omega", "lambda", "frequency", "phase", "tiles", "material_map", "texture_map",
    "uv_mapping", "interpolate",
};

constexpr std::string_view kFileTypes[] = {
    "gif", "tga", "iff", "ppm", "pgm", "png", "jpeg", "tiff", "sys", "exr", "hdr", "ttf", "df3",
};

constexpr std::string_view kDirectives[] = {
    "version", "include", "declare", "local", "default", "macro", "if",
    "ifdef",   "ifndef",  "while",   "for",   "switch",  "undef", "debug",
    "warning", "fopen",   "read",    "write", "end",
};
// clang-format on

template <std::size_t N>
constexpr bool contains(const std::string_view (&list)[N], std::string_view word) {
  return std::find(std::begin(list), std::end(list), word) != std::end(list);
}

constexpr bool statesEveryObject() {
  for (std::string_view keyword : kObjectKeywords) {
    if (!contains(kStatements, keyword)) return false;
  }
  return true;
}
static_assert(statesEveryObject(), "a POV-Ray object of object_kinds.def is no statement");

}  // namespace

std::string_view povObjectKeyword(ObjectKind kind) {
  return kObjectKeywords[static_cast<std::size_t>(kind)];
}

std::optional<ObjectKind> povObjectKind(std::string_view word) {
  for (ObjectKind kind : kObjectKinds) {
    if (povObjectKeyword(kind) == word) return kind;
  }
  return std::nullopt;
}

bool isPovStatement(std::string_view word) {
  return contains(kStatements, word);
}

std::span<const std::string_view> povStatements() {
  return kStatements;
}

bool isPovUnsupportedStatement(std::string_view word) {
  return contains(kUnsupportedStatements, word);
}

bool isPovPattern(std::string_view word) {
  return contains(kPatterns, word);
}

bool isPovFileType(std::string_view word) {
  return contains(kFileTypes, word);
}

bool isPovDirectiveName(std::string_view word) {
  return contains(kDirectives, word);
}

}  // namespace scene
