// Our own files whose meshes another program rewrote: while a mesh is still
// the primitive its extras describe (its vertices and triangles reordered,
// shared or not), the node is read from its extras, bit for bit; once its
// shape changed, the extras are stale and the mesh is fitted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <numeric>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "libscene/formats/gltf/glb.h"
#include "libscene/formats/gltf/gltf_writer.h"
#include "libscene/formats/sf/sf_writer.h"
#include "libscene/testing/random_cases.h"
#include "libscene/testing/random_scenes.h"
#include "scenefile/read.h"

namespace scene {
namespace {

using Json = nlohmann::json;
using Vertex = std::array<float, 6>;  // position, then normal

// One primitive's data as a program that rewrites meshes sees it.
struct MeshData {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;
  bool indexed = true;
};

using Edit = std::function<void(MeshData&, std::mt19937&)>;

template <typename T>
std::vector<T> elements(const Json& doc, const std::string& bin, int accessor, int components) {
  const Json& a = doc["accessors"][accessor];
  const Json& view = doc["bufferViews"][a["bufferView"].get<int>()];
  std::size_t offset = view.value("byteOffset", 0) + a.value("byteOffset", 0);
  std::size_t count = a["count"].get<std::size_t>() * components;
  std::vector<T> out(count);
  std::memcpy(out.data(), bin.data() + offset, count * sizeof(T));
  return out;
}

MeshData readMesh(const Json& doc, const std::string& bin, const Json& prim) {
  MeshData m;
  auto positions = elements<float>(doc, bin, prim["attributes"]["POSITION"].get<int>(), 3);
  auto normals = elements<float>(doc, bin, prim["attributes"]["NORMAL"].get<int>(), 3);
  for (std::size_t i = 0; i < positions.size() / 3; ++i) {
    m.vertices.push_back({positions[3 * i], positions[3 * i + 1], positions[3 * i + 2],
                          normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]});
  }
  int indices = prim["indices"].get<int>();
  if (doc["accessors"][indices]["componentType"].get<int>() == 5125) {
    m.indices = elements<std::uint32_t>(doc, bin, indices, 1);
  } else {
    for (std::uint16_t i : elements<std::uint16_t>(doc, bin, indices, 1)) m.indices.push_back(i);
  }
  return m;
}

// Appends `bytes` to the buffer as a new accessor; returns its index.
int append(Json& doc, std::string& bin, const void* bytes, std::size_t size, std::size_t count,
           const char* type, int componentType) {
  bin.resize((bin.size() + 3) / 4 * 4, '\0');
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", size}});
  bin.append(static_cast<const char*>(bytes), size);
  doc["buffers"][0]["byteLength"] = bin.size();
  doc["accessors"].push_back({{"bufferView", doc["bufferViews"].size() - 1},
                              {"componentType", componentType},
                              {"count", count},
                              {"type", type}});
  return static_cast<int>(doc["accessors"].size() - 1);
}

// The GLB with `edit` applied to every mesh, each primitive given new
// accessors as a program that rewrites meshes gives them.
std::string editMeshes(const std::string& glb, const Edit& edit, std::mt19937& rng) {
  std::string error;
  std::optional<GlbChunks> chunks = decodeGlb(glb, error);
  EXPECT_TRUE(chunks && chunks->bin) << error;
  Json doc = Json::parse(chunks->json);
  std::string bin(*chunks->bin);
  for (Json& mesh : doc["meshes"]) {
    for (Json& prim : mesh["primitives"]) {
      MeshData m = readMesh(doc, bin, prim);
      edit(m, rng);
      std::vector<float> positions, normals;
      for (const Vertex& v : m.vertices) {
        positions.insert(positions.end(), v.begin(), v.begin() + 3);
        normals.insert(normals.end(), v.begin() + 3, v.end());
      }
      prim["attributes"]["POSITION"] =
          append(doc, bin, positions.data(), positions.size() * 4, m.vertices.size(), "VEC3", 5126);
      prim["attributes"]["NORMAL"] =
          append(doc, bin, normals.data(), normals.size() * 4, m.vertices.size(), "VEC3", 5126);
      if (m.indexed) {
        prim["indices"] = append(doc, bin, m.indices.data(), m.indices.size() * 4, m.indices.size(),
                                 "SCALAR", 5125);
      } else {
        prim.erase("indices");
      }
    }
  }
  return encodeGlb(doc.dump(), bin);
}

// --- Edits that keep the shape --------------------------------------------

void permuteVertices(MeshData& m, std::mt19937& rng) {
  std::vector<std::uint32_t> order(m.vertices.size());
  std::iota(order.begin(), order.end(), 0u);
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<std::uint32_t> where(order.size());
  std::vector<Vertex> vertices(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    vertices[i] = m.vertices[order[i]];
    where[order[i]] = static_cast<std::uint32_t>(i);
  }
  for (std::uint32_t& i : m.indices) i = where[i];
  m.vertices = std::move(vertices);
}

// Triangles in another order, each started at another corner (as a
// vertex-cache optimiser leaves them).
void reorderTriangles(MeshData& m, std::mt19937& rng) {
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (std::size_t i = 0; i < m.indices.size(); i += 3) {
    std::array<std::uint32_t, 3> t{m.indices[i], m.indices[i + 1], m.indices[i + 2]};
    std::rotate(t.begin(), t.begin() + rng() % 3, t.end());
    triangles.push_back(t);
  }
  std::shuffle(triangles.begin(), triangles.end(), rng);
  m.indices.clear();
  for (const auto& t : triangles) m.indices.insert(m.indices.end(), t.begin(), t.end());
}

// Vertices at one place merged into one, whatever their normals.
void weldPositions(MeshData& m, std::mt19937&) {
  std::map<std::array<float, 3>, std::uint32_t> first;
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> where;
  for (const Vertex& v : m.vertices) {
    auto [it, fresh] = first.emplace(std::array<float, 3>{v[0], v[1], v[2]},
                                     static_cast<std::uint32_t>(vertices.size()));
    if (fresh) vertices.push_back(v);
    where.push_back(it->second);
  }
  for (std::uint32_t& i : m.indices) i = where[i];
  m.vertices = std::move(vertices);
}

// Every triangle with vertices of its own, and no indices.
void unweld(MeshData& m, std::mt19937&) {
  std::vector<Vertex> vertices;
  for (std::uint32_t i : m.indices) vertices.push_back(m.vertices[i]);
  m.vertices = std::move(vertices);
  m.indices.clear();
  m.indexed = false;
}

// --- Edits that change it --------------------------------------------------

void nudgeOneCoordinate(MeshData& m, std::mt19937& rng) {
  float& x = m.vertices[rng() % m.vertices.size()][rng() % 3];
  x = std::nextafter(x, 2.0f);
}

void scaleAll(MeshData& m, std::mt19937&) {
  for (Vertex& v : m.vertices) {
    for (int c = 0; c < 3; ++c) v[c] *= 2.0f;
  }
}

void translateAll(MeshData& m, std::mt19937&) {
  for (Vertex& v : m.vertices) {
    for (int c = 0; c < 3; ++c) v[c] += 0.5f;
  }
}

void flipOneTriangle(MeshData& m, std::mt19937& rng) {
  std::size_t t = 3 * (rng() % (m.indices.size() / 3));
  std::swap(m.indices[t + 1], m.indices[t + 2]);
}

void dropOneTriangle(MeshData& m, std::mt19937& rng) {
  std::size_t t = 3 * (rng() % (m.indices.size() / 3));
  m.indices.erase(m.indices.begin() + static_cast<std::ptrdiff_t>(t),
                  m.indices.begin() + static_cast<std::ptrdiff_t>(t + 3));
}

// Two triangles sharing an edge (quads of the cube, the side of a cylinder)
// split along the other diagonal: the same surface, other triangles.
void moveOneVertexOntoAnother(MeshData& m, std::mt19937& rng) {
  std::size_t t = 3 * (rng() % (m.indices.size() / 3));
  m.indices[t] = m.indices[t + 1];
}

std::size_t staleNotes(const DiagnosticList& list) {
  return static_cast<std::size_t>(
      std::count_if(list.items().begin(), list.items().end(),
                    [](const Diagnostic& d) { return d.code == DiagnosticCode::GltfExtrasStale; }));
}

struct Case {
  Scene scene;
  std::string sf;
  std::string glb;
};

std::vector<Case> randomCases(int count) {
  testing::RandomSceneGenerator random(20261206);
  std::vector<Case> cases;
  for (int i = 0; static_cast<int>(cases.size()) < count; ++i) {
    Scene scene = random.scene();
    std::string sf = writeSceneFile(scene);
    if (scene.objects.empty() || !parseScene(sf, "random.sf").ok()) continue;
    ConversionOptions options;
    // Every tessellation, the coarsest (3) included.
    options.gltf.segments = 3 + i % 40;
    DiagnosticList diagnostics;
    std::optional<GltfFiles> files = writeGltf(scene, options, true, diagnostics);
    EXPECT_TRUE(files.has_value());
    if (files) cases.push_back({scene, sf, files->main});
  }
  return cases;
}

TEST(GltfMeshEdits, AMeshStillItsPrimitiveIsReadFromItsExtrasBitForBit) {
  std::mt19937 rng(7);
  const std::pair<const char*, std::vector<Edit>> edits[] = {
      {"vertices permuted", {permuteVertices}},
      {"triangles reordered", {reorderTriangles}},
      {"positions welded", {weldPositions}},
      {"unwelded", {unweld}},
      {"welded, permuted, reordered", {weldPositions, permuteVertices, reorderTriangles}},
  };
  for (const Case& c : randomCases(testing::randomCases(150))) {
    for (const auto& [name, stepList] : edits) {
      // A copy of the binding's reference: clang before 16 captures no
      // structured binding.
      const auto& steps = stepList;
      Edit all = [&steps](MeshData& m, std::mt19937& r) {
        for (const Edit& step : steps) step(m, r);
      };
      ReadResult back = parseScene(editMeshes(c.glb, all, rng), "edited.glb");
      ASSERT_TRUE(back.ok()) << name << "\n" << c.sf;
      EXPECT_EQ(staleNotes(back.diagnostics), 0u) << name << "\n" << c.sf;
      ASSERT_EQ(writeSceneFile(back.scene), c.sf) << name;
    }
  }
}

TEST(GltfMeshEdits, AMeshChangedInShapeIsStaleAndFitted) {
  std::mt19937 rng(11);
  // A PLANE's square is any size (the writer picks one for the scene), so
  // a plane scaled is still the plane its extras describe.
  const std::tuple<const char*, Edit, bool> edits[] = {
      {"one coordinate nudged by one float step", nudgeOneCoordinate, true},
      {"scaled by 2", scaleAll, false},
      {"moved by 0.5 along each axis", translateAll, true},
      {"one triangle turned over", flipOneTriangle, true},
      {"one triangle dropped", dropOneTriangle, true},
      {"one triangle collapsed", moveOneVertexOntoAnother, true},
  };
  for (const Case& c : randomCases(testing::randomCases(60))) {
    std::size_t planes = static_cast<std::size_t>(
        std::count_if(c.scene.objects.begin(), c.scene.objects.end(),
                      [](const Object& o) { return o.kind == ObjectKind::Plane; }));
    for (const auto& [name, edit, planesToo] : edits) {
      ReadResult back = parseScene(editMeshes(c.glb, edit, rng), "edited.glb");
      // Each object's mesh was edited: none is read from its extras.
      EXPECT_EQ(staleNotes(back.diagnostics), c.scene.objects.size() - (planesToo ? 0 : planes))
          << name << "\n"
          << c.sf;
    }
  }
}

}  // namespace
}  // namespace scene
