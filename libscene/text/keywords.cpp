// The keyword table of the two line formats: what docs/FORMATS.md says of
// each word, where the word may stand and what the validator accepts.
#include "scenefile/keywords.h"

#include <algorithm>

namespace scene {

namespace {

using P = KeywordPlace;
constexpr Format kSf = Format::SceneFile;
constexpr Format kIn = Format::InstructionFile;

constexpr std::string_view kColourRange = "each component 0 or more";
constexpr std::string_view kObjectColourRange =
    "each component 0 or more (above 1 draws a warning)";
constexpr std::string_view kUnitRange = "0 to 1";

constexpr KeywordInfo kKeywords[] = {
    // Scene files: the record names.
    {"CAMERA", kSf, P::Record, "",
     "The camera, the first record: a pinhole at the matrix's fourth column, looking along the "
     "opposite of its third column, with its second column up; its colour is ignored.",
     ""},
    {"LIGHT", kSf, P::Record, "",
     "A point light at the matrix's fourth column (the rest of the matrix is ignored); the colour "
     "line is its intensity per channel.",
     ""},
    {"PLANE", kSf, P::Record, "",
     "The infinite plane y = 0, seen from both sides, placed by the matrix.", ""},
    {"SPHERE", kSf, P::Record, "", "A sphere of radius 1 around the origin, placed by the matrix.",
     ""},
    {"CYLINDER", kSf, P::Record, "",
     "A solid cylinder of radius 1 around the y axis from y = -1 to 1, with flat caps, placed by "
     "the matrix.",
     ""},
    {"CUBE", kSf, P::Record, "", "The box [-1, 1] on each axis, placed by the matrix.", ""},

    // Instruction files: the top level and the blocks.
    {"OUTPUT_FILE", kIn, P::TopLevel, "name",
     "The image to render to, relative to this file's folder; the first line, once.",
     "one name without spaces"},
    {"START", kIn, P::TopLevel, "CAMERA | LIGHT | OBJECT kind", "Opens a block.", ""},
    {"CAMERA", kIn, P::BlockName, "",
     "The camera, exactly one: LOCATION and LOOK_AT, with world +y up.", ""},
    {"LIGHT", kIn, P::BlockName, "", "A point light: LOCATION and COLOUR.", ""},
    {"OBJECT", kIn, P::BlockName, "kind",
     "An object of a kind, with an optional MATERIAL and an optional TRANSFORMATION section.", ""},
    {"PLANE", kIn, P::ObjectKindName, "", "The infinite plane y = 0, seen from both sides.", ""},
    {"SPHERE", kIn, P::ObjectKindName, "", "A sphere of radius 1 around the origin.", ""},
    {"CYLINDER", kIn, P::ObjectKindName, "",
     "A solid cylinder of radius 1 around the y axis from y = -1 to 1, with flat caps.", ""},
    {"CUBE", kIn, P::ObjectKindName, "", "The box [-1, 1] on each axis.", ""},

    {"LOCATION", kIn, P::Camera, "x y z", "The eye's position.", ""},
    {"LOOK_AT", kIn, P::Camera, "x y z", "The point the camera looks at.", "not the LOCATION"},
    {"END", kIn, P::Camera, "CAMERA", "Closes the CAMERA block.", ""},

    {"LOCATION", kIn, P::Light, "x y z", "The light's position.", ""},
    {"COLOUR", kIn, P::Light, "r g b", "The light's intensity per channel; it may exceed 1.",
     kColourRange},
    {"END", kIn, P::Light, "LIGHT", "Closes the LIGHT block.", ""},

    {"START", kIn, P::Object, "MATERIAL | TRANSFORMATION", "Opens a section of the object.", ""},
    {"END", kIn, P::Object, "OBJECT", "Closes the OBJECT block.", ""},
    {"MATERIAL", kIn, P::SectionName, "",
     "The object's Phong material, at most once; a value not given takes its default.", ""},
    {"TRANSFORMATION", kIn, P::SectionName, "",
     "The operations that place the object, at most once, applied in the order written.", ""},

    {"COLOUR", kIn, P::Material, "r g b", "The surface colour; default 1 1 1.", kObjectColourRange},
    {"AMBIENT", kIn, P::Material, "a", "The share of ambient light reflected; default 0.1.",
     kUnitRange},
    {"DIFFUSE", kIn, P::Material, "d", "The share of light reflected diffusely; default 0.9.",
     kUnitRange},
    {"SPECULAR", kIn, P::Material, "s", "The strength of the specular highlight; default 0.9.",
     kUnitRange},
    {"SHININESS", kIn, P::Material, "h",
     "The Phong exponent: the larger, the smaller the highlight; default 200.", "above 0"},
    {"REFLECTIVITY", kIn, P::Material, "r", "The share of light mirrored; default 0.", kUnitRange},
    {"TRANSPARENCY", kIn, P::Material, "t", "The share of light let through; default 0.",
     kUnitRange},
    {"RI", kIn, P::Material, "n", "The refractive index; default 1.",
     "above 0 (below 1 draws a warning)"},
    {"END", kIn, P::Material, "MATERIAL", "Closes the MATERIAL section.", ""},

    {"SCALE", kIn, P::Transformation, "x y z", "Scales along the axes; a negative factor mirrors.",
     "any factor but 0"},
    {"TRANSLATE", kIn, P::Transformation, "x y z", "Moves by the vector.", ""},
    {"ROTATE_X", kIn, P::Transformation, "radians",
     "Turns about the x axis, counter-clockwise seen from +x.", ""},
    {"ROTATE_Y", kIn, P::Transformation, "radians",
     "Turns about the y axis, counter-clockwise seen from +y.", ""},
    {"ROTATE_Z", kIn, P::Transformation, "radians",
     "Turns about the z axis, counter-clockwise seen from +z.", ""},
    {"END", kIn, P::Transformation, "TRANSFORMATION", "Closes the TRANSFORMATION section.", ""},
};

// A record's matrix, entry by entry: rows 1 to 3, then the last row.
using MatrixWords = std::string_view[4][4];

constexpr MatrixWords kObjectMatrix = {
    {"the world x of the local x axis (rotation, scale, shear)",
     "the world x of the local y axis (rotation, scale, shear)",
     "the world x of the local z axis (rotation, scale, shear)", "translation along x"},
    {"the world y of the local x axis (rotation, scale, shear)",
     "the world y of the local y axis (rotation, scale, shear)",
     "the world y of the local z axis (rotation, scale, shear)", "translation along y"},
    {"the world z of the local x axis (rotation, scale, shear)",
     "the world z of the local y axis (rotation, scale, shear)",
     "the world z of the local z axis (rotation, scale, shear)", "translation along z"},
    {"must be 0", "must be 0", "must be 0", "must be 1"},
};

constexpr MatrixWords kCameraMatrix = {
    {"the right axis's x", "the up axis's x",
     "the backward axis's x (the camera looks the opposite way)", "the eye's x"},
    {"the right axis's y", "the up axis's y",
     "the backward axis's y (the camera looks the opposite way)", "the eye's y"},
    {"the right axis's z", "the up axis's z",
     "the backward axis's z (the camera looks the opposite way)", "the eye's z"},
    {"must be 0", "must be 0", "must be 0", "must be 1"},
};

constexpr MatrixWords kLightMatrix = {
    {"ignored", "ignored", "ignored", "the light's x"},
    {"ignored", "ignored", "ignored", "the light's y"},
    {"ignored", "ignored", "ignored", "the light's z"},
    {"must be 0", "must be 0", "must be 0", "must be 1"},
};

}  // namespace

std::span<const KeywordInfo> keywords() {
  return kKeywords;
}

std::vector<const KeywordInfo*> keywordsAt(Format format, KeywordPlace place) {
  std::vector<const KeywordInfo*> out;
  for (const KeywordInfo& k : kKeywords) {
    if (k.format == format && k.place == place) out.push_back(&k);
  }
  return out;
}

const KeywordInfo* findKeyword(std::string_view word, Format format, KeywordPlace place) {
  auto found = std::find_if(std::begin(kKeywords), std::end(kKeywords), [&](const KeywordInfo& k) {
    return k.word == word && k.format == format && k.place == place;
  });
  return found == std::end(kKeywords) ? nullptr : found;
}

std::string_view matrixEntryMeaning(OutlineKind kind, std::uint32_t row, std::uint32_t column) {
  if (row < 1 || row > 4 || column < 1 || column > 4) return {};
  switch (kind) {
    case OutlineKind::Camera:
      return kCameraMatrix[row - 1][column - 1];
    case OutlineKind::Light:
      return kLightMatrix[row - 1][column - 1];
    case OutlineKind::Object:
      return kObjectMatrix[row - 1][column - 1];
    default:
      return {};
  }
}

}  // namespace scene
