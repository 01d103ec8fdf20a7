#include "libscene/formats/gltf/gltf_writer.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/matrix.hpp>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <set>
#include <vector>

#include "libscene/formats/gltf/glb.h"
#include "libscene/formats/gltf/gltf_extras.h"
#include "libscene/formats/gltf/gltf_light_units.h"
#include "libscene/formats/gltf/gltf_reference_point.h"
#include "libscene/formats/object_label.h"
#include "libscene/text/number.h"

namespace scene {

namespace {

using OrderedJson = nlohmann::ordered_json;

static_assert(std::endian::native == std::endian::little, "glTF buffers are little-endian");

constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kFloat = 5126;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;

OrderedJson vec3Json(const glm::dvec3& v) {
  return OrderedJson::array({v.x, v.y, v.z});
}

// Row by row, as a scene file writes it: the form a person reads in extras.
OrderedJson rowsJson(const glm::dmat4& m) {
  OrderedJson rows = OrderedJson::array();
  for (int r = 0; r < 4; ++r)
    rows.push_back(OrderedJson::array({m[0][r], m[1][r], m[2][r], m[3][r]}));
  return rows;
}

// Column by column, as glTF's `matrix` wants it; GLM holds m[column][row].
OrderedJson columnsJson(const glm::dmat4& m) {
  OrderedJson out = OrderedJson::array();
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) out.push_back(m[c][r]);
  }
  return out;
}

// Our exact values under `extras` (gltf_extras.h), unless the glTF is
// written without them.
void putExtras(OrderedJson& into, OrderedJson sf, bool extras) {
  if (extras) into["extras"] = gltf::extrasJson(std::move(sf));
}

std::string base64(std::string_view bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 3 <= bytes.size(); i += 3) {
    std::uint32_t v = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i])) << 16 |
                      static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 8 |
                      static_cast<unsigned char>(bytes[i + 2]);
    for (int s = 18; s >= 0; s -= 6) out += kAlphabet[(v >> s) & 63];
  }
  std::size_t left = bytes.size() - i;
  if (left > 0) {
    std::uint32_t v = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i])) << 16;
    if (left == 2) v |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 8;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += left == 2 ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

// A file name as a URI: every byte but the unreserved ones percent-encoded.
std::string uriFromFileName(std::string_view name) {
  std::string out;
  for (char ch : name) {
    unsigned char c = static_cast<unsigned char>(ch);
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~') {
      out += ch;
    } else {
      static constexpr char kHex[] = "0123456789ABCDEF";
      out += '%';
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out;
}

// JSON text indented by two spaces, but with arrays of numbers and strings
// on one line: a matrix reads as one line, not sixteen.
void appendPretty(std::string& out, const OrderedJson& j, int depth) {
  auto newline = [&out](int level) {
    out += '\n';
    out.append(static_cast<std::size_t>(2 * level), ' ');
  };
  if (j.is_object() && !j.empty()) {
    out += '{';
    bool first = true;
    for (const auto& [key, value] : j.items()) {
      if (!first) out += ',';
      first = false;
      newline(depth + 1);
      out += OrderedJson(key).dump();
      out += ": ";
      appendPretty(out, value, depth + 1);
    }
    newline(depth);
    out += '}';
  } else if (j.is_array() && !j.empty() &&
             std::any_of(j.begin(), j.end(),
                         [](const OrderedJson& e) { return e.is_structured(); })) {
    out += '[';
    bool first = true;
    for (const OrderedJson& value : j) {
      if (!first) out += ',';
      first = false;
      newline(depth + 1);
      appendPretty(out, value, depth + 1);
    }
    newline(depth);
    out += ']';
  } else {
    std::string flat = j.dump();
    // nlohmann writes arrays without spaces; one after each comma reads better.
    if (j.is_array()) {
      std::string spaced;
      for (char ch : flat) {
        spaced += ch;
        if (ch == ',') spaced += ' ';
      }
      flat = std::move(spaced);
    }
    out += flat;
  }
}

// The binary buffer and the views and accessors that point into it.
class BufferBuilder {
 public:
  template <typename T>
  int addView(const std::vector<T>& items, int target) {
    data_.append((4 - data_.size() % 4) % 4, '\0');
    std::size_t offset = data_.size();
    std::size_t length = items.size() * sizeof(T);
    data_.resize(offset + length);
    if (length) std::memcpy(data_.data() + offset, items.data(), length);
    views_.push_back(
        {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}, {"target", target}});
    return static_cast<int>(views_.size() - 1);
  }
  int addAccessor(OrderedJson accessor) {
    accessors_.push_back(std::move(accessor));
    return static_cast<int>(accessors_.size() - 1);
  }
  std::string& data() {
    data_.append((4 - data_.size() % 4) % 4, '\0');
    return data_;
  }
  OrderedJson& views() { return views_; }
  OrderedJson& accessors() { return accessors_; }

 private:
  std::string data_;
  OrderedJson views_ = OrderedJson::array();
  OrderedJson accessors_ = OrderedJson::array();
};

