#include "libscene/formats/pov/pov_scene_builder.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "libscene/formats/pov/pov_comment_words.h"
#include "libscene/formats/pov/pov_reports.h"
#include "libscene/formats/pov/pov_value.h"
#include "libscene/text/number.h"
#include "scenefile/matrix.h"
#include "scenefile/transform.h"
#include "scenefile/validation.h"

namespace scene {

namespace {

// Every matrix of a left-handed scene is conjugated by z -> -z: F M F.
glm::dmat4 mirrorZ(glm::dmat4 m) {
  for (int c = 0; c < 4; ++c) m[c][2] = -m[c][2];
  m[2] = -m[2];
  return m;
}

glm::dvec3 mirrorZ(glm::dvec3 v) {
  return {v.x, v.y, -v.z};
}

// Equal and of the same sign, so that an exact comment's -0 is not +0.
bool sameBits(double a, double b) {
  return a == b && std::signbit(a) == std::signbit(b);
}

bool sameBits(const glm::dmat4& a, const glm::dmat4& b) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!sameBits(a[c][r], b[c][r])) return false;
    }
  }
  return true;
}

class PovSceneBuilder : PovReports {
 public:
  PovSceneBuilder(const PovSceneParts& parts, const PovMaterialPatch& defaults,
                  const std::vector<PovLexer::ExactComment>& comments, const ReadOptions& options,
                  PovImport& result)
      : PovReports(options, result.read.diagnostics),
        parts_(parts),
        defaults_(defaults),
        comments_(comments),
        result_(result) {}

  void build();

 private:
  std::optional<std::string_view> comment(int index) const;
  void finishCamera(const PovCameraState& c, SourceSpan span);
  void exactCamera(Camera& camera, const glm::dvec3& forward, const glm::dvec3& up, int index);
  void exactLight(Light& light, int index);
  void exactObject(Object& object, int index);
  // `number` counts the file's objects from 1, as the losses name them.
  Material material(const PovPendingObject& pending, const Object& object, std::size_t number);
  void reportView(SourceSpan span);

  const PovSceneParts& parts_;
  const PovMaterialPatch& defaults_;
  const std::vector<PovLexer::ExactComment>& comments_;
  PovImport& result_;
  std::optional<std::pair<int, int>> viewSize_;  // from the exact comment
};

// The text of exact comment `index` (a token's exactComment), if any.
std::optional<std::string_view> PovSceneBuilder::comment(int index) const {
  if (index < 0) return std::nullopt;
  return comments_[static_cast<std::size_t>(index)].text;
}

void PovSceneBuilder::build() {
  Scene& scene = result_.read.scene;
  // A camera whose right vector turns the other way than up x direction
  // (POV-Ray's default) sees a left-handed world: mirror it.
  PovCameraState c = parts_.camera;
  bool mirrored = glm::dot(glm::cross(c.up, c.direction), c.right) > 0.0;
  result_.view.mirrored = mirrored;
  if (mirrored) {
    c.location = mirrorZ(c.location);
    c.direction = mirrorZ(c.direction);
    c.up = mirrorZ(c.up);
    c.right = mirrorZ(c.right);
  }
  SourceSpan cameraSpan = parts_.cameraSpan.known() ? parts_.cameraSpan : SourceSpan{1, 1, 0};
  finishCamera(c, cameraSpan);
  for (const PovPendingLight& pending : parts_.lights) {
    Light light;
    light.matrix = mirrored ? mirrorZ(pending.matrix) : pending.matrix;
    light.colour = pending.colour;
    light.span = pending.span;
    exactLight(light, pending.exactComment);
    RecordSpans spans = RecordSpans::uniform(light.span);
    std::size_t before = out_.errorCount();
    checkColour(light.colour, RecordRole::Light, spans, out_);
    if (out_.errorCount() == before) scene.lights.push_back(light);
  }
  std::size_t number = 0;
  for (const PovPendingObject& pending : parts_.objects) {
    ++number;
    Object object;
    object.kind = pending.kind;
    object.matrix = mirrored ? mirrorZ(pending.transform.m) : pending.transform.m;
    object.span = pending.span;
    std::size_t before = out_.errorCount();
    object.material = material(pending, object, number);
    checkObjectMatrix(object.matrix, objectKindName(object.kind), object.span, out_);
    exactObject(object, pending.exactComment);
    if (out_.errorCount() == before) {
      scene.objects.push_back(std::move(object));
      result_.objectEnds.push_back(pending.end);
    }
  }
  for (const auto& exact : comments_) {
    PovCommentWords words(exact.text);
    if (words.word("output_file")) {
      if (auto name = words.any(); name && words.done()) {
        // Only a name an instruction file holds, which it came from.
        DiagnosticList refused;
        checkOutputFileName(std::string(*name), exact.span, refused);
        if (refused.hasErrors()) {
          ignored(exact.span,
                  "the exact-value comment's output_file is no name an instruction file holds, "
                  "and is ignored");
          continue;
        }
        scene.outputFile = std::string(*name);
        scene.outputFileSpan = exact.span;
      }
    }
  }
  reportView(cameraSpan);
  if (!out_.hasErrors()) checkSceneLevel(scene, out_);
}

