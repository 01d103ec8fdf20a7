#include "libscene/formats/pov/pov_writer.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <limits>
#include <numbers>
#include <string_view>

#include "libscene/formats/pov/pov_keywords.h"
#include "libscene/text/number.h"
#include "scenefile/matrix.h"
#include "scenefile/transform.h"

namespace scene {

namespace {

// The words of the header every file starts with: which render the file
// reproduces and how to run POV-Ray for it. They are the file format's, kept
// as the files already written carry them, tool names and flags included, so
// that conversions stay byte for byte what they were.
constexpr std::string_view kHeaderWrittenBy = "// Written by sfconvert: the picture of sfrender ";
constexpr std::string_view kHeaderFov = "--fov ";
constexpr std::string_view kHeaderWidth = " --width ";
constexpr std::string_view kHeaderHeight = " --height ";
constexpr std::string_view kHeaderRenderIt =
    ".\n// Render it at POV-Ray's default settings:\n//   povray +W";

// The flat colours: object n + 1 (0 is the black of nothing hit) multiplied
// by an odd constant modulo a power of two, a bijection that scatters
// neighbours, then split into three channels.
constexpr std::uint32_t kSmallModulus = 1u << 12;  // 16 levels a channel
constexpr std::uint32_t kLargeModulus = 1u << 24;  // 256 levels a channel
constexpr std::uint32_t kSmallMultiplier = 1597;
constexpr std::uint32_t kLargeMultiplier = 0x3779B1;

bool smallPalette(std::size_t count) {
  return count < kSmallModulus;
}

// The inverse of an odd number modulo 2^32, by Newton's iteration.
std::uint32_t inverseOdd(std::uint32_t a) {
  std::uint32_t x = a;
  for (int i = 0; i < 5; ++i) x *= 2u - a * x;
  return x;
}

void appendVector(std::string& out, const glm::dvec3& v) {
  out += '<';
  for (int i = 0; i < 3; ++i) {
    if (i) out += ", ";
    appendNumber(out, v[i]);
  }
  out += '>';
}

void appendNumbers(std::string& out, const glm::dvec3& v) {
  for (int i = 0; i < 3; ++i) {
    out += ' ';
    appendNumber(out, v[i]);
  }
}

// Row by row, as a scene file writes it.
void appendMatrixNumbers(std::string& out, const glm::dmat4& m) {
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      out += ' ';
      appendNumber(out, m[c][r]);
    }
  }
}

// POV-Ray's matrix multiplies row vectors (p' = p * M), so its twelve
// numbers are our column-vector matrix column by column: the 3x3 block's
// columns, then the translation.
void appendPovMatrix(std::string& out, const glm::dmat4& m) {
  out += "matrix <";
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 3; ++r) {
      if (c || r) out += ", ";
      appendNumber(out, m[c][r]);
    }
  }
  out += '>';
}

bool onlyTranslation(const glm::dmat4& m) {
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (m[c][r] != (c == r ? 1.0 : 0.0) || std::signbit(m[c][r])) return false;
    }
  }
  return m[3][3] == 1.0;
}

// Whether the eye lies on the local -y side of a PLANE. POV-Ray's plane is
// a solid half-space, and a camera inside many solids makes it complain;
// of the two half-spaces whose surface is our plane, take the one that
// leaves the eye out.
bool eyeBelowPlane(const glm::dmat4& plane, const glm::dvec3& eye) {
  glm::dmat3 a(plane);
  glm::dvec3 offset = eye - glm::dvec3(plane[3]);
  // Only the sign counts: halved, the difference of two finite points is
  // finite, and a unit-sized offset keeps the product from overflowing.
  if (!std::isfinite(offset.x) || !std::isfinite(offset.y) || !std::isfinite(offset.z)) {
    offset = 0.5 * eye - 0.5 * glm::dvec3(plane[3]);
  }
  glm::dvec3 local = glm::inverse(a) * unitDirection(offset);
  return local.y < 0.0;
}

std::string objectName(const Object& object, std::size_t index) {
  return std::string(objectKindName(object.kind)) + " object " + std::to_string(index + 1);
}