struct MeshAccessors {
  int position = -1;
  int normal = -1;
  int indices = -1;
};

MeshAccessors addMesh(BufferBuilder& buffer, const TriangleMesh& mesh) {
  MeshAccessors out;
  glm::vec3 lo(std::numeric_limits<float>::max());
  glm::vec3 hi(std::numeric_limits<float>::lowest());
  for (const glm::vec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  auto floats = [](const glm::vec3& v) {
    return OrderedJson::array(
        {static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)});
  };
  out.position = buffer.addAccessor({{"bufferView", buffer.addView(mesh.positions, kArrayBuffer)},
                                     {"componentType", kFloat},
                                     {"count", mesh.positions.size()},
                                     {"type", "VEC3"},
                                     {"min", floats(lo)},
                                     {"max", floats(hi)}});
  out.normal = buffer.addAccessor({{"bufferView", buffer.addView(mesh.normals, kArrayBuffer)},
                                   {"componentType", kFloat},
                                   {"count", mesh.normals.size()},
                                   {"type", "VEC3"}});
  int view;
  int componentType;
  if (mesh.positions.size() <= 65535) {
    std::vector<std::uint16_t> small(mesh.indices.begin(), mesh.indices.end());
    view = buffer.addView(small, kElementArrayBuffer);
    componentType = kUnsignedShort;
  } else {
    view = buffer.addView(mesh.indices, kElementArrayBuffer);
    componentType = kUnsignedInt;
  }
  out.indices = buffer.addAccessor({{"bufferView", view},
                                    {"componentType", componentType},
                                    {"count", mesh.indices.size()},
                                    {"type", "SCALAR"}});
  return out;
}

// A material's identity for sharing: the exact bits of every value.
std::vector<std::uint64_t> materialKey(const Material& m, bool doubleSided) {
  std::vector<std::uint64_t> key;
  for (int i = 0; i < 3; ++i) key.push_back(std::bit_cast<std::uint64_t>(m.colour[i]));
  for (MaterialProperty p : kMaterialProperties) {
    key.push_back(std::bit_cast<std::uint64_t>(materialValue(m, p)));
  }
  key.push_back(doubleSided);
  return key;
}