void PovSceneBuilder::finishCamera(const PovCameraState& c, SourceSpan span) {
  Camera& camera = result_.read.scene.camera;
  camera.span = span;
  double directionLength = glm::length(c.direction);
  if (!(directionLength > 0.0) || !std::isfinite(directionLength)) {
    out_.error(DiagnosticCode::CameraDegenerate, span,
               std::isfinite(directionLength)
                   ? "the camera's direction has zero length"
                   : "the camera's direction is too long for a double (its length overflows)");
    return;
  }
  glm::dvec3 forward = c.direction / directionLength;
  glm::dvec3 upPart = c.up - glm::dot(c.up, forward) * forward;
  double upLength = glm::length(upPart);
  if (!(upLength > kParallelTolerance * glm::length(c.up))) {
    out_.error(DiagnosticCode::CameraDegenerate, span,
               "the camera's up vector is zero or parallel to its direction");
    return;
  }
  glm::dvec3 up = upPart / upLength;
  glm::dvec3 right = glm::cross(forward, up);
  double rightLength = glm::dot(c.right, right);
  // The renderer's image plane is square to forward, with right = forward x up.
  double skew = glm::length(c.right - rightLength * right) / glm::length(c.right);
  double tilt = std::abs(glm::dot(c.up, forward)) / glm::length(c.up);
  if (skew > 1e-9 || tilt > 1e-9) {
    loss(span,
         "the camera's direction, up and right are not at right angles: the picture "
         "is sheared in POV-Ray, not in the renderer",
         "the renderer uses direction, and up made square to it");
  }
  camera.matrix = glm::dmat4(1.0);
  camera.matrix[0] = glm::dvec4(right, 0.0);
  camera.matrix[1] = glm::dvec4(up, 0.0);
  camera.matrix[2] = glm::dvec4(-forward, 0.0);
  camera.matrix[3] = glm::dvec4(c.location, 1.0);
  double height = upLength / directionLength;
  result_.view.verticalFovDegrees = 2.0 * std::atan(0.5 * height) / kPovDegree;
  result_.view.aspectRatio = std::abs(rightLength) / upLength;
  exactCamera(camera, forward, up, parts_.cameraComment);
  checkCameraMatrix(camera.matrix, span, out_);
}