void reportLosses(const Object& object, std::size_t index, Severity severity, DiagnosticList& out) {
  const Material& m = object.material;
  if (m.transparency > 0.0) {
    out.report(severity, DiagnosticCode::LossPov, object.span,
               "TRANSPARENCY " + formatNumber(m.transparency) + " of " + objectName(object, index) +
                   " is written as POV-Ray's transmit, which renders differently")
        .hint =
        "POV-Ray dims the surface by the transmitted part and lets light through to "
        "shadows; the renderer adds the refracted light to the whole surface, and every object "
        "casts a full shadow";
    if (object.kind == ObjectKind::Plane) {
      out.report(severity, DiagnosticCode::LossPov, object.span,
                 "the transparent " + objectName(object, index) +
                     " is a sheet in the renderer but a solid half-space in POV-Ray")
          .hint = "POV-Ray refracts into the half-space; the renderer passes light through unbent";
    }
    if (m.reflectivity > 0.0) {
      out.report(severity, DiagnosticCode::LossPov, object.span,
                 objectName(object, index) +
                     " both reflects and refracts: the renderer weighs the two by Schlick's "
                     "Fresnel term, POV-Ray adds them as given");
    }
  }
}

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The render settings a file is written for: the options' where they say,
// else the scene's View, else the renderer's defaults (60 degrees, 640 x 480).
struct PovSettings {
  double verticalFovDegrees = 60.0;
  int width = 640;
  int height = 480;
  int maxDepth = 5;
  bool flat = false;
  bool noLoss = false;
};

PovSettings povSettings(const Scene& scene, const ConversionOptions& conversion) {
  const PovWriteOptions& options = conversion.pov;
  PovSettings settings;
  if (scene.view) settings.verticalFovDegrees = scene.view->verticalFovDegrees;
  if (options.verticalFovDegrees) settings.verticalFovDegrees = *options.verticalFovDegrees;
  if (options.width > 0 && options.height > 0) {
    settings.width = options.width;
    settings.height = options.height;
  } else if (scene.view && scene.view->aspectRatio) {
    // 480 rows, as the renderer's default, at the file's aspect ratio.
    double width = std::round(settings.height * *scene.view->aspectRatio);
    settings.width = static_cast<int>(std::clamp(width, 1.0, 32768.0));
  }
  settings.maxDepth = options.maxDepth;
  settings.flat = options.flat;
  settings.noLoss = conversion.noLoss;
  return settings;
}

// False, with an error, when the vectors the view gives are not finite (a
// field of view that no finite image plane has).
bool appendCamera(std::string& out, const Scene& scene, const PovSettings& options,
                  DiagnosticList& diagnostics) {
  const Camera& camera = scene.camera;
  out += std::string(kPovExactComment) + " camera matrix";
  appendMatrixNumbers(out, camera.matrix);
  out += " colour";
  appendNumbers(out, camera.colour);
  if (camera.lookAt) {
    out += " look_at";
    appendNumbers(out, *camera.lookAt);
  }
  // The settings the vectors below were made for, so that the reader can
  // report them exactly rather than as recomputed from rounded vectors.
  out += " fov ";
  appendNumber(out, options.verticalFovDegrees);
  out += " width " + std::to_string(options.width) + " height " + std::to_string(options.height);
  out += '\n';
  // The renderer's pinhole camera: forward and up orthonormalised,
  // right = forward x up. POV-Ray's ray through image point (u, v) in
  // [-1/2, 1/2]^2 is direction + u * right + v * up, so right and up are the
  // image plane's width and height at distance 1. Given as vectors without
  // look_at or angle, POV-Ray uses them as they are: no handedness rule
  // applies, and the picture is the renderer's, not its mirror image.
  glm::dvec3 eye(camera.matrix[3]);
  // Axes of length 1e-300 or 1e300 are valid: unitDirection scales them.
  glm::dvec3 forward = unitDirection(-glm::dvec3(camera.matrix[2]));
  glm::dvec3 up(camera.matrix[1]);
  if (!isModerate(up)) up = unitDirection(up);
  up = unitDirection(up - glm::dot(up, forward) * forward);
  glm::dvec3 right = glm::cross(forward, up);
  double height = 2.0 * std::tan(options.verticalFovDegrees * std::numbers::pi / 360.0);
  double width = height * options.width / options.height;
  if (!finite(forward) || !finite(right * width) || !finite(up * height) || !(height > 0.0) ||
      !(width > 0.0)) {
    diagnostics
        .error(DiagnosticCode::ValueNotFinite, camera.span,
               "the camera's image plane for a field of view of " +
                   formatNumber(options.verticalFovDegrees) + " degrees at " +
                   std::to_string(options.width) + "x" + std::to_string(options.height) +
                   " is not finite")
        .hint = "give a field of view between 0 and 180 degrees";
    return false;
  }
  out += "camera {\n  perspective\n  location ";
  appendVector(out, eye);
  out += "\n  direction ";
  appendVector(out, forward);
  out += "\n  right ";
  appendVector(out, right * width);
  out += "\n  up ";
  appendVector(out, up * height);
  out += "\n}\n";
  return true;
}

