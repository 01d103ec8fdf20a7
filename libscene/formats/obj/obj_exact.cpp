#include "libscene/formats/obj/obj_exact.h"

#include <cmath>

#include "libscene/formats/pov/pov_comment_words.h"
#include "libscene/text/number.h"
#include "scenefile/mesh.h"
#include "scenefile/transform.h"

namespace scene {

namespace {

void appendNumbers(std::string& out, std::initializer_list<double> values) {
  for (double v : values) {
    out += ' ';
    appendNumber(out, v);
  }
}

void appendMatrix(std::string& out, const glm::dmat4& m) {
  out += " matrix";
  for (int r = 0; r < 4; ++r) appendNumbers(out, {m[0][r], m[1][r], m[2][r], m[3][r]});
}

void appendVector(std::string& out, const glm::dvec3& v) {
  appendNumbers(out, {v.x, v.y, v.z});
}

// An OUTPUT_FILE that a comment line can hold: no line break, and no blank
// at either end, which the reader would not see.
bool oneLine(const std::string& name) {
  return !name.empty() && name.find_first_of("\r\n") == std::string::npos && name.front() != ' ' &&
         name.back() != ' ' && name.front() != '\t' && name.back() != '\t';
}

std::optional<std::vector<TransformOp>> readTransforms(PovCommentWords& words) {
  std::vector<TransformOp> ops;
  while (std::optional<std::string_view> name = words.any()) {
    TransformOp op;
    bool known = false;
    for (TransformKind kind :
         {TransformKind::Scale, TransformKind::Translate, TransformKind::RotateX,
          TransformKind::RotateY, TransformKind::RotateZ}) {
      if (*name == transformKindName(kind)) {
        op.kind = kind;
        known = true;
      }
    }
    if (!known) return std::nullopt;
    bool vector = op.kind == TransformKind::Scale || op.kind == TransformKind::Translate;
    if (vector ? !words.vector(op.value) : !words.number(op.value.x)) return std::nullopt;
    ops.push_back(op);
  }
  return ops;
}

bool readObject(PovCommentWords& words, std::optional<ObjectComment>& into) {
  ObjectComment c;
  std::optional<std::string_view> kind = words.any();
  if (!kind || !objectKindFromName(*kind)) return false;
  c.object.kind = *objectKindFromName(*kind);
  double segments = 0, planeSize = 0;
  Material& m = c.object.material;
  if (!words.word("segments") || !words.number(segments) || !words.word("plane_size") ||
      !words.number(planeSize) || !words.word("matrix") || !words.matrix(c.object.matrix) ||
      !words.word("material") || !words.vector(m.colour)) {
    return false;
  }
  for (MaterialProperty p : kMaterialProperties) {
    if (!words.number(materialValue(m, p))) return false;
  }
  if (segments < kMinSegments || segments > kMaxSegments || segments != std::floor(segments) ||
      !(planeSize >= 1.0) || planeSize > static_cast<float>(1e30) ||
      static_cast<float>(planeSize) != planeSize) {
    return false;
  }
  c.segments = static_cast<int>(segments);
  c.planeHalfSize = static_cast<float>(planeSize);
  if (words.word("transforms")) {
    c.object.transforms = readTransforms(words);
    // Believed only while they compose to the matrix exactly.
    if (!c.object.transforms || composeTransform(*c.object.transforms) != c.object.matrix) {
      c.object.transforms.reset();
    }
  }
  into = std::move(c);
  return true;
}

}  // namespace

std::string sceneComments(const Scene& scene) {
  std::string out = std::string(kObjExactComment) + " camera";
  appendMatrix(out, scene.camera.matrix);
  out += " colour";
  appendVector(out, scene.camera.colour);
  if (scene.camera.lookAt) {
    out += " look_at";
    appendVector(out, *scene.camera.lookAt);
  }
  out += '\n';
  if (scene.view) {
    out += std::string(kObjExactComment) + " view fov";
    appendNumbers(out, {scene.view->verticalFovDegrees});
    if (scene.view->aspectRatio) {
      out += " aspect";
      appendNumbers(out, {*scene.view->aspectRatio});
    }
    out += '\n';
  }
  if (scene.outputFile && oneLine(*scene.outputFile)) {
    out += std::string(kObjExactComment) + " output_file " + *scene.outputFile + '\n';
  }
  for (const Light& light : scene.lights) {
    out += std::string(kObjExactComment) + " light";
    appendMatrix(out, light.matrix);
    out += " colour";
    appendVector(out, light.colour);
    out += '\n';
  }
  return out;
}

std::string objectComment(const ObjectComment& c) {
  std::string out = std::string(kObjExactComment) + " object " +
                    std::string(objectKindName(c.object.kind)) + " segments " +
                    std::to_string(c.segments) + " plane_size";
  appendNumbers(out, {c.planeHalfSize});
  appendMatrix(out, c.object.matrix);
  out += " material";
  appendVector(out, c.object.material.colour);
  for (MaterialProperty p : kMaterialProperties) {
    appendNumbers(out, {materialValue(c.object.material, p)});
  }
  if (c.object.transforms) {
    out += " transforms";
    for (const TransformOp& op : *c.object.transforms) {
      out += ' ';
      out += transformKindName(op.kind);
      if (op.kind == TransformKind::Scale || op.kind == TransformKind::Translate) {
        appendVector(out, op.value);
      } else {
        appendNumbers(out, {op.value.x});
      }
    }
  }
  return out + '\n';
}

bool readComment(std::string_view text, SceneComments& scene,
                 std::optional<ObjectComment>& object) {
  PovCommentWords words(text);
  if (words.word("object")) return readObject(words, object) && words.done();
  if (words.word("camera")) {
    Camera camera;
    if (!words.word("matrix") || !words.matrix(camera.matrix) || !words.word("colour") ||
        !words.vector(camera.colour)) {
      return false;
    }
    if (words.word("look_at")) {
      glm::dvec3 at;
      if (!words.vector(at)) return false;
      camera.lookAt = at;
    }
    if (!words.done()) return false;
    scene.camera = camera;
    return true;
  }
  if (words.word("view")) {
    View view;
    if (!words.word("fov") || !words.number(view.verticalFovDegrees)) return false;
    if (words.word("aspect")) {
      double aspect = 0;
      if (!words.number(aspect)) return false;
      view.aspectRatio = aspect;
    }
    if (!words.done()) return false;
    scene.view = view;
    return true;
  }
  if (words.word("light")) {
    Light light;
    if (!words.word("matrix") || !words.matrix(light.matrix) || !words.word("colour") ||
        !words.vector(light.colour) || !words.done()) {
      return false;
    }
    scene.lights.push_back(light);
    return true;
  }
  std::string_view prefix = " output_file ";
  if (text.starts_with(prefix) && text.size() > prefix.size()) {
    std::string name(text.substr(prefix.size()));
    while (!name.empty() && (name.back() == '\r')) name.pop_back();
    if (!oneLine(name)) return false;
    scene.outputFile = name;
    return true;
  }
  return false;
}

}  // namespace scene
