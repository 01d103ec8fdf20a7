#include "libscene/formats/gltf/gltf_meshes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <glm/gtc/quaternion.hpp>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>

#include "libscene/formats/gltf/gltf_document.h"
#include "libscene/formats/gltf/gltf_extras.h"
#include "libscene/text/number.h"

namespace scene::gltf {

namespace {

std::string deviationText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2g", value);
  return text;
}

}  // namespace

MeshReader::MeshReader(const ImportContext& context, const ReadOptions& options)
    : c_(context),
      maxVertices_(options.gltf.maxVertices),
      maxIndices_(options.gltf.maxVertices > std::numeric_limits<std::size_t>::max() / 3
                      ? std::numeric_limits<std::size_t>::max()
                      : 3 * options.gltf.maxVertices) {}

// The accessor's elements as doubles, after every bound is checked; an
// error (or for what is valid but unsupported, a skip) leaves it empty.
// `limit` bounds the elements of this role over the whole file, of which
// `read` have been read before; a read adds its own.
std::optional<std::vector<double>> MeshReader::readAccessor(
    int index, int wantType, std::initializer_list<int> componentTypes, const std::string& role,
    std::size_t limit, std::size_t& read, bool& skipped) {
  if (!accessorReadable(index, wantType, componentTypes, role, limit, read, skipped)) {
    return std::nullopt;
  }
  std::optional<Layout> layout = accessorLayout(index, role);
  if (!layout) return std::nullopt;
  const tinygltf::Accessor& a = c_.model.accessors[index];
  std::vector<double> values;
  values.reserve(a.count * layout->components);
  for (std::size_t i = 0; i < a.count; ++i) {
    const unsigned char* e = layout->base + i * layout->stride;
    for (int c = 0; c < layout->components; ++c) {
      const unsigned char* at = e + static_cast<std::size_t>(c) * layout->componentSize;
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

// What the accessor says of itself: stored, of the type its role needs,
// and within the file's limit for the role.
bool MeshReader::accessorReadable(int index, int wantType,
                                  std::initializer_list<int> componentTypes,
                                  const std::string& role, std::size_t limit, std::size_t read,
                                  bool& skipped) {
  const tinygltf::Accessor& a = c_.model.accessors[index];
  std::string label = "accessor " + std::to_string(index) + " (" + role + ")";
  if (a.sparse.isSparse) {
    skipped = true;
    c_.out.report(c_.loss, DiagnosticCode::GltfIgnored, {},
                  label + " is sparse, which is not read; its primitive is skipped");
    return false;
  }
  if (a.bufferView < 0) {
    skipped = true;
    c_.out.report(c_.loss, DiagnosticCode::GltfIgnored, {},
                  label + " has no buffer view (all zeros); its primitive is skipped");
    return false;
  }
  if (a.type != wantType ||
      std::find(componentTypes.begin(), componentTypes.end(), a.componentType) ==
          componentTypes.end() ||
      (role == "POSITION" && a.normalized)) {
    c_.out.error(DiagnosticCode::GltfBadAccessor, {},
                 label + " has the wrong type: " +
                     (role == "POSITION" ? "POSITION must be VEC3 of FLOAT"
                                         : "indices must be SCALAR of unsigned integers"));
    return false;
  }
  if (a.count == 0) {
    c_.out.error(DiagnosticCode::GltfBadAccessor, {}, label + " has a count of 0");
    return false;
  }
  if (a.count > limit - read) {
    c_.out.error(
        DiagnosticCode::GltfTooLarge, {},
        label + " has " + std::to_string(a.count) + " elements; at most " + std::to_string(limit) +
            " are read" +
            (read ? " from a file, and " + std::to_string(read) + " were read before it" : ""));
    return false;
  }
  return true;
}

// Where the elements lie, once the view lies within its buffer and every
// element within its view.
std::optional<MeshReader::Layout> MeshReader::accessorLayout(int index, const std::string& role) {
  const tinygltf::Accessor& a = c_.model.accessors[index];
  std::string label = "accessor " + std::to_string(index) + " (" + role + ")";
  const tinygltf::BufferView& view = c_.model.bufferViews[a.bufferView];
  const tinygltf::Buffer& buffer = c_.model.buffers[view.buffer];
  std::size_t bufferSize = buffer.data.size();
  if (view.byteOffset > bufferSize || view.byteLength > bufferSize - view.byteOffset) {
    c_.out.error(DiagnosticCode::GltfBadAccessor, {},
                 "buffer view " + std::to_string(a.bufferView) + " (bytes " +
                     std::to_string(view.byteOffset) + " + " + std::to_string(view.byteLength) +
                     ") runs past the end of buffer " + std::to_string(view.buffer) + " (" +
                     std::to_string(bufferSize) + " bytes)");
    return std::nullopt;
  }
  Layout layout;
  layout.componentSize =
      tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
  layout.components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
  std::size_t elementSize = static_cast<std::size_t>(layout.componentSize) * layout.components;
  layout.stride = view.byteStride ? view.byteStride : elementSize;
  if (view.byteStride && (view.byteStride < elementSize || view.byteStride > 252)) {
    c_.out.error(DiagnosticCode::GltfBadAccessor, {},
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
    end += (a.count - 1) * layout.stride + elementSize;
    fits = end <= view.byteLength;
  }
  if (!fits) {
    c_.out.error(DiagnosticCode::GltfBadAccessor, {},
                 label + " (" + std::to_string(a.count) + " elements of " +
                     std::to_string(elementSize) + " bytes from byte " +
                     std::to_string(a.byteOffset) + ") runs past the end of buffer view " +
                     std::to_string(a.bufferView) + " (" + std::to_string(view.byteLength) +
                     " bytes)");
    return std::nullopt;
  }
  layout.base = buffer.data.data() + view.byteOffset + a.byteOffset;
  return layout;
}

std::optional<MeshReader::Triangles> MeshReader::primitiveTriangles(int mesh, std::size_t p) {
  const tinygltf::Primitive& prim = c_.model.meshes[mesh].primitives[p];
  std::string label = meshLabel(c_.model, mesh) + " primitive " + std::to_string(p);
  int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
  if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
      mode != TINYGLTF_MODE_TRIANGLE_FAN) {
    c_.out.report(c_.loss, DiagnosticCode::GltfIgnored, {},
                  label + " draws points or lines (mode " + std::to_string(mode) +
                      "), not triangles; it is skipped");
    return std::nullopt;
  }
  if (!prim.targets.empty()) {
    c_.out.report(c_.loss, DiagnosticCode::GltfIgnored, {},
                  label + " has morph targets; its base shape is read");
  }
  auto position = prim.attributes.find("POSITION");
  if (position == prim.attributes.end()) {
    c_.out.report(c_.loss, DiagnosticCode::GltfIgnored, {},
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
      c_.out.error(DiagnosticCode::GltfBadAccessor, {},
                   "accessor " + std::to_string(position->second) +
                       " (POSITION) holds a value that is not finite");
      return std::nullopt;
    }
    t.positions.push_back(v);
  }
  std::optional<std::vector<std::uint32_t>> order =
      vertexOrder(prim.indices, t.positions.size(), label);
  if (!order) return std::nullopt;
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    order->resize(order->size() - order->size() % 3);
    t.indices = std::move(*order);
  } else {
    for (std::size_t i = 2; i < order->size(); ++i) {
      const std::vector<std::uint32_t>& o = *order;
      if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        t.indices.insert(t.indices.end(), {o[0], o[i - 1], o[i]});
      } else if (i % 2 == 0) {
        t.indices.insert(t.indices.end(), {o[i - 2], o[i - 1], o[i]});
      } else {
        t.indices.insert(t.indices.end(), {o[i - 1], o[i - 2], o[i]});
      }
    }
  }
  return t;
}

// The primitive's vertices in drawing order: its indices, each checked
// against the `vertices` of its POSITION, or without indices every vertex.
std::optional<std::vector<std::uint32_t>> MeshReader::vertexOrder(int indices, std::size_t vertices,
                                                                  const std::string& label) {
  std::vector<std::uint32_t> order;
  if (indices < 0) {
    for (std::size_t i = 0; i < vertices; ++i) order.push_back(static_cast<std::uint32_t>(i));
    return order;
  }
  bool skipped = false;
  std::optional<std::vector<double>> raw =
      readAccessor(indices, TINYGLTF_TYPE_SCALAR,
                   {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                   "indices", maxIndices_, indicesRead_, skipped);
  if (!raw) return std::nullopt;
  for (double v : *raw) {
    if (v >= static_cast<double>(vertices)) {
      c_.out.error(DiagnosticCode::GltfIndexOutOfRange, {},
                   "accessor " + std::to_string(indices) + " (indices of " + label +
                       ") holds the index " + formatNumber(v) + ", but POSITION has " +
                       std::to_string(vertices) + " vertices");
      return std::nullopt;
    }
    order.push_back(static_cast<std::uint32_t>(v));
  }
  return order;
}

const std::vector<FittedPart>& MeshReader::fitMesh(int meshIndex, int nodeIndex) {
  auto cached = fitted_.find(meshIndex);
  if (cached != fitted_.end()) return cached->second;
  std::vector<FittedPart>& parts = fitted_[meshIndex];
  const tinygltf::Mesh& mesh = c_.model.meshes[meshIndex];
  std::vector<Triangles> each;
  std::vector<int> materials;
  Triangles all;
  for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
    std::optional<Triangles> t = primitiveTriangles(meshIndex, p);
    if (c_.out.hasErrors()) return parts;
    if (!t) continue;
    auto first = static_cast<std::uint32_t>(all.positions.size());
    all.positions.insert(all.positions.end(), t->positions.begin(), t->positions.end());
    for (std::uint32_t i : t->indices) all.indices.push_back(first + i);
    each.push_back(std::move(*t));
    materials.push_back(mesh.primitives[p].material);
  }
  if (each.empty()) return parts;
  std::string label =
      meshLabel(c_.model, meshIndex) + " (on " + nodeLabel(c_.model, nodeIndex) + ")";
  FitResult whole = fitPrimitive(all.positions, all.indices);
  if (whole.fit) {
    parts.push_back({*whole.fit, materials[0]});
    if (std::set<int>(materials.begin(), materials.end()).size() > 1) {
      c_.out.report(c_.loss, DiagnosticCode::GltfIgnored, {},
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
  c_.out
      .report(
          c_.loss, DiagnosticCode::GltfMeshNotPrimitive, {},
          label + " is not a sphere, box, cylinder or plane (" + whole.reason + "); it is skipped")
      .hint =
      "the tolerance is " + formatNumber(kFitTolerance) + " of the shape's size; see docs/GLTF.md";
  return parts;
}

void MeshReader::reportFit(const std::string& label, const MeshFit& fit) {
  c_.out.note(DiagnosticCode::GltfMeshFit, {},
              label + " is read as a " + std::string(objectKindName(fit.kind)) +
                  " (largest deviation " + deviationText(fit.error) + " of its size)");
}

bool MeshReader::holdsWrittenMesh(int mesh, ObjectKind kind) {
  const tinygltf::Primitive& prim = c_.model.meshes[mesh].primitives[0];
  int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
  auto position = prim.attributes.find("POSITION");
  if ((mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
       mode != TINYGLTF_MODE_TRIANGLE_FAN) ||
      !prim.targets.empty() || position == prim.attributes.end()) {
    return false;
  }
  // What primitiveTriangles would skip with a loss is simply not ours.
  for (int accessor : {position->second, prim.indices}) {
    if (accessor < 0) continue;
    const tinygltf::Accessor& a = c_.model.accessors[accessor];
    if (a.sparse.isSparse || a.bufferView < 0) return false;
  }
  auto [cached, fresh] =
      writtenMesh_.emplace(std::tuple{position->second, prim.indices, mode, kind}, false);
  if (!fresh) return cached->second;
  std::optional<Triangles> t = primitiveTriangles(mesh, 0);
  cached->second = t && isWrittenMesh(kind, t->positions, t->indices);
  return cached->second;
}

std::optional<std::vector<glm::dmat4>> MeshReader::instanceMatrices(int node, std::size_t limit) {
  nlohmann::json ext = parseOrNull(c_.model.nodes[node].extensions_json_string);
  if (!ext.is_object() || !ext.contains("EXT_mesh_gpu_instancing")) return std::nullopt;
  const nlohmann::json& instancing = ext["EXT_mesh_gpu_instancing"];
  std::vector<glm::dmat4> matrices;
  if (!instancing.is_object() || !instancing.contains("attributes") ||
      !instancing["attributes"].is_object()) {
    return matrices;
  }
  std::string label = nodeLabel(c_.model, node) + " EXT_mesh_gpu_instancing";
  // Each attribute's values, three or four to an instance.
  std::map<std::string, std::vector<double>> values;
  const std::pair<const char*, int> kinds[] = {{"TRANSLATION", TINYGLTF_TYPE_VEC3},
                                               {"ROTATION", TINYGLTF_TYPE_VEC4},
                                               {"SCALE", TINYGLTF_TYPE_VEC3}};
  std::optional<std::size_t> count;
  for (const auto& [name, type] : kinds) {
    auto it = instancing["attributes"].find(name);
    if (it == instancing["attributes"].end()) continue;
    int index = it->get<int>();  // checked in the document (gltf_document.h)
    const tinygltf::Accessor& a = c_.model.accessors[index];
    if (a.type != type || a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || a.normalized) {
      c_.out.report(c_.loss, DiagnosticCode::GltfIgnored, {},
                    label + ": accessor " + std::to_string(index) + " (" + name +
                        ") is not of floats, which are read; the instances are skipped");
      return matrices;
    }
    if (count && a.count != *count) {
      c_.out.error(DiagnosticCode::GltfBadAccessor, {},
                   label + ": the attributes hold different numbers of instances");
      return matrices;
    }
    count = a.count;
    bool skipped = false;
    std::size_t read = 0;
    std::optional<std::vector<double>> v =
        readAccessor(index, type, {TINYGLTF_COMPONENT_TYPE_FLOAT}, name, limit, read, skipped);
    if (!v) return matrices;
    values[name] = std::move(*v);
  }
  for (std::size_t i = 0; count && i < *count; ++i) {
    glm::dmat4 m(1.0);
    if (values.count("ROTATION")) {
      const double* q = &values["ROTATION"][4 * i];
      glm::dquat r(q[3], q[0], q[1], q[2]);
      double length = glm::length(r);
      if (!(std::abs(length - 1.0) <= kUnitQuaternionTolerance)) {
        c_.out.error(DiagnosticCode::GltfInvalid, {},
                     label + ": the rotation of instance " + std::to_string(i) +
                         " is not a unit quaternion (length " + formatNumber(length) + ")");
        return std::vector<glm::dmat4>{};
      }
      m = glm::dmat4(glm::mat3_cast(r / length));
    }
    if (values.count("SCALE")) {
      for (int c = 0; c < 3; ++c) m[c] *= values["SCALE"][3 * i + c];
    }
    if (values.count("TRANSLATION")) {
      const double* t = &values["TRANSLATION"][3 * i];
      m[3] = glm::dvec4(t[0], t[1], t[2], 1.0);
    }
    if (!finite(m)) {
      c_.out.error(DiagnosticCode::ValueNotFinite, {},
                   label + ": instance " + std::to_string(i) + " holds a value that is not finite");
      return std::vector<glm::dmat4>{};
    }
    matrices.push_back(m);
  }
  return matrices;
}

}  // namespace scene::gltf
