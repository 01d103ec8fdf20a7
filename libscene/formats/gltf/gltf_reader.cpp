#include "libscene/formats/gltf/gltf_reader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <glm/gtc/quaternion.hpp>
#include <glm/matrix.hpp>
#include <limits>
#include <map>
#include <new>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <set>
#include <vector>

#include "libscene/formats/gltf/glb.h"
#include "libscene/formats/gltf/gltf_document.h"
#include "libscene/formats/gltf/gltf_extras.h"
#include "libscene/formats/gltf/gltf_files.h"
#include "libscene/formats/gltf/gltf_mapping.h"
#include "scenefile/mesh.h"
#include "libscene/formats/gltf/mesh_fit.h"
#include "libscene/text/number.h"
#include "libscene/text/reader_support.h"
#include "scenefile/read.h"
#include "scenefile/transform.h"
#include "scenefile/validation.h"

namespace scene {

namespace {

using Json = nlohmann::json;
namespace fs = std::filesystem;

// Extensions whose absence from our reading changes nothing a scene file
// can hold; a file that requires any other cannot be read right.
const std::set<std::string> kReadableRequired = {
    "KHR_lights_punctual",    "KHR_materials_ior",     "KHR_materials_transmission",
    "KHR_materials_specular", "KHR_texture_transform", "KHR_materials_emissive_strength",
    "KHR_materials_unlit",
};

// ---------------------------------------------------------------------------
// The text before tinygltf sees it.

SourceSpan spanAtByte(std::string_view text, std::size_t byte) {
  byte = std::min(byte, text.size());
  SourceSpan span{1, 1, 0};
  for (std::size_t i = 0; i < byte; ++i) {
    if (text[i] == '\n') {
      ++span.line;
      span.column = 1;
    } else {
      ++span.column;
    }
  }
  return span;
}

// The byte at which `text` nests deeper than kMaxJsonDepth, if it does.
// tinygltf turns `extras` into its own values recursively, so depth must be
// bounded before it parses.
std::optional<std::size_t> tooDeep(std::string_view text) {
  int depth = 0;
  bool inString = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (inString) {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        inString = false;
      }
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) return i;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return std::nullopt;
}

// nlohmann's message without its "[json.exception...] parse error at line
// L, column C: " prefix, which the span already says.
std::string parseErrorMessage(const std::string& what) {
  std::size_t colon = what.find(": ");
  std::string message = colon == std::string::npos ? what : what.substr(colon + 2);
  return message;
}

// Files beside the glTF (gltf_files.h).
using gltf::confinedExists;
using gltf::confinedRead;
using gltf::Confinement;
using gltf::noWrite;
using gltf::unexpandedPath;
using gltf::uriProblem;

bool noImageDecoding(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                     const unsigned char*, int, void*) {
  return true;
}

// tinygltf's error text, first line only, without its trailing newline.
std::string firstLine(const std::string& text) {
  std::string line = text.substr(0, text.find('\n'));
  if (line.size() > 160) line = line.substr(0, 157) + "...";
  return line.empty() ? "tinygltf could not read it" : line;
}

// Our own extras (gltf_extras.h).
using gltf::materialExtras;
using gltf::number;
using gltf::parseOrNull;
using gltf::RecordExtras;
using gltf::recordExtras;
using gltf::sfExtras;

// ---------------------------------------------------------------------------
// The model, once tinygltf has read it.

std::string deviationText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2g", value);
  return text;
}

// Names come from the file: a long one is cut, so that a message stays one
// line. Control bytes stay as they are; the tools print every message
// through tools::printableText, which shows them as \xNN.
std::string quoted(const std::string& name) {
  if (name.empty()) return "";
  constexpr std::size_t kMaxShown = 80;
  // The cut falls between UTF-8 characters, not inside one.
  std::size_t end = std::min(name.size(), kMaxShown);
  while (end < name.size() && end > 0 && (static_cast<unsigned char>(name[end]) & 0xC0) == 0x80) {
    --end;
  }
  return " '" + name.substr(0, end) + (end < name.size() ? "..." : "") + "'";
}

std::string nodeLabel(const tinygltf::Model& model, int node) {
  return "node " + std::to_string(node) + quoted(model.nodes[node].name);
}

std::string meshLabel(const tinygltf::Model& model, int mesh) {
  return "mesh " + std::to_string(mesh) + quoted(model.meshes[mesh].name);
}

double distanceOfPbr(const gltf::PbrMaterial& a, const gltf::PbrMaterial& b) {
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

const std::string& ownExtras(const std::vector<std::string>& extras, int index) {
  static const std::string kNone;
  return index >= 0 && static_cast<std::size_t>(index) < extras.size() ? extras[index] : kNone;
}

// Whether the file's weighted count of objects (gltf::objectWeight) is
// within options.gltf.maxNodes; when not, says so.
bool withinObjectLimit(std::size_t objects, const ReadOptions& options, DiagnosticList& out) {
  if (objects <= options.gltf.maxNodes) return true;
  out.error(DiagnosticCode::GltfTooManyNodes, {},
            "the file has " + std::to_string(objects) +
                " nodes and other objects (a material counting 5, a camera or a light 2), more "
                "than the limit of " +
                std::to_string(options.gltf.maxNodes))
      .hint = "raise the limit with --max-nodes if the file is meant to be this large";
  return false;
}

bool finite(const glm::dmat4& m) {
  double sum = 0.0;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) sum += m[c][r] * 0.0;
  }
  return sum == 0.0;
}

// The extras tell whether they still describe the file's own data: a
// difference above this (relative) means the file was edited elsewhere.
constexpr double kExtrasAgreement = 1e-9;

struct FittedPart {
  MeshFit fit;
  int material = -1;
};

class Importer {
 public:
  Importer(const tinygltf::Model& model, const gltf::OwnExtras& own, const ReadOptions& options,
           ReadResult& result)
      : model_(model),
        own_(own),
        scene_(result.scene),
        out_(result.diagnostics),
        loss_(options.noLoss ? Severity::Error : Severity::Warning),
        maxObjects_(options.maxObjects),
        maxVertices_(options.gltf.maxVertices),
        maxIndices_(options.gltf.maxVertices > std::numeric_limits<std::size_t>::max() / 3
                        ? std::numeric_limits<std::size_t>::max()
                        : 3 * options.gltf.maxVertices) {}