// The exact camera of a file the POV-Ray writer wrote, when the comment still
// describes the camera that POV-Ray's statement gives.
void PovSceneBuilder::exactCamera(Camera& camera, const glm::dvec3& forward, const glm::dvec3& up,
                                  int index) {
  std::optional<std::string_view> text = comment(index);
  if (!text) return;
  PovCommentWords words(*text);
  glm::dmat4 m(1.0);
  glm::dvec3 colour(0.0);
  glm::dvec3 lookAt(0.0);
  bool hasLookAt = false;
  bool ok = words.word("camera") && words.word("matrix") && words.matrix(m) &&
            words.word("colour") && words.vector(colour);
  if (ok && words.word("look_at")) hasLookAt = words.vector(lookAt);
  double fov = 0.0, width = 0.0, height = 0.0;
  bool hasView = ok && words.word("fov") && words.number(fov) && words.word("width") &&
                 words.number(width) && words.word("height") && words.number(height);
  ok = ok && words.done();
  if (ok) {
    // Scaled normalisation: axes of length 1e-300 or 1e300 are valid.
    glm::dvec3 f = scaledNormalize(-glm::dvec3(m[2]));
    glm::dvec3 u = scaledNormalize(glm::dvec3(m[1]));
    u = scaledNormalize(u - glm::dot(u, f) * f);
    ok = sameBits(m[3][0], camera.matrix[3][0]) && sameBits(m[3][1], camera.matrix[3][1]) &&
         sameBits(m[3][2], camera.matrix[3][2]) && glm::length(f - forward) < 1e-12 &&
         glm::length(u - up) < 1e-9;
  }
  if (!ok) {
    ignored(camera.span,
            "the exact-value comment before the camera does not describe it: the "
            "camera is read from the statement");
    return;
  }
  camera.matrix = m;
  camera.colour = colour;
  if (hasLookAt) camera.lookAt = lookAt;
  // The view the writer made the vectors for, when they still show it.
  PovCameraView& view = result_.view;
  if (hasView && width >= 1 && height >= 1 &&
      std::abs(fov - view.verticalFovDegrees) <= 1e-9 * fov &&
      std::abs(width / height - view.aspectRatio) <= 1e-9 * view.aspectRatio) {
    view.verticalFovDegrees = fov;
    view.aspectRatio = width / height;
    viewSize_ = {static_cast<int>(width), static_cast<int>(height)};
  }
}

void PovSceneBuilder::exactLight(Light& light, int index) {
  std::optional<std::string_view> text = comment(index);
  if (!text) return;
  PovCommentWords words(*text);
  glm::dmat4 m(1.0);
  bool ok = words.word("light") && words.word("matrix") && words.matrix(m) && words.done() &&
            sameBits(m[3][0], light.matrix[3][0]) && sameBits(m[3][1], light.matrix[3][1]) &&
            sameBits(m[3][2], light.matrix[3][2]) && sameBits(m[3][3], 1.0);
  if (!ok) {
    ignored(light.span,
            "the exact-value comment before the light does not describe it: the "
            "light is read from the statement");
    return;
  }
  light.matrix = m;
}

void PovSceneBuilder::exactObject(Object& object, int index) {
  std::optional<std::string_view> text = comment(index);
  if (!text) return;
  PovCommentWords words(*text);
  std::vector<TransformOp> ops;
  bool ok = words.word("object");
  glm::dmat4 matrix = object.matrix;
  if (ok && words.word("last_row")) {
    // Only the signs of its zeros: the row is 0 0 0 1 in value.
    for (int c = 0; c < 4 && ok; ++c) {
      double v = 0.0;
      ok = words.number(v) && v == matrix[c][3];
      matrix[c][3] = v;
    }
  }
  bool hasTransforms = ok && words.word("transforms");
  while (ok && hasTransforms && !words.done()) {
    std::optional<std::string_view> name = words.any();
    TransformOp op;
    op.span = object.span;
    if (name == "SCALE" || name == "TRANSLATE") {
      op.kind = name == "SCALE" ? TransformKind::Scale : TransformKind::Translate;
      ok = words.vector(op.value);
    } else if (name == "ROTATE_X" || name == "ROTATE_Y" || name == "ROTATE_Z") {
      op.kind = name == "ROTATE_X"   ? TransformKind::RotateX
                : name == "ROTATE_Y" ? TransformKind::RotateY
                                     : TransformKind::RotateZ;
      ok = words.number(op.value.x);
    } else {
      ok = false;
    }
    ops.push_back(op);
  }
  ok = ok && words.done() && (!hasTransforms || sameBits(composeTransform(ops), matrix));
  if (!ok) {
    ignored(object.span,
            "the exact-value comment before the object does not describe it: the "
            "object is read from the statement");
    return;
  }
  object.matrix = matrix;
  if (hasTransforms) object.transforms = std::move(ops);
}