std::string lowerCase(std::string_view name) {
  std::string out(name);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

OrderedJson materialJson(const Material& material, ObjectKind kind, bool extras,
                         std::set<std::string>& extensions, int number) {
  gltf::PbrMaterial pbr = gltf::pbrFromMaterial(material, kind);
  OrderedJson out = {{"name", "material " + std::to_string(number)}};
  out["pbrMetallicRoughness"] = {
      {"baseColorFactor",
       OrderedJson::array({pbr.baseColor.r, pbr.baseColor.g, pbr.baseColor.b, 1.0})},
      {"metallicFactor", pbr.metallic},
      {"roughnessFactor", pbr.roughness}};
  if (pbr.doubleSided) out["doubleSided"] = true;
  OrderedJson ext = OrderedJson::object();
  if (pbr.ior) ext["KHR_materials_ior"] = {{"ior", *pbr.ior}};
  if (pbr.transmission)
    ext["KHR_materials_transmission"] = {{"transmissionFactor", *pbr.transmission}};
  if (pbr.specular) ext["KHR_materials_specular"] = {{"specularFactor", *pbr.specular}};
  for (const auto& [name, value] : ext.items()) extensions.insert(name);
  if (!ext.empty()) out["extensions"] = std::move(ext);
  OrderedJson sf = {{"colour", vec3Json(material.colour)}};
  for (MaterialProperty p : kMaterialProperties) {
    sf[lowerCase(materialPropertyName(p))] = materialValue(material, p);
  }
  putExtras(out, std::move(sf), extras);
  return out;
}

OrderedJson transformsJson(const std::vector<TransformOp>& ops) {
  OrderedJson out = OrderedJson::array();
  for (const TransformOp& op : ops) {
    OrderedJson entry = OrderedJson::array({std::string(transformKindName(op.kind))});
    if (op.kind == TransformKind::Scale || op.kind == TransformKind::Translate) {
      entry.insert(entry.end(), {op.value.x, op.value.y, op.value.z});
    } else {
      entry.push_back(op.value.x);
    }
    out.push_back(std::move(entry));
  }
  return out;
}

// The nodes of one record: one, or a chain (gltf::nodeChain) whose last
// node carries the content and the record's name. The first goes into the
// scene's roots; the last is returned.
std::size_t addRecordNodes(OrderedJson& nodes, OrderedJson& roots, const glm::dmat4& m,
                           const std::string& name) {
  std::vector<glm::dmat4> chain = gltf::nodeChain(gltf::withinFloatRange(m));
  roots.push_back(nodes.size());
  for (std::size_t i = 0; i < chain.size(); ++i) {
    std::string part = i + 1 == chain.size() ? name
                       : i == 0              ? name + " translation and rotation"
                                             : name + " scale";
    OrderedJson node = {{"name", part}, {"matrix", columnsJson(chain[i])}};
    if (i + 1 < chain.size()) node["children"] = OrderedJson::array({nodes.size() + 1});
    nodes.push_back(std::move(node));
  }
  return nodes.size() - 1;
}

std::string colourText(const glm::dvec3& c) {
  return formatNumber(c.x) + " " + formatNumber(c.y) + " " + formatNumber(c.z);
}

// Every value glTF cannot hold as it is, reported at its record.
// Where values go that glTF cannot hold: how severe a loss is, and whether
// the exact values ride in extras (the hints say so only then).
struct LossReport {
  Severity severity;
  bool extras;
  DiagnosticList& out;

  Diagnostic& loss(DiagnosticCode code, SourceSpan span, std::string message,
                   std::string extrasHint) {
    Diagnostic& d = out.report(severity, code, span, std::move(message));
    if (extras) d.hint = std::move(extrasHint);
    return d;
  }
};

void reportBeyondFloat(const glm::dmat4& m, const std::string& label, SourceSpan span,
                       LossReport& report) {
  if (gltf::withinFloatRange(m) == m) return;
  report.loss(DiagnosticCode::GltfValueClamped, span,
              "the matrix of " + label +
                  " holds a value beyond single precision (3.4e38), where glTF readers hold node "
                  "matrices: the node gets the nearest float",
              "the exact matrix rides in extras");
}

// Each LIGHT's glTF light: matched to the scene's light at its reference
// distance (gltf_light_units.h, gltf_reference_point.h).
// Without falloff there is no reference distance: the intensity is the
// colour's largest channel, which the reader's check of extras without a
// `referenceDistance` expects.
struct LightPlan {
  std::optional<double> distance;
  gltf::PointLight point;
};

std::vector<LightPlan> planLights(const Scene& scene, const gltf::ReferencePoint& reference,
                                  GltfLightFalloff falloff) {
  std::vector<LightPlan> plans;
  plans.reserve(scene.lights.size());
  for (const Light& light : scene.lights) {
    if (falloff == GltfLightFalloff::None) {
      plans.push_back(
          {std::nullopt, gltf::withinFloats(gltf::unscaledPointLightFromColour(light.colour))});
      continue;
    }
    double distance = gltf::referenceDistance(light.position(), reference);
    plans.push_back({distance, gltf::pointLightFromColour(light.colour, distance)});
  }
  return plans;
}

void reportLightLosses(const Scene& scene, const gltf::ReferencePoint& reference,
                       const std::vector<LightPlan>& plans, LossReport& report) {
  std::string where = gltf::describeReferencePoint(reference);
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    std::string label = "LIGHT " + std::to_string(i + 1);
    if (plans.empty()) {
      report.out.report(report.severity, DiagnosticCode::GltfLightLeftOut, scene.lights[i].span,
                        label + " (COLOUR " + colourText(scene.lights[i].colour) +
                            ") is left out: the glTF is written without lights");
      continue;
    }
    const LightPlan& plan = plans[i];
    reportBeyondFloat(gltf::lightNodeMatrix(scene.lights[i].matrix), label, scene.lights[i].span,
                      report);
    if (!plan.distance) {
      if (plan.point.clamped) {
        report.loss(DiagnosticCode::GltfValueClamped, scene.lights[i].span,
                    "the intensity of " + label +
                        " is beyond single precision, where glTF readers hold it: it is clamped "
                        "to " +
                        gltf::approximateNumber(plan.point.intensity),
                    "the exact colour rides in extras");
      }
      continue;
    }
    if (plan.point.clamped) {
      report.loss(DiagnosticCode::GltfValueClamped, scene.lights[i].span,
                  "the intensity that matches " + label + " at its reference distance " +
                      gltf::approximateNumber(*plan.distance) +
                      " is beyond single precision, where glTF readers hold it: it is clamped "
                      "to " +
                      gltf::approximateNumber(plan.point.intensity) + " cd",
                  "the exact colour rides in extras");
    }
    report.out.note(DiagnosticCode::LightFalloff, scene.lights[i].span,
                    label +
                        " becomes a KHR_lights_punctual point light, whose light falls off with "
                        "the square of the distance where a scene file's does not: its "
                        "intensity, " +
                        gltf::approximateNumber(plan.point.intensity) + " cd, matches " + label +
                        " at the reference distance " + gltf::approximateNumber(*plan.distance) +
                        ", from the light to " + where);
  }
}

