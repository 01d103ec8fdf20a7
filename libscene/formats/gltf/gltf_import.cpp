#include "libscene/formats/gltf/gltf_import.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <glm/matrix.hpp>
#include <optional>
#include <utility>

#include "libscene/text/reader_support.h"

namespace scene::gltf {

namespace {

// checkDocument (gltf_document.h) has made sure that each property is
// absent or whole, and that a rotation is a unit quaternion to within a
// tolerance, which is normalised away here.
glm::dmat4 localMatrix(const tinygltf::Node& node) {
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
    q /= glm::length(q);
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

}  // namespace

Importer::Importer(const tinygltf::Model& model, const OwnExtras& own, const ReadOptions& options,
                   ReadResult& result)
    : c_{model, own, result.scene, result.diagnostics,
         options.noLoss ? Severity::Error : Severity::Warning},
      camerasAndLights_(c_),
      materials_(c_),
      meshes_(c_, options),
      maxObjects_(options.maxObjects) {}

void Importer::run() {
  if (!checkIndices()) return;
  if (!c_.model.animations.empty()) {
    c_.out.report(c_.loss, DiagnosticCode::GltfIgnored, {},
                  std::to_string(c_.model.animations.size()) +
                      " animation(s) are ignored: a scene file is a still");
  }
  if (!c_.model.skins.empty()) {
    c_.out.report(c_.loss, DiagnosticCode::GltfIgnored, {},
                  std::to_string(c_.model.skins.size()) +
                      " skin(s) are ignored: meshes are read in their rest pose");
  }
  std::vector<int> roots = rootNodes();
  if (c_.out.hasErrors()) return;
  walk(roots);
  if (c_.out.hasErrors()) return;
  camerasAndLights_.finish();
  restoreObjectOrder();
}

// Objects read from our own extras carry their number in the scene: when
// every object has one, and no two the same, they go back into that order,
// which a program that moved nodes (instancing gathers a mesh's nodes into
// one) has changed.
void Importer::restoreObjectOrder() {
  std::vector<Object>& objects = c_.scene.objects;
  if (numbers_.size() != objects.size()) return;
  std::vector<std::size_t> order(objects.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [this](std::size_t a, std::size_t b) { return numbers_[a] < numbers_[b]; });
  for (std::size_t i = 1; i < order.size(); ++i) {
    if (numbers_[order[i]] == numbers_[order[i - 1]]) return;
  }
  std::vector<Object> sorted;
  sorted.reserve(objects.size());
  for (std::size_t i : order) sorted.push_back(std::move(objects[i]));
  objects = std::move(sorted);
}

// --- Indices ----------------------------------------------------------------

bool Importer::index(int value, std::size_t size, const std::string& where, const std::string& what,
                     bool optional) {
  if (value < 0 && optional && value == -1) return true;
  if (value >= 0 && static_cast<std::size_t>(value) < size) return true;
  c_.out.error(DiagnosticCode::GltfIndexOutOfRange, {},
               where + " points at " + what + " " + std::to_string(value) + ", but the file has " +
                   std::to_string(size));
  return false;
}

bool Importer::checkIndices() {
  const tinygltf::Model& m = c_.model;
  bool ok = true;
  if (m.defaultScene != -1) ok &= index(m.defaultScene, m.scenes.size(), "scene", "scene");
  for (std::size_t s = 0; s < m.scenes.size(); ++s) {
    for (int n : m.scenes[s].nodes) {
      ok &= index(n, m.nodes.size(), "scenes[" + std::to_string(s) + "]", "node", false);
    }
  }
  for (std::size_t i = 0; i < m.nodes.size() && !c_.out.full(); ++i) {
    const tinygltf::Node& node = m.nodes[i];
    std::string where = "nodes[" + std::to_string(i) + "]";
    for (int c : node.children) ok &= index(c, m.nodes.size(), where + ".children", "node", false);
    ok &= index(node.mesh, m.meshes.size(), where + ".mesh", "mesh");
    ok &= index(node.camera, m.cameras.size(), where + ".camera", "camera");
    int light = nodeLight(m, static_cast<int>(i));
    if (light != -1)
      ok &= index(light, m.lights.size(), where + " KHR_lights_punctual", "light", false);
  }
  for (std::size_t i = 0; i < m.meshes.size() && !c_.out.full(); ++i) {
    for (std::size_t p = 0; p < m.meshes[i].primitives.size(); ++p) {
      const tinygltf::Primitive& prim = m.meshes[i].primitives[p];
      std::string where = "meshes[" + std::to_string(i) + "].primitives[" + std::to_string(p) + "]";
      auto position = prim.attributes.find("POSITION");
      if (position != prim.attributes.end()) {
        ok &= index(position->second, m.accessors.size(), where + ".attributes.POSITION",
                    "accessor", false);
      }
      ok &= index(prim.indices, m.accessors.size(), where + ".indices", "accessor");
      ok &= index(prim.material, m.materials.size(), where + ".material", "material");
    }
  }
  for (std::size_t i = 0; i < m.accessors.size() && !c_.out.full(); ++i) {
    ok &= index(m.accessors[i].bufferView, m.bufferViews.size(),
                "accessors[" + std::to_string(i) + "].bufferView", "buffer view");
  }
  for (std::size_t i = 0; i < m.bufferViews.size() && !c_.out.full(); ++i) {
    ok &= index(m.bufferViews[i].buffer, m.buffers.size(),
                "bufferViews[" + std::to_string(i) + "].buffer", "buffer", false);
  }
  return ok;
}

// --- The hierarchy ----------------------------------------------------------

std::vector<int> Importer::rootNodes() {
  const tinygltf::Model& m = c_.model;
  if (!m.scenes.empty()) {
    int scene = m.defaultScene >= 0 ? m.defaultScene : 0;
    if (m.scenes.size() > 1) {
      c_.out.note(DiagnosticCode::GltfIgnored, {},
                  "the file has " + std::to_string(m.scenes.size()) + " scenes; scene " +
                      std::to_string(scene) + " is read");
    }
    return m.scenes[scene].nodes;
  }
  // No scene: every node that is nobody's child.
  std::vector<bool> child(m.nodes.size(), false);
  for (const tinygltf::Node& node : m.nodes) {
    for (int c : node.children) child[c] = true;
  }
  std::vector<int> roots;
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    if (!child[i]) roots.push_back(static_cast<int>(i));
  }
  return roots;
}

// Depth first, children in order, with an explicit stack: a deep or
// cyclic hierarchy costs no recursion.
void Importer::walk(const std::vector<int>& roots) {
  std::vector<bool> seen(c_.model.nodes.size(), false);
  std::vector<std::pair<int, glm::dmat4>> stack;
  for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, glm::dmat4(1.0));
  while (!stack.empty() && !c_.out.full() && !stopped_) {
    auto [node, parent] = stack.back();
    stack.pop_back();
    if (seen[node]) {
      c_.out.error(
          DiagnosticCode::GltfNodeCycle, {},
          nodeLabel(c_.model, node) +
              " is reached twice: the node hierarchy has a cycle or a node with two parents");
      return;
    }
    seen[node] = true;
    glm::dmat4 world = parent * localMatrix(c_.model.nodes[node]);
    // Finite values can compose to infinity: the error names the node
    // where it happens, not a record far from it.
    if (!finite(world)) {
      c_.out.error(DiagnosticCode::ValueNotFinite, {},
                   "/nodes/" + std::to_string(node) + " (" + nodeLabel(c_.model, node) +
                       "): its transform composed with its parents' is not finite");
      return;
    }
    visit(node, world);
    const std::vector<int>& children = c_.model.nodes[node].children;
    for (auto it = children.rbegin(); it != children.rend(); ++it) stack.emplace_back(*it, world);
  }
}