  void run() {
    if (!checkIndices()) return;
    if (!model_.animations.empty()) {
      out_.report(loss_, DiagnosticCode::GltfIgnored, {},
                  std::to_string(model_.animations.size()) +
                      " animation(s) are ignored: a scene file is a still");
    }
    if (!model_.skins.empty()) {
      out_.report(loss_, DiagnosticCode::GltfIgnored, {},
                  std::to_string(model_.skins.size()) +
                      " skin(s) are ignored: meshes are read in their rest pose");
    }
    std::vector<int> roots = rootNodes();
    if (out_.hasErrors()) return;
    walk(roots);
    if (out_.hasErrors()) return;
    placeDirectionalLights();
    if (!haveCamera_) makeDefaultCamera();
  }

 private:
  // --- Indices ------------------------------------------------------------

  bool index(int value, std::size_t size, const std::string& where, const std::string& what,
             bool optional = true) {
    if (value < 0 && optional && value == -1) return true;
    if (value >= 0 && static_cast<std::size_t>(value) < size) return true;
    out_.error(DiagnosticCode::GltfIndexOutOfRange, {},
               where + " points at " + what + " " + std::to_string(value) + ", but the file has " +
                   std::to_string(size));
    return false;
  }

  bool checkIndices() {
    const tinygltf::Model& m = model_;
    bool ok = true;
    if (m.defaultScene != -1) ok &= index(m.defaultScene, m.scenes.size(), "scene", "scene");
    for (std::size_t s = 0; s < m.scenes.size(); ++s) {
      for (int n : m.scenes[s].nodes) {
        ok &= index(n, m.nodes.size(), "scenes[" + std::to_string(s) + "]", "node", false);
      }
    }
    for (std::size_t i = 0; i < m.nodes.size() && !out_.full(); ++i) {
      const tinygltf::Node& node = m.nodes[i];
      std::string where = "nodes[" + std::to_string(i) + "]";
      for (int c : node.children)
        ok &= index(c, m.nodes.size(), where + ".children", "node", false);
      ok &= index(node.mesh, m.meshes.size(), where + ".mesh", "mesh");
      ok &= index(node.camera, m.cameras.size(), where + ".camera", "camera");
      int light = nodeLight(static_cast<int>(i));
      if (light != -1)
        ok &= index(light, m.lights.size(), where + " KHR_lights_punctual", "light", false);
      if (!(node.matrix.empty() || node.matrix.size() == 16) ||
          !(node.translation.empty() || node.translation.size() == 3) ||
          !(node.rotation.empty() || node.rotation.size() == 4) ||
          !(node.scale.empty() || node.scale.size() == 3)) {
        out_.error(DiagnosticCode::GltfInvalid, {},
                   where + " has a matrix, translation, rotation or scale of the wrong length");
        ok = false;
      }
    }
    for (std::size_t i = 0; i < m.meshes.size() && !out_.full(); ++i) {
      for (std::size_t p = 0; p < m.meshes[i].primitives.size(); ++p) {
        const tinygltf::Primitive& prim = m.meshes[i].primitives[p];
        std::string where =
            "meshes[" + std::to_string(i) + "].primitives[" + std::to_string(p) + "]";
        auto position = prim.attributes.find("POSITION");
        if (position != prim.attributes.end()) {
          ok &= index(position->second, m.accessors.size(), where + ".attributes.POSITION",
                      "accessor", false);
        }
        ok &= index(prim.indices, m.accessors.size(), where + ".indices", "accessor");
        ok &= index(prim.material, m.materials.size(), where + ".material", "material");
      }
    }
    for (std::size_t i = 0; i < m.accessors.size() && !out_.full(); ++i) {
      ok &= index(m.accessors[i].bufferView, m.bufferViews.size(),
                  "accessors[" + std::to_string(i) + "].bufferView", "buffer view");
    }
    for (std::size_t i = 0; i < m.bufferViews.size() && !out_.full(); ++i) {
      ok &= index(m.bufferViews[i].buffer, m.buffers.size(),
                  "bufferViews[" + std::to_string(i) + "].buffer", "buffer", false);
    }
    return ok;
  }

  int nodeLight(int node) const {
    Json ext = parseOrNull(model_.nodes[node].extensions_json_string);
    if (!ext.is_object()) return -1;
    auto it = ext.find("KHR_lights_punctual");
    if (it == ext.end() || !it->is_object()) return -1;
    auto light = it->find("light");
    if (light == it->end() || !light->is_number_integer()) return -2;
    long long value = light->get<long long>();
    return value < 0 || value > std::numeric_limits<int>::max() ? -2 : static_cast<int>(value);
  }

  // --- The hierarchy ------------------------------------------------------

  std::vector<int> rootNodes() {
    if (!model_.scenes.empty()) {
      int scene = model_.defaultScene >= 0 ? model_.defaultScene : 0;
      if (model_.scenes.size() > 1) {
        out_.note(DiagnosticCode::GltfIgnored, {},
                  "the file has " + std::to_string(model_.scenes.size()) + " scenes; scene " +
                      std::to_string(scene) + " is read");
      }
      return model_.scenes[scene].nodes;
    }
    // No scene: every node that is nobody's child.
    std::vector<bool> child(model_.nodes.size(), false);
    for (const tinygltf::Node& node : model_.nodes) {
      for (int c : node.children) child[c] = true;
    }
    std::vector<int> roots;
    for (std::size_t i = 0; i < model_.nodes.size(); ++i) {
      if (!child[i]) roots.push_back(static_cast<int>(i));
    }
    return roots;
  }

  glm::dmat4 localMatrix(const tinygltf::Node& node) const {
    if (node.matrix.size() == 16) {
      glm::dmat4 m;
      for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = node.matrix[i];
      return m;
    }
    glm::dmat4 m(1.0);
    if (node.translation.size() == 3) {
      m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
    }
    if (node.rotation.size() == 4) {
      glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
      double length = glm::length(q);
      if (length > 0.0 && std::isfinite(length)) q /= length;
      glm::dmat3 r = glm::mat3_cast(q);
      glm::dmat4 t = m;
      m = glm::dmat4(r);
      m[3] = t[3];
    }
    if (node.scale.size() == 3) {
      for (int i = 0; i < 3; ++i) m[i] *= node.scale[i];
    }
    return m;
  }