// A material value with no glTF counterpart rides in extras alone; without
// extras it is lost.
void reportExtrasOnly(const Material& m, const std::string& label, SourceSpan span,
                      LossReport& report) {
  // A glass reflects by its IOR's Fresnel term alone: its REFLECTIVITY
  // has no counterpart.
  for (MaterialProperty p :
       {MaterialProperty::Ambient, MaterialProperty::Diffuse, MaterialProperty::Reflectivity}) {
    double value = materialValue(m, p);
    if (value == defaultMaterialValue(p)) continue;
    if (p == MaterialProperty::Reflectivity && m.transparency <= 0.0) continue;
    std::string what = std::string(materialPropertyName(p)) + " " + formatNumber(value) + " of " +
                       label + " has no glTF counterpart";
    if (report.extras) {
      report.out.note(DiagnosticCode::GltfExtrasOnly, span, what + " and rides in extras alone");
    } else {
      report.out.report(report.severity, DiagnosticCode::LossMaterial, span,
                        what + " and is dropped: the glTF is written without extras");
    }
  }
}

void reportLosses(const Scene& scene, float planeSize, const gltf::ReferencePoint& reference,
                  const std::vector<LightPlan>& lights, LossReport& report) {
  if (!report.extras) {
    report.out
        .report(report.severity, DiagnosticCode::GltfExtrasLeftOut, {},
                "the glTF is written without extras, so it keeps no exact values: not the "
                "matrices, the object kinds, the material terms, PLANE's infiniteness, the "
                "CAMERA's colour and look-at point, the LIGHTs' colours, nor OUTPUT_FILE")
        .hint =
        "read back, each object is found by fitting its mesh, and the rest comes from "
        "the glTF values";
  }
  reportBeyondFloat(gltf::cameraNodeMatrix(scene.camera.matrix), "the CAMERA", scene.camera.span,
                    report);
  reportLightLosses(scene, reference, lights, report);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& object = scene.objects[i];
    const Material& m = object.material;
    std::string label = objectLabel(object, i);
    reportBeyondFloat(object.matrix, label, object.span, report);
    if (object.kind == ObjectKind::Plane) {
      report.loss(DiagnosticCode::PlaneMadeFinite, object.span,
                  label + " is infinite; glTF gets a square of half-size " +
                      formatNumber(planeSize) + " in the plane's own space",
                  "the kind rides in extras, so the glTF reader reads it back as an infinite "
                  "PLANE");
    }
    if (m.colour.x > 1.0 || m.colour.y > 1.0 || m.colour.z > 1.0) {
      report.loss(
          DiagnosticCode::GltfValueClamped, object.span,
          "COLOUR " + colourText(m.colour) + " of " + label + " is clamped to 1 in baseColorFactor",
          "the exact colour rides in extras");
    }
    if (m.ri < 1.0) {
      report.loss(
          DiagnosticCode::GltfValueClamped, object.span,
          "RI " + formatNumber(m.ri) + " of " + label + " is written as KHR_materials_ior 1",
          "the exact value rides in extras");
    }
    reportExtrasOnly(m, label, object.span, report);
    if (!gltf::isTrsMatrix(object.matrix)) {
      report.out.note(DiagnosticCode::GltfMatrixSplit, object.span,
                      "the matrix of " + label +
                          " has shear, which one glTF node cannot hold: it is written as a chain "
                          "of three nodes (translation and rotation, scale, rotation)");
    }
  }
}

