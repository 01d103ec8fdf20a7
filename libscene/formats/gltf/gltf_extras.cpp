#include "libscene/formats/gltf/gltf_extras.h"

#include <cctype>
#include <cmath>

#include "libscene/formats/gltf/gltf_mapping.h"

namespace scene::gltf {

namespace {

using Json = nlohmann::json;

std::optional<glm::dvec3> vec3(const Json& j) {
  if (!j.is_array() || j.size() != 3) return std::nullopt;
  glm::dvec3 v;
  for (int i = 0; i < 3; ++i) {
    std::optional<double> x = number(j[i]);
    if (!x) return std::nullopt;
    v[i] = *x;
  }
  return v;
}

std::optional<glm::dmat4> rows(const Json& j) {
  if (!j.is_array() || j.size() != 4) return std::nullopt;
  glm::dmat4 m;
  for (int r = 0; r < 4; ++r) {
    if (!j[r].is_array() || j[r].size() != 4) return std::nullopt;
    for (int c = 0; c < 4; ++c) {
      std::optional<double> x = number(j[r][c]);
      if (!x) return std::nullopt;
      m[c][r] = *x;
    }
  }
  return m;
}

std::optional<std::vector<TransformOp>> transformsFromJson(const Json& j) {
  if (!j.is_array()) return std::nullopt;
  std::vector<TransformOp> ops;
  for (const Json& entry : j) {
    if (!entry.is_array() || entry.empty() || !entry[0].is_string()) return std::nullopt;
    std::string name = entry[0].get<std::string>();
    TransformOp op;
    bool vector = name == "SCALE" || name == "TRANSLATE";
    if (name == "SCALE")
      op.kind = TransformKind::Scale;
    else if (name == "TRANSLATE")
      op.kind = TransformKind::Translate;
    else if (name == "ROTATE_X")
      op.kind = TransformKind::RotateX;
    else if (name == "ROTATE_Y")
      op.kind = TransformKind::RotateY;
    else if (name == "ROTATE_Z")
      op.kind = TransformKind::RotateZ;
    else
      return std::nullopt;
    if (entry.size() != (vector ? 4u : 2u)) return std::nullopt;
    for (std::size_t i = 1; i < entry.size(); ++i) {
      std::optional<double> v = number(entry[i]);
      if (!v) return std::nullopt;
      op.value[static_cast<int>(i - 1)] = *v;
    }
    ops.push_back(op);
  }
  return ops;
}

}  // namespace

std::optional<double> number(const Json& j) {
  if (!j.is_number()) return std::nullopt;
  double v = j.get<double>();
  if (!std::isfinite(v)) return std::nullopt;
  return v;
}

Json parseOrNull(const std::string& text) {
  if (text.empty()) return nullptr;
  Json j = Json::parse(text, nullptr, false);
  return j.is_discarded() ? Json(nullptr) : j;
}

const Json* sfExtras(const Json& extras) {
  if (!extras.is_object()) return nullptr;
  auto it = extras.find(gltf::kExtrasKey);
  return it != extras.end() && it->is_object() ? &*it : nullptr;
}

std::optional<RecordExtras> recordExtras(const std::string& extrasText) {
  Json extras = parseOrNull(extrasText);
  const Json* sf = sfExtras(extras);
  if (!sf || !sf->contains("record") || !(*sf)["record"].is_string()) return std::nullopt;
  RecordExtras out;
  out.record = (*sf)["record"].get<std::string>();
  std::optional<glm::dmat4> m = sf->contains("matrix") ? rows((*sf)["matrix"]) : std::nullopt;
  if (!m) return std::nullopt;
  out.matrix = *m;
  if (out.record == "CAMERA" || out.record == "LIGHT") {
    std::optional<glm::dvec3> colour =
        sf->contains("colour") ? vec3((*sf)["colour"]) : std::nullopt;
    if (!colour) return std::nullopt;
    out.colour = *colour;
  } else if (!objectKindFromName(out.record)) {
    return std::nullopt;
  }
  if (out.record == "CAMERA" && sf->contains("lookAt")) {
    out.lookAt = vec3((*sf)["lookAt"]);
    if (!out.lookAt) return std::nullopt;
  }
  if (out.record == "CAMERA" && sf->contains("view")) {
    const nlohmann::json& view = (*sf)["view"];
    if (!view.is_boolean()) return std::nullopt;
    out.noView = !view.get<bool>();
  }
  if (sf->contains("transforms")) {
    out.transforms = transformsFromJson((*sf)["transforms"]);
    // The operations are kept only while they still make the matrix.
    if (out.transforms && composeTransform(*out.transforms) != out.matrix) out.transforms.reset();
  }
  return out;
}

std::optional<Material> materialExtras(const std::string& extrasText) {
  Json extras = parseOrNull(extrasText);
  const Json* sf = sfExtras(extras);
  if (!sf) return std::nullopt;
  Material m;
  std::optional<glm::dvec3> colour = sf->contains("colour") ? vec3((*sf)["colour"]) : std::nullopt;
  if (!colour) return std::nullopt;
  m.colour = *colour;
  for (MaterialProperty p : kMaterialProperties) {
    std::string key(materialPropertyName(p));
    for (char& c : key) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    std::optional<double> v = sf->contains(key) ? number((*sf)[key]) : std::nullopt;
    if (!v) return std::nullopt;
    materialValue(m, p) = *v;
  }
  return m;
}

}  // namespace scene::gltf