  // Depth first, children in order, with an explicit stack: a deep or
  // cyclic hierarchy costs no recursion.
  void walk(const std::vector<int>& roots) {
    std::vector<bool> seen(model_.nodes.size(), false);
    std::vector<std::pair<int, glm::dmat4>> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it)
      stack.emplace_back(*it, glm::dmat4(1.0));
    while (!stack.empty() && !out_.full() && !stopped_) {
      auto [node, parent] = stack.back();
      stack.pop_back();
      if (seen[node]) {
        out_.error(
            DiagnosticCode::GltfNodeCycle, {},
            nodeLabel(model_, node) +
                " is reached twice: the node hierarchy has a cycle or a node with two parents");
        return;
      }
      seen[node] = true;
      glm::dmat4 world = parent * localMatrix(model_.nodes[node]);
      // Finite values can compose to infinity: the error names the node
      // where it happens, not a record far from it.
      if (!finite(world)) {
        out_.error(DiagnosticCode::ValueNotFinite, {},
                   "/nodes/" + std::to_string(node) + " (" + nodeLabel(model_, node) +
                       "): its transform composed with its parents' is not finite");
        return;
      }
      visit(node, world);
      const std::vector<int>& children = model_.nodes[node].children;
      for (auto it = children.rbegin(); it != children.rend(); ++it) stack.emplace_back(*it, world);
    }
  }

  void visit(int index, const glm::dmat4& world) {
    const tinygltf::Node& node = model_.nodes[index];
    // A node holds at most one light, counted here, and one mesh, whose
    // objects are counted as they are added (roomForOne).
    if (nodeLight(index) >= 0 && !roomForOne(index)) return;
    if (std::optional<RecordExtras> extras = recordExtras(ownExtras(own_.nodes, index))) {
      if (useExtras(index, world, *extras)) return;
      out_.note(DiagnosticCode::GltfExtrasStale, {},
                nodeLabel(model_, index) + " no longer matches the " + extras->record +
                    " that its extras describe (the file was edited elsewhere): the node is read "
                    "as it is");
    }
    if (node.camera >= 0) addCamera(index, world);
    int light = nodeLight(index);
    if (light >= 0) addLight(index, light, world);
    if (node.mesh >= 0) addMeshObjects(index, world);
  }

  // --- Records from our own extras ---------------------------------------

  bool useExtras(int index, const glm::dmat4& world, const RecordExtras& extras) {
    const tinygltf::Node& node = model_.nodes[index];
    if (extras.record == "CAMERA") {
      if (node.camera < 0 || haveCamera_ ||
          gltf::matrixDistance(gltf::withinFloatRange(gltf::cameraNodeMatrix(extras.matrix)),
                               world) > kExtrasAgreement) {
        return false;
      }
      haveCamera_ = true;
      scene_.camera.matrix = extras.matrix;
      scene_.camera.colour = extras.colour;
      scene_.camera.lookAt = extras.lookAt;
      reportFov(node.camera);
      if (extras.noView) scene_.view.reset();
      return true;
    }
    if (extras.record == "LIGHT") {
      int light = nodeLight(index);
      if (light < 0 ||
          gltf::matrixDistance(gltf::withinFloatRange(gltf::lightNodeMatrix(extras.matrix)),
                               world) > kExtrasAgreement) {
        return false;
      }
      gltf::PointLight want = gltf::pointLightFromColour(extras.colour);
      gltf::PointLight have = pointLight(model_.lights[light]);
      double d = std::max(
          glm::length(want.color - have.color),
          std::abs(want.intensity - have.intensity) / std::max(1.0, std::abs(want.intensity)));
      if (!(d <= kExtrasAgreement) || model_.lights[light].type != "point") return false;
      scene_.lights.push_back(Light{extras.matrix, extras.colour, {}});
      return true;
    }
    ObjectKind kind = *objectKindFromName(extras.record);
    if (node.mesh < 0 || model_.meshes[node.mesh].primitives.size() != 1 ||
        gltf::matrixDistance(gltf::withinFloatRange(extras.matrix), world) > kExtrasAgreement ||
        !holdsWrittenMesh(node.mesh, kind)) {
      return false;
    }
    Object object;
    object.kind = kind;
    object.matrix = extras.matrix;
    object.transforms = extras.transforms;
    object.material = material(model_.meshes[node.mesh].primitives[0].material, kind);
    if (roomForOne(index)) scene_.objects.push_back(std::move(object));
    return true;
  }

  // Whether the mesh holds the vertices the writer writes for `kind`
  // (libscene/mesh.*): a node edited to point at another mesh keeps its old
  // extras, and they are believed only while the mesh is still their kind's.
  // Cached by accessor, which the writer shares among a kind's meshes.
  bool holdsWrittenMesh(int meshIndex, ObjectKind kind) {
    const tinygltf::Primitive& prim = model_.meshes[meshIndex].primitives[0];
    auto position = prim.attributes.find("POSITION");
    if ((prim.mode >= 0 && prim.mode != TINYGLTF_MODE_TRIANGLES) ||
        position == prim.attributes.end()) {
      return false;
    }
    auto [cached, fresh] = writtenMesh_.emplace(std::pair{position->second, kind}, false);
    if (!fresh) return cached->second;
    const tinygltf::Accessor& accessor = model_.accessors[position->second];
    std::optional<int> segments = writtenSegments(kind, accessor.count);
    if (!segments || accessor.sparse.isSparse || accessor.bufferView < 0) return false;
    bool skipped = false;
    std::optional<std::vector<double>> xyz =
        readAccessor(position->second, TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT},
                     "POSITION", maxVertices_, verticesRead_, skipped);
    if (!xyz || xyz->empty()) return false;
    TriangleMesh want = primitiveMesh(kind, *segments, static_cast<float>(std::abs((*xyz)[0])));
    if (want.positions.size() * 3 != xyz->size()) return false;
    for (std::size_t i = 0; i < want.positions.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        if (static_cast<double>(want.positions[i][c]) != (*xyz)[3 * i + c]) return false;
      }
    }
    cached->second = true;
    return true;
  }

  // The --tessellation that gives the writer's mesh of `kind` this many
  // vertices, if one does.
  static std::optional<int> writtenSegments(ObjectKind kind, std::size_t vertices) {
    for (int n = kMinSegments; n <= kMaxSegments; ++n) {
      std::size_t want = 0;
      switch (kind) {
        case ObjectKind::Sphere:
          want = 2 + static_cast<std::size_t>(n) * (std::max(2, n / 2) - 1);
          break;
        case ObjectKind::Cylinder:
          want = 4 * static_cast<std::size_t>(n) + 2;
          break;
        case ObjectKind::Cube:
          want = 24;
          break;
        case ObjectKind::Plane:
          want = 4;
          break;
      }
      if (want == vertices) return n;
    }
    return std::nullopt;
  }

  // --- Cameras and lights -------------------------------------------------

  void reportFov(int camera) {
    const tinygltf::Camera& c = model_.cameras[camera];
    if (c.type != "perspective" || !(c.perspective.yfov > 0.0)) return;
    double degrees = std::round(c.perspective.yfov * 180.0 / std::numbers::pi * 1e6) / 1e6;
    // sfrender's --fov range; a yfov from pi is reported with the file's
    // other values (gltf_document.h).
    if (!(degrees >= 0.001 && degrees <= 179.999)) {
      if (c.perspective.yfov < std::numbers::pi) {
        out_.report(loss_, DiagnosticCode::GltfIgnored, {},
                    "the camera's vertical field of view of " + formatNumber(c.perspective.yfov) +
                        " radians is outside what sfrender renders (0.001 to 179.999 degrees), "
                        "and is dropped");
      }
      return;
    }
    View& view = scene_.view.emplace();
    view.verticalFovDegrees = degrees;
    if (c.perspective.aspectRatio > 0.0 && std::isfinite(c.perspective.aspectRatio)) {
      view.aspectRatio = c.perspective.aspectRatio;
    }
    out_.note(DiagnosticCode::CameraFov, {},
              "the camera's vertical field of view is " + formatNumber(degrees) +
                  " degrees, which a scene file cannot hold")
        .hint = "render with sfrender --fov " + formatNumber(degrees);
  }

  void addCamera(int index, const glm::dmat4& world) {
    const tinygltf::Camera& camera = model_.cameras[model_.nodes[index].camera];
    if (haveCamera_) {
      out_.report(loss_, DiagnosticCode::GltfExtraCamera, {},
                  "camera" + quoted(camera.name) + " on " + nodeLabel(model_, index) +
                      " is ignored: a scene file has one CAMERA, the first one found");
      return;
    }
    haveCamera_ = true;
    if (camera.type != "perspective") {
      out_.report(loss_, DiagnosticCode::GltfIgnored, {},
                  "camera" + quoted(camera.name) + " is " + camera.type +
                      "; it becomes a pinhole camera at the same place");
    }
    glm::dvec3 eye(world[3]);
    glm::dvec3 forward = -glm::dvec3(world[2]);
    glm::dvec3 up(world[1]);
    double fl = glm::length(forward);
    if (fl > 0.0) forward /= fl;
    up -= glm::dot(up, forward) * forward;
    double ul = glm::length(up);
    if (ul > 0.0) up /= ul;
    glm::dvec3 right = glm::cross(forward, up);
    scene_.camera.matrix = glm::dmat4(glm::dvec4(right, 0.0), glm::dvec4(up, 0.0),
                                      glm::dvec4(-forward, 0.0), glm::dvec4(eye, 1.0));
    reportFov(model_.nodes[index].camera);
  }

  static gltf::PointLight pointLight(const tinygltf::Light& light) {
    gltf::PointLight out;
    if (light.color.size() == 3) out.color = {light.color[0], light.color[1], light.color[2]};
    out.intensity = light.intensity;
    return out;
  }

  void addLight(int index, int lightIndex, const glm::dmat4& world) {
    const tinygltf::Light& light = model_.lights[lightIndex];
    std::string label = "light" + quoted(light.name) + " on " + nodeLabel(model_, index);
    gltf::PointLight point = pointLight(light);
    glm::dvec3 colour = gltf::colourFromPointLight(point);
    if (!std::isfinite(colour.x + colour.y + colour.z)) colour = glm::dvec3(0.0);
    glm::dmat4 m(1.0);
    m[3] = glm::dvec4(glm::dvec3(world[3]), 1.0);
    if (light.type == "directional") {
      glm::dvec3 direction = -glm::dvec3(world[2]);
      pendingDirectional_.push_back({scene_.lights.size(), direction});
      out_.report(loss_, DiagnosticCode::GltfLightApproximated, {},
                  "directional " + label +
                      " becomes a point light far away against its direction: a scene file has "
                      "point lights only");
    } else if (light.type == "spot") {
      out_.report(loss_, DiagnosticCode::GltfLightApproximated, {},
                  "spot " + label + " becomes a point light: its cone is dropped");
    } else if (light.type != "point") {
      out_.report(
          loss_, DiagnosticCode::GltfLightApproximated, {},
          label + " has the unknown type '" + light.type + "'; it is read as a point light");
    }
    out_.note(DiagnosticCode::LightFalloff, {},
              label +
                  " falls off with the square of the distance; a scene file's LIGHT of colour " +
                  formatNumber(colour.x) + " " + formatNumber(colour.y) + " " +
                  formatNumber(colour.z) + " (colour times intensity) does not fall off");
    scene_.lights.push_back(Light{m, colour, {}});
  }

  void placeDirectionalLights() {
    if (pendingDirectional_.empty()) return;
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    auto add = [&](const glm::dvec3& p) {
      if (std::isfinite(p.x + p.y + p.z)) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
    };
    for (const Object& o : scene_.objects) add(glm::dvec3(o.matrix[3]));
    if (haveCamera_) add(glm::dvec3(scene_.camera.matrix[3]));
    glm::dvec3 centre = lo.x <= hi.x ? 0.5 * (lo + hi) : glm::dvec3(0.0);
    double radius = lo.x <= hi.x ? glm::length(hi - lo) : 1.0;
    for (const auto& [light, direction] : pendingDirectional_) {
      double length = glm::length(direction);
      glm::dvec3 d = length > 0.0 ? direction / length : glm::dvec3(0, -1, 0);
      glm::dvec3 position = centre - d * (100.0 * std::max(radius, 1.0));
      if (!std::isfinite(position.x + position.y + position.z)) {
        out_.error(DiagnosticCode::ValueNotFinite, {},
                   "a directional light becomes a point light 100 scene sizes away, which is "
                   "not finite for a scene this large");
        continue;
      }
      scene_.lights[light].matrix[3] = glm::dvec4(position, 1.0);
    }
  }

  void makeDefaultCamera() {
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (const Object& o : scene_.objects) {
      glm::dvec3 p(o.matrix[3]);
      if (std::isfinite(p.x + p.y + p.z)) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
    }
    glm::dvec3 centre = lo.x <= hi.x ? 0.5 * (lo + hi) : glm::dvec3(0.0);
    double radius = lo.x <= hi.x ? glm::length(hi - lo) / 2 : 0.0;
    glm::dvec3 eye = centre + glm::dvec3(0.0, 0.0, 2.0 * radius + 5.0);
    if (!std::isfinite(eye.x + eye.y + eye.z + radius)) {
      out_.error(DiagnosticCode::ValueNotFinite, {},
                 "the file has no camera, and one on +Z that sees every object would stand "
                 "beyond the largest number");
      return;
    }
    scene_.camera.matrix = cameraFromLookAt(eye, centre);
    out_.report(loss_, DiagnosticCode::GltfNoCamera, {},
                "the file has no camera: CAMERA looks at the scene from +Z");
  }

  // --- Materials ----------------------------------------------------------

  Material material(int index, ObjectKind kind) {
    if (index < 0) return Material{};
    const tinygltf::Material& m = model_.materials[index];
    gltf::PbrMaterial pbr;
    const std::vector<double>& base = m.pbrMetallicRoughness.baseColorFactor;
    if (base.size() == 4) pbr.baseColor = {base[0], base[1], base[2], base[3]};
    pbr.metallic = m.pbrMetallicRoughness.metallicFactor;
    pbr.roughness = m.pbrMetallicRoughness.roughnessFactor;
    pbr.doubleSided = m.doubleSided;
    Json ext = parseOrNull(m.extensions_json_string);
    auto factor = [&ext](const char* extension, const char* key) -> std::optional<double> {
      if (!ext.is_object() || !ext.contains(extension) || !ext[extension].is_object()) {
        return std::nullopt;
      }
      const Json& e = ext[extension];
      if (!e.contains(key)) {
        // The extensions' own defaults.
        if (std::strcmp(key, "ior") == 0) return 1.5;
        if (std::strcmp(key, "specularFactor") == 0) return 1.0;
        return 0.0;
      }
      return number(e[key]);
    };
    pbr.ior = factor("KHR_materials_ior", "ior");
    pbr.transmission = factor("KHR_materials_transmission", "transmissionFactor");
    pbr.specular = factor("KHR_materials_specular", "specularFactor");
    if (std::optional<Material> exact = materialExtras(ownExtras(own_.materials, index))) {
      if (distanceOfPbr(gltf::pbrFromMaterial(*exact, kind), pbr) <= kExtrasAgreement) {
        return *exact;
      }
      out_.note(DiagnosticCode::GltfExtrasStale, {},
                "material " + std::to_string(index) + quoted(m.name) +
                    " no longer matches its extras (the file was edited elsewhere): it is read "
                    "from its glTF values");
    }
    if (reportedMaterials_.insert(index).second) {
      if (m.pbrMetallicRoughness.baseColorTexture.index >= 0) {
        out_.report(loss_, DiagnosticCode::GltfIgnored, {},
                    "material " + std::to_string(index) + quoted(m.name) +
                        ": its base colour texture is ignored; baseColorFactor gives COLOUR");
      }
      if (m.alphaMode != "OPAQUE" && pbr.baseColor[3] < 1.0) {
        out_.report(loss_, DiagnosticCode::GltfIgnored, {},
                    "material " + std::to_string(index) + quoted(m.name) + ": its alpha of " +
                        formatNumber(pbr.baseColor[3]) + " is ignored");
      }
    }
    Material out = gltf::materialFromPbr(pbr);
    for (int i = 0; i < 3; ++i) {
      if (!std::isfinite(out.colour[i])) out.colour[i] = 1.0;
    }
    return out;
  }

  // --- Meshes -------------------------------------------------------------

  // The accessor's elements as doubles, after every bound is checked; an
  // error (or for what is valid but unsupported, a skip) leaves it empty.
  // `limit` bounds the elements of this role over the whole file, of which
  // `read` have been read before; a read adds its own.
  std::optional<std::vector<double>> readAccessor(int index, int wantType,
                                                  std::initializer_list<int> componentTypes,
                                                  const std::string& role, std::size_t limit,
                                                  std::size_t& read, bool& skipped) {
    const tinygltf::Accessor& a = model_.accessors[index];
    std::string label = "accessor " + std::to_string(index) + " (" + role + ")";
    if (a.sparse.isSparse) {
      skipped = true;
      out_.report(loss_, DiagnosticCode::GltfIgnored, {},
                  label + " is sparse, which is not read; its primitive is skipped");
      return std::nullopt;
    }
    if (a.bufferView < 0) {
      skipped = true;
      out_.report(loss_, DiagnosticCode::GltfIgnored, {},
                  label + " has no buffer view (all zeros); its primitive is skipped");
      return std::nullopt;
    }
    if (a.type != wantType ||
        std::find(componentTypes.begin(), componentTypes.end(), a.componentType) ==
            componentTypes.end() ||
        (role == "POSITION" && a.normalized)) {
      out_.error(DiagnosticCode::GltfBadAccessor, {},
                 label + " has the wrong type: " +
                     (role == "POSITION" ? "POSITION must be VEC3 of FLOAT"
                                         : "indices must be SCALAR of unsigned integers"));
      return std::nullopt;
    }
    if (a.count == 0) {
      out_.error(DiagnosticCode::GltfBadAccessor, {}, label + " has a count of 0");
      return std::nullopt;
    }
    if (a.count > limit - read) {
      out_.error(
          DiagnosticCode::GltfTooLarge, {},
          label + " has " + std::to_string(a.count) + " elements; at most " +
              std::to_string(limit) + " are read" +
              (read ? " from a file, and " + std::to_string(read) + " were read before it" : ""));
      return std::nullopt;
    }
    const tinygltf::BufferView& view = model_.bufferViews[a.bufferView];
    const tinygltf::Buffer& buffer = model_.buffers[view.buffer];
    std::size_t bufferSize = buffer.data.size();
    if (view.byteOffset > bufferSize || view.byteLength > bufferSize - view.byteOffset) {
      out_.error(DiagnosticCode::GltfBadAccessor, {},
                 "buffer view " + std::to_string(a.bufferView) + " (bytes " +
                     std::to_string(view.byteOffset) + " + " + std::to_string(view.byteLength) +
                     ") runs past the end of buffer " + std::to_string(view.buffer) + " (" +
                     std::to_string(bufferSize) + " bytes)");
      return std::nullopt;
    }
    int componentSize =
        tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    std::size_t elementSize = static_cast<std::size_t>(componentSize) * components;
    std::size_t stride = view.byteStride ? view.byteStride : elementSize;
    if (view.byteStride && (view.byteStride < elementSize || view.byteStride > 252)) {
      out_.error(DiagnosticCode::GltfBadAccessor, {},
                 "buffer view " + std::to_string(a.bufferView) + " has a byte stride of " +
                     std::to_string(view.byteStride) + ", outside " + std::to_string(elementSize) +
                     " .. 252");
      return std::nullopt;
    }
    // The last element ends at offset + (count - 1) * stride + size; every
    // term is bounded above, so none of this overflows.
    std::size_t end = a.byteOffset;
    bool fits = a.byteOffset <= view.byteLength;
    if (fits) {
      end += (a.count - 1) * stride + elementSize;
      fits = end <= view.byteLength;
    }
    if (!fits) {
      out_.error(DiagnosticCode::GltfBadAccessor, {},
                 label + " (" + std::to_string(a.count) + " elements of " +
                     std::to_string(elementSize) + " bytes from byte " +
                     std::to_string(a.byteOffset) + ") runs past the end of buffer view " +
                     std::to_string(a.bufferView) + " (" + std::to_string(view.byteLength) +
                     " bytes)");
      return std::nullopt;
    }
    const unsigned char* base = buffer.data.data() + view.byteOffset + a.byteOffset;
    std::vector<double> values;
    values.reserve(a.count * components);
    for (std::size_t i = 0; i < a.count; ++i) {
      const unsigned char* e = base + i * stride;
      for (int c = 0; c < components; ++c) {
        const unsigned char* at = e + static_cast<std::size_t>(c) * componentSize;
        switch (a.componentType) {
          case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float f;
            std::memcpy(&f, at, 4);
            values.push_back(f);
            break;
          }
          case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            std::uint32_t u;
            std::memcpy(&u, at, 4);
            values.push_back(u);
            break;
          }
          case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t u;
            std::memcpy(&u, at, 2);
            values.push_back(u);
            break;
          }
          default:
            values.push_back(*at);
            break;
        }
      }
    }
    read += a.count;
    return values;
  }

  // The triangles of one primitive, as indices into its POSITION data.
  struct Triangles {
    std::vector<glm::dvec3> positions;
    std::vector<std::uint32_t> indices;
  };

  std::optional<Triangles> primitiveTriangles(int meshIndex, std::size_t p) {
    const tinygltf::Primitive& prim = model_.meshes[meshIndex].primitives[p];
    std::string label = meshLabel(model_, meshIndex) + " primitive " + std::to_string(p);
    int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      out_.report(loss_, DiagnosticCode::GltfIgnored, {},
                  label + " draws points or lines (mode " + std::to_string(mode) +
                      "), not triangles; it is skipped");
      return std::nullopt;
    }
    if (!prim.targets.empty()) {
      out_.report(loss_, DiagnosticCode::GltfIgnored, {},
                  label + " has morph targets; its base shape is read");
    }
    auto position = prim.attributes.find("POSITION");
    if (position == prim.attributes.end()) {
      out_.report(loss_, DiagnosticCode::GltfIgnored, {},
                  label + " has no POSITION; it is skipped");
      return std::nullopt;
    }
    bool skipped = false;
    std::optional<std::vector<double>> xyz =
        readAccessor(position->second, TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT},
                     "POSITION", maxVertices_, verticesRead_, skipped);
    if (!xyz) return std::nullopt;
    Triangles t;
    for (std::size_t i = 0; i + 2 < xyz->size(); i += 3) {
      glm::dvec3 v((*xyz)[i], (*xyz)[i + 1], (*xyz)[i + 2]);
      if (!std::isfinite(v.x + v.y + v.z)) {
        out_.error(DiagnosticCode::GltfBadAccessor, {},
                   "accessor " + std::to_string(position->second) +
                       " (POSITION) holds a value that is not finite");
        return std::nullopt;
      }
      t.positions.push_back(v);
    }
    std::vector<std::uint32_t> order;
    if (prim.indices >= 0) {
      std::optional<std::vector<double>> raw = readAccessor(
          prim.indices, TINYGLTF_TYPE_SCALAR,
          {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
           TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
          "indices", maxIndices_, indicesRead_, skipped);
      if (!raw) return std::nullopt;
      for (double v : *raw) {
        if (v >= static_cast<double>(t.positions.size())) {
          out_.error(DiagnosticCode::GltfIndexOutOfRange, {},
                     "accessor " + std::to_string(prim.indices) + " (indices of " + label +
                         ") holds the index " + formatNumber(v) + ", but POSITION has " +
                         std::to_string(t.positions.size()) + " vertices");
          return std::nullopt;
        }
        order.push_back(static_cast<std::uint32_t>(v));
      }
    } else {
      for (std::size_t i = 0; i < t.positions.size(); ++i) {
        order.push_back(static_cast<std::uint32_t>(i));
      }
    }
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      order.resize(order.size() - order.size() % 3);
      t.indices = std::move(order);
    } else {
      for (std::size_t i = 2; i < order.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
          t.indices.insert(t.indices.end(), {order[0], order[i - 1], order[i]});
        } else if (i % 2 == 0) {
          t.indices.insert(t.indices.end(), {order[i - 2], order[i - 1], order[i]});
        } else {
          t.indices.insert(t.indices.end(), {order[i - 1], order[i - 2], order[i]});
        }
      }
    }
    return t;
  }

  // Fits a mesh once, however many nodes use it: all its primitives as one
  // shape first (an exporter splits a mesh by material), else each alone.
  const std::vector<FittedPart>& fitMesh(int meshIndex, int nodeIndex) {
    auto cached = fitted_.find(meshIndex);
    if (cached != fitted_.end()) return cached->second;
    std::vector<FittedPart>& parts = fitted_[meshIndex];
    const tinygltf::Mesh& mesh = model_.meshes[meshIndex];
    std::vector<Triangles> each;
    std::vector<int> materials;
    Triangles all;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      std::optional<Triangles> t = primitiveTriangles(meshIndex, p);
      if (out_.hasErrors()) return parts;
      if (!t) continue;
      auto first = static_cast<std::uint32_t>(all.positions.size());
      all.positions.insert(all.positions.end(), t->positions.begin(), t->positions.end());
      for (std::uint32_t i : t->indices) all.indices.push_back(first + i);
      each.push_back(std::move(*t));
      materials.push_back(mesh.primitives[p].material);
    }
    if (each.empty()) return parts;
    std::string label = meshLabel(model_, meshIndex) + " (on " + nodeLabel(model_, nodeIndex) + ")";
    FitResult whole = fitPrimitive(all.positions, all.indices);
    if (whole.fit) {
      parts.push_back({*whole.fit, materials[0]});
      if (std::set<int>(materials.begin(), materials.end()).size() > 1) {
        out_.report(loss_, DiagnosticCode::GltfIgnored, {},
                    label + " has " + std::to_string(materials.size()) +
                        " materials; the first one colours the whole " +
                        std::string(objectKindName(whole.fit->kind)));
      }
      reportFit(label, *whole.fit);
      return parts;
    }
    if (each.size() > 1) {
      bool allFit = true;
      std::vector<FittedPart> separate;
      for (std::size_t i = 0; i < each.size() && allFit; ++i) {
        FitResult r = fitPrimitive(each[i].positions, each[i].indices);
        if (r.fit) separate.push_back({*r.fit, materials[i]});
        allFit = r.fit.has_value();
      }
      if (allFit) {
        for (const FittedPart& part : separate) reportFit(label, part.fit);
        parts = std::move(separate);
        return parts;
      }
    }
    out_.report(loss_, DiagnosticCode::GltfMeshNotPrimitive, {},
                label + " is not a sphere, box, cylinder or plane (" + whole.reason +
                    "); it is skipped")
        .hint = "the tolerance is " + formatNumber(kFitTolerance) +
                " of the shape's size; see docs/GLTF.md";
    return parts;
  }

  void reportFit(const std::string& label, const MeshFit& fit) {
    out_.note(DiagnosticCode::GltfMeshFit, {},
              label + " is read as a " + std::string(objectKindName(fit.kind)) +
                  " (largest deviation " + deviationText(fit.error) + " of its size)");
  }

  void addMeshObjects(int index, const glm::dmat4& world) {
    const std::vector<FittedPart>& parts = fitMesh(model_.nodes[index].mesh, index);
    for (const FittedPart& part : parts) {
      Object object;
      object.kind = part.fit.kind;
      object.matrix = world * part.fit.shape;
      if (!finite(object.matrix)) {
        out_.error(DiagnosticCode::ValueNotFinite, {},
                   "/nodes/" + std::to_string(index) + " (" + nodeLabel(model_, index) + "): its " +
                       std::string(objectKindName(part.fit.kind)) +
                       " has a matrix that is not finite (the node's transform times the mesh's "
                       "size and place overflows)");
        return;
      }
      object.material = material(part.material, part.fit.kind);
      if (!roomForOne(index)) return;
      scene_.objects.push_back(std::move(object));
    }
  }

  // Whether one more object or light fits under maxObjects; when not,
  // reports too-many-objects on the node and stops the walk.
  bool roomForOne(int node) {
    if (stopped_) return false;
    if (scene_.objects.size() + scene_.lights.size() < maxObjects_) return true;
    // glTF has no lines to point at: the message names the node instead.
    reportTooManyObjects({}, maxObjects_, out_).message =
        "the file has more than " + std::to_string(maxObjects_) +
        " objects and lights: reading stops at " + nodeLabel(model_, node);
    stopped_ = true;
    return false;
  }

  const tinygltf::Model& model_;
  const gltf::OwnExtras& own_;
  Scene& scene_;
  DiagnosticList& out_;
  Severity loss_;
  bool haveCamera_ = false;
  std::map<int, std::vector<FittedPart>> fitted_;
  std::map<std::pair<int, ObjectKind>, bool> writtenMesh_;
  std::set<int> reportedMaterials_;
  std::vector<std::pair<std::size_t, glm::dvec3>> pendingDirectional_;
  std::size_t maxObjects_;
  bool stopped_ = false;  // past maxObjects: the walk ends
  // POSITION vertices and indices allowed in the whole file, and read so far.
  std::size_t maxVertices_;
  std::size_t maxIndices_;
  std::size_t verticesRead_ = 0;
  std::size_t indicesRead_ = 0;
};

}  // namespace