// The JSON pointer of the first number in `j` that is not finite, which
// nlohmann would write as null: a last check over every derived value (a
// node of a chain, a light's intensity, the plane's square).
std::optional<std::string> firstNonFinite(const OrderedJson& j, const std::string& at) {
  if (j.is_number_float()) {
    if (std::isfinite(j.get<double>())) return std::nullopt;
    return at.empty() ? "/" : at;
  }
  if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) {
      if (auto found = firstNonFinite(j[i], at + "/" + std::to_string(i))) return found;
    }
  } else if (j.is_object()) {
    for (const auto& [key, value] : j.items()) {
      if (auto found = firstNonFinite(value, at + "/" + key)) return found;
    }
  }
  return std::nullopt;
}

// What the document is built from before it is assembled: the nodes and
// the scene's roots, the extensions used, the materials and meshes, and
// the binary buffer they point into.
struct Parts {
  OrderedJson nodes = OrderedJson::array();
  OrderedJson roots = OrderedJson::array();
  std::set<std::string> extensions;
  OrderedJson materials = OrderedJson::array();
  OrderedJson meshes = OrderedJson::array();
  BufferBuilder buffer;
};

void addCamera(const Scene& scene, const GltfWriteOptions& options, OrderedJson& doc,
               Parts& parts) {
  // The options' field of view and aspect ratio where they give one, else
  // the scene's View's.
  double yfov = options.yfovDegrees.value_or(scene.view ? scene.view->verticalFovDegrees
                                                        : gltf::kDefaultYfovDegrees);
  OrderedJson perspective = {{"yfov", yfov * std::numbers::pi / 180.0}, {"znear", gltf::kZnear}};
  if (options.width > 0 && options.height > 0) {
    perspective["aspectRatio"] = static_cast<double>(options.width) / options.height;
  } else if (scene.view && scene.view->aspectRatio) {
    perspective["aspectRatio"] = *scene.view->aspectRatio;
  }
  bool defaultView = !scene.view && !options.yfovDegrees && !perspective.contains("aspectRatio");
  doc["cameras"] = OrderedJson::array(
      {{{"name", "CAMERA"}, {"type", "perspective"}, {"perspective", std::move(perspective)}}});
  std::size_t node = addRecordNodes(parts.nodes, parts.roots,
                                    gltf::cameraNodeMatrix(scene.camera.matrix), "CAMERA");
  parts.nodes[node]["camera"] = 0;
  OrderedJson sf = {{"record", "CAMERA"},
                    {"colour", vec3Json(scene.camera.colour)},
                    {"matrix", rowsJson(scene.camera.matrix)}};
  if (scene.camera.lookAt) sf["lookAt"] = vec3Json(*scene.camera.lookAt);
  // A scene without a View, written with the default field of view, reads
  // back without one: the yfov is then the writer's, not the scene's.
  if (defaultView) sf["view"] = false;
  putExtras(parts.nodes[node], std::move(sf), options.extras);
}

