// Our own files whose objects a program gathered into instances of their
// meshes (EXT_mesh_gpu_instancing, as glTF-Transform's `instance` writes
// it: the nodes and their extras gone, each instance's translation, rotation
// and scale in float accessors): each instance is found again as the object
// it stands for, exactly and in the scene's order; an instance moved is not.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "libscene/formats/gltf/glb.h"
#include "libscene/formats/gltf/gltf_writer.h"
#include "libscene/formats/sf/sf_writer.h"
#include "scenefile/read.h"

namespace scene {
namespace {

using Json = nlohmann::json;

// Objects of every kind in one material, each a translation, rotation and
// scale (a mirror among them), as many per kind as `instance` batches.
Scene alikeScene(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Scene scene;
  scene.camera.matrix[3] = glm::dvec4(0.0, 1.0, 12.0, 1.0);
  scene.lights.push_back(Light{});
  const ObjectKind kinds[] = {ObjectKind::Sphere, ObjectKind::Cube, ObjectKind::Cylinder,
                              ObjectKind::Plane};
  for (int i = 0; i < 24; ++i) {
    Object o;
    o.kind = kinds[i % 4];
    glm::dquat q = glm::normalize(glm::dquat(unit(rng), unit(rng), unit(rng), unit(rng)));
    glm::dmat4 m(glm::mat3_cast(q));
    glm::dvec3 scale(1.5 + unit(rng), 1.5 + unit(rng), 1.5 + unit(rng));
    if (i % 7 == 3) scale.x = -scale.x;
    for (int c = 0; c < 3; ++c) m[c] *= scale[c];
    m[3] = glm::dvec4(4 * unit(rng), 4 * unit(rng), 4 * unit(rng), 1.0);
    o.matrix = m;
    scene.objects.push_back(o);
  }
  return scene;
}

int appendFloats(Json& doc, std::string& bin, const std::vector<float>& values, const char* type,
                 std::size_t count) {
  bin.resize((bin.size() + 3) / 4 * 4, '\0');
  doc["bufferViews"].push_back(
      {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", values.size() * 4}});
  bin.append(reinterpret_cast<const char*>(values.data()), values.size() * 4);
  doc["buffers"][0]["byteLength"] = bin.size();
  doc["accessors"].push_back({{"bufferView", doc["bufferViews"].size() - 1},
                              {"componentType", 5126},
                              {"count", count},
                              {"type", type}});
  return static_cast<int>(doc["accessors"].size() - 1);
}

// The GLB with every mesh's nodes replaced by one node of instances, whose
// first instance is moved by `nudge` (relative).
std::string instanced(const std::string& glb, double nudge) {
  std::string error;
  std::optional<GlbChunks> chunks = decodeGlb(glb, error);
  EXPECT_TRUE(chunks && chunks->bin) << error;
  Json doc = Json::parse(chunks->json);
  std::string bin(*chunks->bin);
  std::map<int, std::vector<glm::dmat4>> byMesh;
  for (Json& node : doc["nodes"]) {
    if (!node.contains("mesh")) continue;
    glm::dmat4 m;
    for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = node["matrix"][i].get<double>();
    byMesh[node["mesh"].get<int>()].push_back(m);
    node.erase("mesh");
    node.erase("extras");
  }
  for (const auto& [mesh, matrices] : byMesh) {
    std::vector<float> t, r, s;
    for (const glm::dmat4& m : matrices) {
      glm::dvec3 scale(glm::length(glm::dvec3(m[0])), glm::length(glm::dvec3(m[1])),
                       glm::length(glm::dvec3(m[2])));
      if (glm::determinant(glm::dmat3(m)) < 0.0) scale.x = -scale.x;
      glm::dmat3 rotation(glm::dvec3(m[0]) / scale.x, glm::dvec3(m[1]) / scale.y,
                          glm::dvec3(m[2]) / scale.z);
      glm::dquat q = glm::quat_cast(rotation);
      t.insert(t.end(), {float(m[3].x), float(m[3].y), float(m[3].z)});
      r.insert(r.end(), {float(q.x), float(q.y), float(q.z), float(q.w)});
      s.insert(s.end(), {float(scale.x), float(scale.y), float(scale.z)});
    }
    t[0] = static_cast<float>(t[0] + nudge * (1.0 + std::abs(t[0])));
    Json attributes = {{"TRANSLATION", appendFloats(doc, bin, t, "VEC3", matrices.size())},
                       {"ROTATION", appendFloats(doc, bin, r, "VEC4", matrices.size())},
                       {"SCALE", appendFloats(doc, bin, s, "VEC3", matrices.size())}};
    doc["nodes"].push_back(
        {{"mesh", mesh},
         {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", attributes}}}}}});
    doc["scenes"][0]["nodes"].push_back(doc["nodes"].size() - 1);
  }
  doc["extensionsUsed"].push_back("EXT_mesh_gpu_instancing");
  return encodeGlb(doc.dump(), bin);
}

std::size_t count(const DiagnosticList& list, DiagnosticCode code) {
  std::size_t n = 0;
  for (const Diagnostic& d : list.items()) n += d.code == code;
  return n;
}

TEST(GltfInstancing, EachInstanceIsTheObjectItStandsForExactlyAndInOrder) {
  std::mt19937 rng(2026);
  for (int i = 0; i < 50; ++i) {
    Scene scene = alikeScene(rng);
    std::string sf = writeSceneFile(scene);
    DiagnosticList diagnostics;
    std::optional<GltfFiles> files = writeGltf(scene, {}, true, diagnostics);
    ASSERT_TRUE(files.has_value());
    ReadResult back = parseScene(instanced(files->main, 0.0), "instanced.glb");
    ASSERT_TRUE(back.ok()) << sf;
    EXPECT_EQ(count(back.diagnostics, DiagnosticCode::GltfExtrasStale), 0u) << sf;
    ASSERT_EQ(writeSceneFile(back.scene), sf);
  }
}

TEST(GltfInstancing, AnInstanceMovedIsFittedWithANote) {
  std::mt19937 rng(7);
  Scene scene = alikeScene(rng);
  DiagnosticList diagnostics;
  std::optional<GltfFiles> files = writeGltf(scene, {}, true, diagnostics);
  ASSERT_TRUE(files.has_value());
  ReadResult back = parseScene(instanced(files->main, 1e-4), "moved.glb");
  ASSERT_TRUE(back.ok());
  // The first instance of each of the four meshes.
  EXPECT_EQ(count(back.diagnostics, DiagnosticCode::GltfExtrasStale), 4u);
  EXPECT_EQ(back.scene.objects.size(), scene.objects.size());
}

// Each instance is an object: the instances' accessors are not read past
// maxObjects, however many they hold.
TEST(GltfInstancing, NoMoreInstancesAreReadThanMaxObjectsAllows) {
  std::mt19937 rng(3);
  Scene scene = alikeScene(rng);
  DiagnosticList diagnostics;
  std::optional<GltfFiles> files = writeGltf(scene, {}, true, diagnostics);
  ASSERT_TRUE(files.has_value());
  ReadOptions options;
  options.maxObjects = 10;
  ReadResult back = parseScene(instanced(files->main, 0.0), "instanced.glb", options);
  EXPECT_FALSE(back.ok());
  EXPECT_GE(count(back.diagnostics, DiagnosticCode::GltfTooLarge), 1u);
}

}  // namespace
}  // namespace scene