void appendMaterial(std::string& out, const Material& m) {
  out += "  pigment { ";
  // rgbt also for -0, which renders as rgb but reads back with its sign.
  if (m.transparency > 0.0 || std::signbit(m.transparency)) {
    out += "rgbt <";
    for (int i = 0; i < 3; ++i) {
      appendNumber(out, m.colour[i]);
      out += ", ";
    }
    appendNumber(out, m.transparency);
    out += '>';
  } else {
    out += "rgb ";
    appendVector(out, m.colour);
  }
  out += " }\n  finish { ambient ";
  appendNumber(out, m.ambient);
  out += " diffuse ";
  appendNumber(out, m.diffuse);
  out += " phong ";
  appendNumber(out, m.specular);
  out += " phong_size ";
  appendNumber(out, m.shininess);
  out += " reflection ";
  appendNumber(out, m.reflectivity);
  out += " }\n";
  if (m.ri != 1.0) {
    out += "  interior { ior ";
    appendNumber(out, m.ri);
    out += " }\n";
  }
}

// The object comment: what POV-Ray's 12 numbers cannot hold (the sign of
// a zero in the fourth row) and an instruction file's operations.
void appendObjectComment(std::string& out, const Object& object) {
  const glm::dmat4& m = object.matrix;
  bool plainLastRow = !std::signbit(m[0][3]) && !std::signbit(m[1][3]) && !std::signbit(m[2][3]);
  if (plainLastRow && !object.transforms) return;
  out += std::string(kPovExactComment) + " object";
  if (!plainLastRow) {
    out += " last_row";
    for (int c = 0; c < 4; ++c) {
      out += ' ';
      appendNumber(out, m[c][3]);
    }
  }
  if (object.transforms) out += " transforms";
  for (const TransformOp& op :
       object.transforms ? *object.transforms : std::vector<TransformOp>{}) {
    out += ' ';
    out += transformKindName(op.kind);
    bool rotation = op.kind != TransformKind::Scale && op.kind != TransformKind::Translate;
    for (int i = 0; i < (rotation ? 1 : 3); ++i) {
      out += ' ';
      appendNumber(out, op.value[i]);
    }
  }
  out += '\n';
}

void appendObject(std::string& out, const Object& object, std::size_t index, const Scene& scene,
                  const PovSettings& options) {
  if (!options.flat) appendObjectComment(out, object);
  out += povObjectKeyword(object.kind);
  out += " { ";
  switch (object.kind) {
    case ObjectKind::Sphere:
      out += "0, 1\n";
      break;
    case ObjectKind::Cube:
      out += "-1, 1\n";
      break;
    case ObjectKind::Cylinder:
      // Closed by its caps unless `open`: a solid, like ours.
      out += "<0, -1, 0>, <0, 1, 0>, 1\n";
      break;
    case ObjectKind::Plane:
      out +=
          eyeBelowPlane(object.matrix, glm::dvec3(scene.camera.matrix[3])) ? "-y, 0\n" : "y, 0\n";
      break;
  }
  out += "  ";
  appendPovMatrix(out, object.matrix);
  out += '\n';
  if (options.flat) {
    std::array<int, 3> rgb = povFlatColour(index, scene.objects.size());
    out += "  pigment { rgb ";
    appendVector(out, glm::dvec3(rgb[0], rgb[1], rgb[2]) / 255.0);
    out += " }\n  finish { ambient 1 diffuse 0 phong 0 specular 0 reflection 0 }\n";
  } else {
    appendMaterial(out, object.material);
  }
  out += "}\n";
}

}  // namespace