void addLights(const Scene& scene, const std::vector<LightPlan>& plans, bool extras,
               OrderedJson& doc, Parts& parts) {
  if (plans.empty()) return;
  OrderedJson lights = OrderedJson::array();
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& light = scene.lights[i];
    std::string name = "LIGHT " + std::to_string(i + 1);
    const gltf::PointLight& point = plans[i].point;
    lights.push_back({{"name", name},
                      {"type", "point"},
                      {"color", vec3Json(point.color)},
                      {"intensity", point.intensity}});
    std::size_t node =
        addRecordNodes(parts.nodes, parts.roots, gltf::lightNodeMatrix(light.matrix), name);
    parts.nodes[node]["extensions"] = {{"KHR_lights_punctual", {{"light", i}}}};
    OrderedJson sf = {{"record", "LIGHT"},
                      {"colour", vec3Json(light.colour)},
                      {"matrix", rowsJson(light.matrix)}};
    if (plans[i].distance) sf["referenceDistance"] = *plans[i].distance;
    putExtras(parts.nodes[node], std::move(sf), extras);
  }
  parts.extensions.insert("KHR_lights_punctual");
  doc["extensions"] = {{"KHR_lights_punctual", {{"lights", std::move(lights)}}}};
}

// The objects: one vertex set per kind, one material per distinct value,
// one mesh per kind and material.
void addObjects(const Scene& scene, const GltfWriteOptions& options, float planeSize,
                Parts& parts) {
  std::map<ObjectKind, MeshAccessors> kindAccessors;
  std::map<std::vector<std::uint64_t>, std::size_t> materialIndex;
  std::map<std::pair<ObjectKind, std::size_t>, std::size_t> meshIndex;
  std::map<std::size_t, OrderedJson> meshObjects;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& object = scene.objects[i];
    auto accessors = kindAccessors.find(object.kind);
    if (accessors == kindAccessors.end()) {
      accessors = kindAccessors
                      .emplace(object.kind,
                               addMesh(parts.buffer,
                                       primitiveMesh(object.kind, options.segments, planeSize)))
                      .first;
    }
    bool doubleSided = object.kind == ObjectKind::Plane;
    auto [material, newMaterial] =
        materialIndex.emplace(materialKey(object.material, doubleSided), parts.materials.size());
    if (newMaterial) {
      parts.materials.push_back(materialJson(object.material, object.kind, options.extras,
                                             parts.extensions,
                                             static_cast<int>(parts.materials.size()) + 1));
    }
    auto [mesh, newMesh] =
        meshIndex.emplace(std::pair{object.kind, material->second}, parts.meshes.size());
    if (newMesh) {
      const MeshAccessors& a = accessors->second;
      parts.meshes.push_back(
          {{"name", std::string(objectKindName(object.kind))},
           {"primitives",
            OrderedJson::array({{{"attributes", {{"POSITION", a.position}, {"NORMAL", a.normal}}},
                                 {"indices", a.indices},
                                 {"material", material->second}}})}});
    }
    std::string name = std::string(objectKindName(object.kind)) + " " + std::to_string(i + 1);
    std::size_t node = addRecordNodes(parts.nodes, parts.roots, object.matrix, name);
    parts.nodes[node]["mesh"] = mesh->second;
    OrderedJson sf = {{"record", std::string(objectKindName(object.kind))},
                      {"matrix", rowsJson(object.matrix)},
                      {"object", i + 1}};
    if (object.transforms) sf["transforms"] = transformsJson(*object.transforms);
    meshObjects[mesh->second].push_back(sf);
    putExtras(parts.nodes[node], std::move(sf), options.extras);
  }
  // Each mesh names its objects too: a program that replaces their nodes by
  // instances of the mesh (glTF-Transform's `instance`) drops the nodes'
  // extras, and keeps the mesh's.
  for (auto& [mesh, objects] : meshObjects) {
    putExtras(parts.meshes[mesh], {{"objects", std::move(objects)}}, options.extras);
  }
}