// The object's material from POV-Ray's texture, each value that the
// model cannot hold reported.
Material PovSceneBuilder::material(const PovPendingObject& pending, const Object& object,
                                   std::size_t number) {
  PovMaterialPatch p = defaults_;
  p.merge(pending.patch);
  Material m;
  m.colour = *p.colour;
  if (p.pattern) {
    loss(p.pattern->span,
         "the " + p.pattern->pattern + " pigment of " + std::string(objectKindName(object.kind)) +
             " object " + std::to_string(number) + " is approximated by its mean colour " +
             formatNumber(m.colour.r) + " " + formatNumber(m.colour.g) + " " +
             formatNumber(m.colour.b),
         "the scene model holds one colour an object");
  }
  RecordSpans spans = RecordSpans::uniform(object.span);
  checkColour(m.colour, RecordRole::Object, spans, out_);
  if (*p.filter > 0.0) {
    loss(object.span, "filter " + formatNumber(*p.filter) +
                          " becomes plain transparency: the renderer's light through an object "
                          "is not tinted by its colour");
  }
  // +0 + -0 is +0: without a filter, transmit as written keeps a -0.
  m.transparency = *p.filter == 0.0 ? *p.transmit : *p.filter + *p.transmit;
  m.ambient = *p.ambient;
  m.diffuse = *p.diffuse;
  m.specular = *p.phong;
  m.shininess = *p.phongSize;
  if (*p.specular > 0.0) {
    if (*p.phong == 0.0) {
      // Blinn's (N.H)^(1/roughness) is about Phong's (R.V)^(1/(4 roughness)).
      m.specular = *p.specular;
      m.shininess = 1.0 / (4.0 * *p.roughness);
      if (!std::isfinite(m.shininess)) {
        out_.error(DiagnosticCode::ValueNotFinite, object.span,
                   "roughness " + formatNumber(*p.roughness) +
                       " gives a phong size that is not a finite number")
            .hint = "every number of a scene must be a finite double";
      }
      loss(object.span, "the specular highlight (Blinn) becomes a phong highlight of size " +
                            formatNumber(m.shininess));
    } else {
      loss(object.span, "the specular highlight is dropped: the phong highlight is kept");
    }
  }
  m.reflectivity = *p.reflection;
  m.ri = *p.ior;
  for (MaterialProperty property : kMaterialProperties) {
    double& value = materialValue(m, property);
    if (property == MaterialProperty::Shininess || property == MaterialProperty::Ri) {
      checkMaterialValue(property, value, object.span, out_);
      continue;
    }
    if (value < 0.0 || value > 1.0) {
      double clamped = std::clamp(value, 0.0, 1.0);
      loss(object.span, std::string(materialPropertyName(property)) + " " + formatNumber(value) +
                            " becomes " + formatNumber(clamped) +
                            ": the scene model keeps it in [0, 1]");
      value = clamped;
    }
  }
  return m;
}

void PovSceneBuilder::reportView(SourceSpan span) {
  const PovCameraView& view = result_.view;
  // A view out of range is dropped, as the glTF reader drops one: the scene
  // is still good, only the renderer cannot show what POV-Ray would.
  View read{view.verticalFovDegrees, view.aspectRatio, span};
  DiagnosticList range;
  checkView(read, span, range);
  if (range.hasErrors()) {
    loss(span, range.items().front().message + ", and is dropped", range.items().front().hint);
    return;
  }
  result_.read.scene.view = read;
  int width = viewSize_ ? viewSize_->first : options_.pov.imageWidth;
  int height =
      viewSize_ ? viewSize_->second : static_cast<int>(std::lround(width / view.aspectRatio));
  std::string fov = formatNumber(view.verticalFovDegrees);
  Diagnostic& d =
      out_.note(DiagnosticCode::CameraFov, span,
                std::string(parts_.cameraSpan.known() ? "the camera"
                                                      : "the file has no camera; POV-Ray's "
                                                        "default camera") +
                    " shows a vertical field of view of " + fov +
                    " degrees at an aspect ratio of " + formatNumber(view.aspectRatio) +
                    (view.mirrored ? ", in a left-handed world (mirrored)" : ""));
  d.hint = "render with {0} {1} {2}";
  d.remedies = {{Setting::FieldOfView, fov},
                {Setting::Width, std::to_string(width)},
                {Setting::Height, std::to_string(std::max(height, 1))}};
}

}  // namespace

void buildPovScene(const PovSceneParts& parts, const PovMaterialPatch& defaults,
                   const std::vector<PovLexer::ExactComment>& comments, const ReadOptions& options,
                   PovImport& result) {
  PovSceneBuilder(parts, defaults, comments, options, result).build();
}

}  // namespace scene