void Importer::visit(int index, const glm::dmat4& world) {
  const tinygltf::Node& node = c_.model.nodes[index];
  // A node holds at most one light, counted here, and one mesh, whose
  // objects are counted as they are added (roomForOne).
  if (nodeLight(c_.model, index) >= 0 && !roomForOne(index)) return;
  // Each instance is an object: no more are read than maxObjects allows.
  std::optional<std::vector<glm::dmat4>> instances = meshes_.instanceMatrices(
      index, maxObjects_ - std::min(maxObjects_, c_.scene.objects.size() + c_.scene.lights.size()));
  if (c_.out.hasErrors()) return;
  std::optional<RecordExtras> extras = recordExtras(ownExtras(c_.own.nodes, index));
  // Our writer never instances: a node that does is not the one its
  // extras describe.
  if (extras && !instances) {
    if (useExtras(index, world, *extras)) return;
    c_.out.note(DiagnosticCode::GltfExtrasStale, {},
                nodeLabel(c_.model, index) + " no longer matches the " + extras->record +
                    " that its extras describe (the file was edited elsewhere): the node is read "
                    "as it is");
  }
  if (node.camera >= 0) camerasAndLights_.addCamera(index, world);
  int light = nodeLight(c_.model, index);
  if (light >= 0) camerasAndLights_.addLight(index, light, world);
  if (node.mesh < 0) return;
  if (!instances) {
    addMeshObjects(index, world);
    return;
  }
  for (std::size_t i = 0; i < instances->size() && !c_.out.hasErrors() && !stopped_; ++i) {
    addInstance(index, i, world * (*instances)[i]);
  }
}