// The scene, the nodes, materials and meshes after what `doc` holds, with
// extensionsUsed first among the top-level keys after asset.
void assemble(OrderedJson& doc, Parts& parts) {
  if (!parts.extensions.empty()) {
    OrderedJson used = OrderedJson::array();
    for (const std::string& name : parts.extensions) used.push_back(name);
    OrderedJson reordered;
    for (auto& [key, value] : doc.items()) {
      reordered[key] = value;
      if (key == "asset") reordered["extensionsUsed"] = used;
    }
    doc = std::move(reordered);
  }
  doc["scene"] = 0;
  doc["scenes"] = OrderedJson::array({{{"name", "scene"}, {"nodes", std::move(parts.roots)}}});
  doc["nodes"] = std::move(parts.nodes);
  if (!parts.materials.empty()) doc["materials"] = std::move(parts.materials);
  if (!parts.meshes.empty()) doc["meshes"] = std::move(parts.meshes);
}

// The file (and for a .gltf with an external buffer, the buffer's), once
// the buffer is in the document: embedded in a .gltf as base64, or beside.
GltfFiles encode(OrderedJson& doc, BufferBuilder& buffer, const GltfWriteOptions& options,
                 bool binary) {
  GltfFiles files;
  std::string& bin = buffer.data();
  if (!bin.empty()) {
    doc["accessors"] = std::move(buffer.accessors());
    doc["bufferViews"] = std::move(buffer.views());
    OrderedJson b = {{"byteLength", bin.size()}};
    if (!binary) {
      if (options.externalBuffer.empty()) {
        b["uri"] = "data:application/octet-stream;base64," + base64(bin);
      } else {
        b["uri"] = uriFromFileName(options.externalBuffer);
        files.buffer = bin;
      }
    }
    doc["buffers"] = OrderedJson::array({std::move(b)});
  }
  if (binary) {
    files.main = encodeGlb(doc.dump(), bin);
  } else {
    appendPretty(files.main, doc, 0);
    files.main += '\n';
  }
  return files;
}

}  // namespace

std::optional<GltfFiles> writeGltf(const Scene& scene, const ConversionOptions& conversion,
                                   bool binary, DiagnosticList& out) {
  const GltfWriteOptions& options = conversion.gltf;
  std::size_t errorsBefore = out.errorCount();
  float planeSize = scenePlaneHalfSize(scene);
  gltf::ReferencePoint reference = gltf::referencePoint(scene);
  std::vector<LightPlan> lights;
  if (options.lights) lights = planLights(scene, reference, options.lightFalloff);
  LossReport report{conversion.noLoss ? Severity::Error : Severity::Warning, options.extras, out};
  reportLosses(scene, planeSize, reference, lights, report);
  if (out.errorCount() != errorsBefore) return std::nullopt;

  OrderedJson doc;
  OrderedJson asset = {{"version", "2.0"}, {"generator", options.generator}};
  if (scene.outputFile && options.extras)
    asset["extras"] = {{gltf::kExtrasKey, {{"outputFile", *scene.outputFile}}}};
  doc["asset"] = std::move(asset);
  Parts parts;
  addCamera(scene, options, doc, parts);
  addLights(scene, lights, options.extras, doc, parts);
  addObjects(scene, options, planeSize, parts);
  assemble(doc, parts);
  if (std::optional<std::string> where = firstNonFinite(doc, "")) {
    out.error(DiagnosticCode::ValueNotFinite, scene.camera.span,
              "the glTF's number at " + *where + " is not finite, so nothing is written")
        .hint = "scale the scene so that its numbers stay within about 1e300";
    return std::nullopt;
  }
  return encode(doc, parts.buffer, options, binary);
}

}  // namespace scene
