#include "libscene/formats/gltf/gltf_extras.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>

#include "libscene/formats/gltf/gltf_mapping.h"
#include "scenefile/mesh.h"

namespace scene::gltf {

namespace {

using Json = nlohmann::json;

std::optional<glm::dvec3> vec3(const Json& j) {
  if (!j.is_array() || j.size() != 3) return std::nullopt;
  glm::dvec3 v;
  for (int i = 0; i < 3; ++i) {
    std::optional<double> x = extrasNumber(j[i]);
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
      std::optional<double> x = extrasNumber(j[r][c]);
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
      std::optional<double> v = extrasNumber(entry[i]);
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

std::optional<double> extrasNumber(const Json& j) {
  if (j.is_string() && j.get_ref<const std::string&>() == "-0") return -0.0;
  return number(j);
}

Json extrasJson(Json sf) {
  // Depth is that of the writer's own values: a matrix's rows at most.
  auto mark = [](auto& self, Json& j) -> void {
    if (j.is_number_float() && j.get<double>() == 0.0 && std::signbit(j.get<double>())) {
      j = "-0";
    } else if (j.is_structured()) {
      for (Json& e : j) self(self, e);
    }
  };
  mark(mark, sf);
  return Json{{kExtrasKey, std::move(sf)}};
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

namespace {

std::optional<RecordExtras> recordOf(const Json* sf) {
  if (!sf || !sf->is_object() || !sf->contains("record") || !(*sf)["record"].is_string()) {
    return std::nullopt;
  }
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
  if (out.record == "LIGHT" && sf->contains("referenceDistance")) {
    out.referenceDistance = extrasNumber((*sf)["referenceDistance"]);
    if (!out.referenceDistance || !(*out.referenceDistance > 0.0)) return std::nullopt;
  }
  if (sf->contains("transforms")) {
    out.transforms = transformsFromJson((*sf)["transforms"]);
    // The operations are kept only while they still make the matrix.
    if (out.transforms && composeTransform(*out.transforms) != out.matrix) out.transforms.reset();
  }
  if (sf->contains("object")) {
    const Json& object = (*sf)["object"];
    if (!object.is_number_unsigned() || object.get<std::uint64_t>() == 0) return std::nullopt;
    out.object = object.get<std::uint64_t>();
  }
  return out;
}

}  // namespace

std::optional<RecordExtras> recordExtras(const std::string& extrasText) {
  Json extras = parseOrNull(extrasText);
  return recordOf(sfExtras(extras));
}

std::vector<RecordExtras> meshRecords(const std::string& extrasText) {
  Json extras = parseOrNull(extrasText);
  const Json* sf = sfExtras(extras);
  std::vector<RecordExtras> out;
  if (!sf || !sf->contains("objects") || !(*sf)["objects"].is_array()) return out;
  for (const Json& entry : (*sf)["objects"]) {
    std::optional<RecordExtras> record = recordOf(&entry);
    if (record && objectKindFromName(record->record)) out.push_back(std::move(*record));
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
    std::optional<double> v = sf->contains(key) ? extrasNumber((*sf)[key]) : std::nullopt;
    if (!v) return std::nullopt;
    materialValue(m, p) = *v;
  }
  return m;
}

const std::string& ownExtras(const std::vector<std::string>& extras, int index) {
  static const std::string kNone;
  return index >= 0 && static_cast<std::size_t>(index) < extras.size() ? extras[index] : kNone;
}

double distanceOfPbr(const PbrMaterial& a, const PbrMaterial& b) {
  double d = 0.0;
  for (int i = 0; i < 4; ++i) d = std::max(d, std::abs(a.baseColor[i] - b.baseColor[i]));
  d = std::max({d, std::abs(a.metallic - b.metallic), std::abs(a.roughness - b.roughness)});
  auto optional = [&d](const std::optional<double>& x, const std::optional<double>& y) {
    if (x.has_value() != y.has_value()) {
      d = std::numeric_limits<double>::infinity();
    } else if (x) {
      d = std::max(d, std::abs(*x - *y));
    }
  };
  optional(a.ior, b.ior);
  optional(a.transmission, b.transmission);
  optional(a.specular, b.specular);
  return std::isnan(d) ? std::numeric_limits<double>::infinity() : d;
}

std::optional<int> writtenSegments(ObjectKind kind, std::size_t triangles) {
  for (int n = kMinSegments; n <= kMaxSegments; ++n) {
    auto segments = static_cast<std::size_t>(n);
    std::size_t want = 0;
    switch (kind) {
      case ObjectKind::Sphere:
        want = 2 * segments * (static_cast<std::size_t>(std::max(2, n / 2)) - 1);
        break;
      case ObjectKind::Cylinder:
        want = 4 * segments;
        break;
      case ObjectKind::Cube:
        want = 12;
        break;
      case ObjectKind::Plane:
        want = 2;
        break;
    }
    if (want == triangles) return n;
  }
  return std::nullopt;
}

namespace {

// A triangle as its three corners, turned (not mirrored) so that the
// smallest comes first: the same triangle gives the same value whichever
// corner a file starts it at, and keeps its winding.
using Corner = std::array<float, 3>;
using Triangle = std::array<Corner, 3>;

Triangle canonical(const Corner& a, const Corner& b, const Corner& c) {
  if (b < a && b < c) return {b, c, a};
  if (c < a && c < b) return {c, a, b};
  return {a, b, c};
}

std::vector<Triangle> sortedTriangles(const std::vector<Corner>& corners,
                                      const std::vector<std::uint32_t>& indices) {
  std::vector<Triangle> out;
  out.reserve(indices.size() / 3);
  for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
    out.push_back(canonical(corners[indices[i]], corners[indices[i + 1]], corners[indices[i + 2]]));
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

bool isWrittenMesh(ObjectKind kind, const std::vector<glm::dvec3>& positions,
                   const std::vector<std::uint32_t>& indices) {
  std::optional<int> segments = writtenSegments(kind, indices.size() / 3);
  if (!segments || positions.empty() || indices.size() % 3 != 0) return false;
  // The writer's coordinates are floats: any other value is not its mesh.
  std::vector<Corner> corners;
  corners.reserve(positions.size());
  float halfSize = 0.0f;
  for (const glm::dvec3& p : positions) {
    Corner c{static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)};
    for (int i = 0; i < 3; ++i) {
      if (static_cast<double>(c[i]) != p[i]) return false;
    }
    // A plane's square is as large as the scene it was written for: its
    // corners give the half-size.
    halfSize = std::max(halfSize, std::abs(c[0]));
    corners.push_back(c);
  }
  TriangleMesh want = primitiveMesh(kind, *segments, halfSize);
  std::vector<Corner> wantCorners;
  wantCorners.reserve(want.positions.size());
  for (const glm::vec3& p : want.positions) wantCorners.push_back({p.x, p.y, p.z});
  return sortedTriangles(corners, indices) == sortedTriangles(wantCorners, want.indices);
}

}  // namespace scene::gltf