// One instance of a mesh (EXT_mesh_gpu_instancing), which stands where one
// of the objects its extras describe stood, when the mesh is still their
// kind's: then that object, exactly; else the mesh fitted like any other.
void Importer::addInstance(int index, std::size_t instance, const glm::dmat4& world) {
  int mesh = c_.model.nodes[index].mesh;
  auto [cached, fresh] = meshRecords_.emplace(mesh, std::vector<RecordExtras>{});
  if (fresh) cached->second = meshRecords(ownExtras(c_.own.meshes, mesh));
  std::vector<RecordExtras>& records = cached->second;
  auto best = records.end();
  double nearest = kInstanceAgreement;
  for (auto it = records.begin(); it != records.end(); ++it) {
    double d = instanceDistance(withinFloatRange(it->matrix), world);
    if (d <= nearest) {
      nearest = d;
      best = it;
    }
  }
  if (best != records.end() && c_.model.meshes[mesh].primitives.size() == 1 &&
      meshes_.holdsWrittenMesh(mesh, *objectKindFromName(best->record))) {
    Object object;
    object.kind = *objectKindFromName(best->record);
    object.matrix = best->matrix;
    object.transforms = best->transforms;
    object.material =
        materials_.material(c_.model.meshes[mesh].primitives[0].material, object.kind);
    if (!roomForOne(index)) return;
    c_.scene.objects.push_back(std::move(object));
    if (best->object) numbers_.push_back(*best->object);
    // Each object stands once.
    records.erase(best);
    return;
  }
  if (!records.empty()) {
    c_.out.note(DiagnosticCode::GltfExtrasStale, {},
                nodeLabel(c_.model, index) + " instance " + std::to_string(instance) +
                    " matches none of the objects that its mesh's extras describe (the file was "
                    "edited elsewhere): the instance is read as it is");
  }
  addMeshObjects(index, world);
}

// --- Records ----------------------------------------------------------------

// The node's record exactly as our own extras hold it, while they still
// describe the node; false, and nothing added, when they do not.
bool Importer::useExtras(int index, const glm::dmat4& world, const RecordExtras& extras) {
  if (extras.record == "CAMERA") return camerasAndLights_.cameraFromExtras(index, world, extras);
  if (extras.record == "LIGHT") return camerasAndLights_.lightFromExtras(index, world, extras);
  const tinygltf::Node& node = c_.model.nodes[index];
  ObjectKind kind = *objectKindFromName(extras.record);
  if (node.mesh < 0 || c_.model.meshes[node.mesh].primitives.size() != 1 ||
      matrixDistance(withinFloatRange(extras.matrix), world) > kExtrasAgreement ||
      !meshes_.holdsWrittenMesh(node.mesh, kind)) {
    return false;
  }
  Object object;
  object.kind = kind;
  object.matrix = extras.matrix;
  object.transforms = extras.transforms;
  object.material = materials_.material(c_.model.meshes[node.mesh].primitives[0].material, kind);
  if (roomForOne(index)) {
    c_.scene.objects.push_back(std::move(object));
    if (extras.object) numbers_.push_back(*extras.object);
  }
  return true;
}

void Importer::addMeshObjects(int index, const glm::dmat4& world) {
  const std::vector<FittedPart>& parts = meshes_.fitMesh(c_.model.nodes[index].mesh, index);
  for (const FittedPart& part : parts) {
    Object object;
    object.kind = part.fit.kind;
    object.matrix = world * part.fit.shape;
    if (!finite(object.matrix)) {
      c_.out.error(DiagnosticCode::ValueNotFinite, {},
                   "/nodes/" + std::to_string(index) + " (" + nodeLabel(c_.model, index) +
                       "): its " + std::string(objectKindName(part.fit.kind)) +
                       " has a matrix that is not finite (the node's transform times the mesh's "
                       "size and place overflows)");
      return;
    }
    object.material = materials_.material(part.material, part.fit.kind);
    if (!roomForOne(index)) return;
    c_.scene.objects.push_back(std::move(object));
  }
}

// Whether one more object or light fits under maxObjects; when not,
// reports too-many-objects on the node and stops the walk.
bool Importer::roomForOne(int node) {
  if (stopped_) return false;
  if (c_.scene.objects.size() + c_.scene.lights.size() < maxObjects_) return true;
  // glTF has no lines to point at: the message names the node instead.
  reportTooManyObjects({}, maxObjects_, c_.out).message =
      "the file has more than " + std::to_string(maxObjects_) +
      " objects and lights: reading stops at " + nodeLabel(c_.model, node);
  stopped_ = true;
  return false;
}

}  // namespace scene::gltf