std::optional<std::string> writePovScene(const Scene& scene, const ConversionOptions& conversion,
                                         DiagnosticList& out) {
  const PovSettings options = povSettings(scene, conversion);
  std::size_t errorsBefore = out.errorCount();
  if (!options.flat) {
    Severity severity = options.noLoss ? Severity::Error : Severity::Warning;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
      reportLosses(scene.objects[i], i, severity, out);
    }
  }
  if (out.errorCount() != errorsBefore) return std::nullopt;

  std::string text;
  text.reserve(512 + 256 * (scene.lights.size() + scene.objects.size()));
  text += kHeaderWrittenBy;
  text += kHeaderFov;
  text += formatNumber(options.verticalFovDegrees);
  text += kHeaderWidth;
  text += std::to_string(options.width);
  text += kHeaderHeight;
  text += std::to_string(options.height);
  if (options.flat) text += ",\n// flat: each object unlit in a colour of its own";
  text += kHeaderRenderIt;
  text +=
      std::to_string(options.width) + " +H" + std::to_string(options.height) + " -A +Iscene.pov\n";
  text += "// The '" + std::string(kPovExactComment) +
          "' comments carry exact values for reading back.\n";
  text += "#version 3.7;\n";
  // Our ambient term is AMBIENT times each light's colour, POV-Ray's is
  // ambient times ambient_light once: the sum of the lights makes them equal.
  glm::dvec3 ambientLight(options.flat ? 1.0 : 0.0);
  SourceSpan overflowAt;
  if (!options.flat) {
    for (const Light& light : scene.lights) {
      ambientLight += light.colour;
      if (!finite(ambientLight) && !overflowAt.known()) overflowAt = light.span;
    }
  }
  if (!finite(ambientLight)) {
    // Lights near the largest double sum beyond it; the reader does not read
    // ambient_light back, so only the picture changes.
    constexpr double kLargest = std::numeric_limits<double>::max();
    ambientLight = glm::min(ambientLight, glm::dvec3(kLargest));
    out.report(options.noLoss ? Severity::Error : Severity::Warning, DiagnosticCode::LossPov,
               overflowAt,
               "the lights' colours sum beyond the largest double: POV-Ray's ambient_light is "
               "clamped to " +
                   formatNumber(kLargest))
        .hint = "objects with AMBIENT above 0 render darker in POV-Ray than in the renderer";
    if (options.noLoss) return std::nullopt;
  }
  // POV-Ray computes in its working gamma and encodes the output from it to
  // File_Gamma, sRGB by default: a working gamma of sRGB makes that encoding
  // the identity, so POV-Ray's levels are linear, as the renderer's, without a
  // File_Gamma setting. Colour literals are not converted either way.
  text += "global_settings { assumed_gamma srgb max_trace_level " +
          std::to_string(options.maxDepth + 1) + " adc_bailout 0 ambient_light rgb ";
  appendVector(text, ambientLight);
  text += " }\nbackground { rgb 0 }\n";
  if (scene.outputFile)
    text += std::string(kPovExactComment) + " output_file " + *scene.outputFile + "\n";
  if (!appendCamera(text, scene, options, out)) return std::nullopt;
  if (!options.flat) {
    for (const Light& light : scene.lights) {
      if (!onlyTranslation(light.matrix)) {
        text += std::string(kPovExactComment) + " light matrix";
        appendMatrixNumbers(text, light.matrix);
        text += '\n';
      }
      text += "light_source { ";
      appendVector(text, light.position());
      text += " color rgb ";
      appendVector(text, light.colour);
      text += " }\n";
    }
  }
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    appendObject(text, scene.objects[i], i, scene, options);
  }
  return text;
}

std::array<int, 3> povFlatColour(std::size_t index, std::size_t count) {
  std::uint32_t n = static_cast<std::uint32_t>(index + 1);
  if (smallPalette(count)) {
    std::uint32_t p = (n * kSmallMultiplier) % kSmallModulus;
    return {static_cast<int>((p >> 8) & 15) * 17, static_cast<int>((p >> 4) & 15) * 17,
            static_cast<int>(p & 15) * 17};
  }
  std::uint32_t p = (n * kLargeMultiplier) % kLargeModulus;
  return {static_cast<int>((p >> 16) & 255), static_cast<int>((p >> 8) & 255),
          static_cast<int>(p & 255)};
}

std::optional<long long> povFlatObject(const std::array<int, 3>& rgb, std::size_t count) {
  std::uint32_t p = 0;
  if (smallPalette(count)) {
    for (int level : rgb) {
      int digit = (level + 8) / 17;
      if (level < 0 || level > 255 || std::abs(level - 17 * digit) > 4) return std::nullopt;
      p = p * 16 + static_cast<std::uint32_t>(digit);
    }
    p = (p * inverseOdd(kSmallMultiplier)) % kSmallModulus;
  } else {
    for (int level : rgb) {
      if (level < 0 || level > 255) return std::nullopt;
      p = p * 256 + static_cast<std::uint32_t>(level);
    }
    p = (p * inverseOdd(kLargeMultiplier)) % kLargeModulus;
  }
  if (p == 0) return -1;
  if (p - 1 >= count) return std::nullopt;
  return static_cast<long long>(p) - 1;
}

}  // namespace scene