bool looksLikeGlb(std::string_view bytes) {
  return bytes.starts_with(kGlbMagic);
}

bool looksLikeGltfJson(std::string_view bytes) {
  if (bytes.starts_with("\xEF\xBB\xBF")) bytes.remove_prefix(3);
  for (char c : bytes) {
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n') continue;
    return c == '{';
  }
  return false;
}

ReadResult parseGltf(std::string_view bytes, std::string fileName, const fs::path& folder,
                     const ReadOptions& options) {
  ReadResult result{Scene{}, DiagnosticList(fileName, options.errorLimit)};
  DiagnosticList& out = result.diagnostics;
  if (!checkFileSize(bytes.size(), options, out)) return result;
  bool binary = looksLikeGlb(bytes);
  std::string_view jsonText = bytes;
  std::optional<std::string_view> bin;
  if (binary) {
    std::string why;
    std::optional<GlbChunks> chunks = decodeGlb(bytes, why);
    if (!chunks) {
      out.error(DiagnosticCode::GltfInvalidGlb, {}, "not a valid GLB file: " + why);
      return result;
    }
    jsonText = chunks->json;
    bin = chunks->bin;
  } else if (jsonText.starts_with("\xEF\xBB\xBF")) {
    jsonText.remove_prefix(3);
  }
  auto jsonSpan = [&](std::size_t byte) {
    return binary ? SourceSpan{} : spanAtByte(bytes, byte + (bytes.size() - jsonText.size()));
  };
  if (std::optional<std::size_t> deep = tooDeep(jsonText)) {
    out.error(DiagnosticCode::GltfInvalidJson, jsonSpan(*deep),
              "the JSON nests deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    return result;
  }
  // Counted in the bytes, before anything is parsed: a node costs three
  // bytes of text and hundreds in memory.
  if (!withinObjectLimit(gltf::countTopLevelObjects(jsonText), options, out)) return result;
  Json doc;
  try {
    doc = Json::parse(jsonText);
  } catch (const Json::parse_error& e) {
    std::size_t at = e.byte > 0 ? e.byte - 1 : 0;
    out.error(
        DiagnosticCode::GltfInvalidJson, jsonSpan(at),
        std::string(binary ? "the GLB's JSON chunk is not valid JSON: " : "not valid JSON: ") +
            parseErrorMessage(e.what()));
    return result;
  } catch (const Json::out_of_range& e) {
    // A number past a double's range (1e400) is refused by nlohmann as
    // out_of_range, not as a parse error, and carries no position.
    std::string what = e.what();
    std::size_t bracket = what.find("] ");
    out.error(
        DiagnosticCode::GltfInvalidJson, {},
        std::string(binary ? "the GLB's JSON chunk is not valid JSON: " : "not valid JSON: ") +
            (bracket == std::string::npos ? what : what.substr(bracket + 2)));
    return result;
  }
  if (!doc.is_object()) {
    out.error(DiagnosticCode::GltfInvalid, {}, "the JSON is not an object, so it is no glTF");
    return result;
  }
  // glTF 2.0 only.
  const Json* asset = doc.contains("asset") && doc["asset"].is_object() ? &doc["asset"] : nullptr;
  if (!asset || !asset->contains("version") || !(*asset)["version"].is_string()) {
    out.error(DiagnosticCode::GltfInvalid, {}, "the file has no asset.version, so it is no glTF");
    return result;
  }
  std::string version = (*asset)["version"].get<std::string>();
  if (!version.starts_with("2.")) {
    out.error(DiagnosticCode::GltfInvalid, {},
              "asset.version is '" + version + "'; only glTF 2.0 is read");
    return result;
  }
  if (!withinObjectLimit(gltf::countObjects(doc), options, out)) return result;
  gltf::reportProblems(gltf::checkDocument(doc, options.noLoss),
                       binary ? std::string_view{} : bytes, bytes.size() - jsonText.size(), out);
  if (out.hasErrors()) return result;
  if (doc.contains("extensionsRequired") && doc["extensionsRequired"].is_array()) {
    for (const Json& name : doc["extensionsRequired"]) {
      if (name.is_string() && !kReadableRequired.count(name.get<std::string>())) {
        out.error(
            DiagnosticCode::GltfUnsupportedExtension, {},
            "the file requires the extension " + name.get<std::string>() + ", which is not read");
      }
    }
    if (out.hasErrors()) return result;
  }
  if (doc.contains("buffers") && doc["buffers"].is_array()) {
    for (std::size_t i = 0; i < doc["buffers"].size(); ++i) {
      const Json& b = doc["buffers"][i];
      if (!b.is_object() || !b.contains("uri") || !b["uri"].is_string()) continue;
      std::string uri = b["uri"].get<std::string>();
      std::string shown = uri.size() > 80 ? uri.substr(0, 77) + "..." : uri;
      fs::path target;
      if (std::optional<std::string> problem = uriProblem(uri, folder, target)) {
        out.error(DiagnosticCode::GltfExternalFile, {},
                  "buffer " + std::to_string(i) + "'s uri '" + shown + "' " + *problem);
        continue;
      }
      std::error_code sizeError;
      std::uintmax_t size = uri.starts_with("data:") ? 0 : fs::file_size(target, sizeError);
      if (!sizeError && size > options.maxFileSize) {
        out.error(DiagnosticCode::FileTooLarge, {},
                  "buffer " + std::to_string(i) + "'s file '" + shown + "' is " +
                      std::to_string(size) + " bytes, more than the limit of " +
                      std::to_string(options.maxFileSize))
            .hint = "raise the limit with --max-file-size if the file is meant to be this large";
      }
    }
    if (out.hasErrors()) return result;
  }
  std::optional<std::string> outputFile;
  if (asset->contains("extras")) {
    const Json* sf = sfExtras((*asset)["extras"]);
    if (sf && sf->contains("outputFile") && (*sf)["outputFile"].is_string()) {
      outputFile = (*sf)["outputFile"].get<std::string>();
    }
  }
  // Images are never needed: tinygltf does not even see them, nor any
  // extras or extension that is not read; the document is let go before
  // tinygltf parses its own.
  doc.erase("images");
  gltf::OwnExtras own = gltf::trimForTinygltf(doc);
  std::string cleaned = doc.dump();
  doc = Json();

  tinygltf::TinyGLTF loader;
  Confinement confinement;
  std::error_code ec;
  confinement.folder =
      fs::weakly_canonical(fs::absolute(folder.empty() ? fs::path(".") : folder), ec);
  confinement.maxFileSize = options.maxFileSize;
  loader.SetFsCallbacks({&confinedExists, &unexpandedPath, &confinedRead, &noWrite, &confinement});
  loader.SetImageLoader(&noImageDecoding, nullptr);
  loader.SetStoreOriginalJSONForExtrasAndExtensions(true);
  tinygltf::Model model;
  std::string err;
  std::string warn;
  bool loaded = false;
  try {
    if (binary) {
      std::string glb = encodeGlb(cleaned, bin.value_or(std::string_view{}));
      loaded = loader.LoadBinaryFromMemory(
          &model, &err, &warn, reinterpret_cast<const unsigned char*>(glb.data()),
          static_cast<unsigned int>(glb.size()), confinement.folder.string());
    } else {
      loaded = loader.LoadASCIIFromString(&model, &err, &warn, cleaned.data(),
                                          static_cast<unsigned int>(cleaned.size()),
                                          confinement.folder.string());
    }
  } catch (const std::bad_alloc&) {
    // Out of memory is no property of the file: the tools report it.
    throw;
  } catch (const std::exception& e) {
    err = e.what();
    loaded = false;
  }
  // tinygltf catches what its JSON parser throws, std::bad_alloc too, and
  // returns its text: that is no fault of the file, and goes on as itself.
  if (!loaded && err.starts_with(std::bad_alloc().what())) throw std::bad_alloc();
  if (!loaded) {
    out.error(DiagnosticCode::GltfInvalid, {}, "not a valid glTF 2.0 file: " + firstLine(err));
    return result;
  }

  Importer importer(model, own, options, result);
  importer.run();
  if (out.hasErrors()) return result;
  // What the file gave must hold as a scene file's values would.
  DiagnosticList checked = validateScene(result.scene, fileName);
  out.append(checked);
  if (outputFile) result.scene.outputFile = *outputFile;
  return result;
}

}  // namespace scene
