// Materials through glTF both ways (docs/GLTF.md, "Materials"): a mirror is
// a smooth metal, glass a smooth transmitting dielectric, the exact values
// come back from extras, and other programs' materials map back without.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "libscene/formats/gltf/gltf_mapping.h"
#include "libscene/formats/gltf/gltf_writer.h"
#include "libscene/testing/test_support.h"
#include "scenefile/read.h"

namespace scene {
namespace {

using Json = nlohmann::json;
using testing::withCode;

// The default scene's mirror and glass, and a plain diffuse cube.
Scene mirrorAndGlass() {
  ReadResult read = parseScene(testing::kCameraRecord + testing::kLightRecord +
                                   "CUBE\n0.05 0.05 0.05\n3 0 0 0\n0 2 0 0\n0 0 0.1 -3\n0 0 0 1\n"
                                   "SPHERE\n0.9 0.95 1\n1 0 0 2\n0 1 0 0\n0 0 1 0\n0 0 0 1\n"
                                   "CUBE\n0.2 0.7 0.25\n1 0 0 -2\n0 1 0 0\n0 0 1 0\n0 0 0 1\n",
                               "t.sf");
  EXPECT_TRUE(read.ok());
  Material& mirror = read.scene.objects[0].material;
  mirror.reflectivity = 0.9;
  mirror.shininess = 200;
  Material& glass = read.scene.objects[1].material;
  glass.transparency = 0.9;
  glass.reflectivity = 0.2;
  glass.ri = 1.5;
  glass.shininess = 200;
  glass.ambient = 0.0;
  glass.diffuse = 0.05;
  read.scene.objects[2].material.shininess = 60;
  return read.scene;
}

Json materialsWritten(const Scene& scene) {
  DiagnosticList out;
  std::optional<GltfFiles> files = writeGltf(scene, {}, false, out);
  EXPECT_TRUE(files.has_value());
  // The mirror's REFLECTIVITY has a counterpart; the glass's AMBIENT and
  // DIFFUSE (in the base colour as their sum) and REFLECTIVITY (its IOR's
  // Fresnel term stands for it) ride in extras alone.
  std::vector<Diagnostic> notes = withCode(out, DiagnosticCode::GltfExtrasOnly);
  EXPECT_EQ(notes.size(), 3u);
  EXPECT_EQ(
      notes.back().message,
      "REFLECTIVITY 0.2 of SPHERE object 2 has no glTF counterpart and rides in extras alone");
  return files ? Json::parse(files->main) : Json();
}

// Walter et al.'s GGX width of a Phong exponent, alpha = sqrt(2 / (n + 2)),
// as glTF's perceptual roughness sqrt(alpha).
double roughnessOf(double shininess) {
  return std::pow(2.0 / (shininess + 2.0), 0.25);
}
double decodeSrgb(double v) {
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

TEST(GltfMaterials, AMirrorIsASmoothMetalAndGlassASmoothTransmitter) {
  Json doc = materialsWritten(mirrorAndGlass());
  // The mirror: diffuse colour 0.05 (AMBIENT + DIFFUSE is 1) plus the
  // linear weight of REFLECTIVITY 0.9; metallic is that weight's share.
  const Json& mirror = doc["materials"][0];
  const Json& pbr = mirror["pbrMetallicRoughness"];
  double g = decodeSrgb(0.9);
  double metallic = g / (0.05 + g);
  EXPECT_NEAR(pbr["metallicFactor"].get<double>(), metallic, 1e-15);
  EXPECT_GT(metallic, 0.9);
  EXPECT_NEAR(pbr["baseColorFactor"][0].get<double>(), 0.05 + g, 1e-15);
  EXPECT_NEAR(pbr["roughnessFactor"].get<double>(), (1 - metallic) * roughnessOf(200), 1e-15);
  EXPECT_LT(pbr["roughnessFactor"].get<double>(), 0.02);
  EXPECT_FALSE(mirror.contains("extensions"));

  // The glass: diffuse colour COLOUR * 0.05, transmitting TRANSPARENCY
  // 0.9's share, not metallic.
  const Json& glass = doc["materials"][1];
  double transmission = 0.9 / (0.05 + 0.9);
  EXPECT_EQ(glass["pbrMetallicRoughness"]["metallicFactor"].get<double>(), 0.0);
  EXPECT_NEAR(glass["pbrMetallicRoughness"]["baseColorFactor"][1].get<double>(), 0.95 * 0.05 + 0.9,
              1e-15);
  EXPECT_NEAR(glass["pbrMetallicRoughness"]["roughnessFactor"].get<double>(),
              (1 - transmission) * roughnessOf(200), 1e-15);
  EXPECT_NEAR(glass["extensions"]["KHR_materials_transmission"]["transmissionFactor"].get<double>(),
              transmission, 1e-15);
  EXPECT_EQ(glass["extensions"]["KHR_materials_ior"]["ior"].get<double>(), 1.5);

  // Neither reflecting nor refracting: COLOUR as it is, SHININESS's roughness.
  const Json& plain = doc["materials"][2]["pbrMetallicRoughness"];
  EXPECT_EQ(plain["metallicFactor"].get<double>(), 0.0);
  EXPECT_EQ(plain["baseColorFactor"], Json::array({0.2, 0.7, 0.25, 1.0}));
  EXPECT_EQ(plain["roughnessFactor"].get<double>(), roughnessOf(60));

  // Ratified extensions, declared used and never required: a viewer without
  // them still shows the metallic-roughness material.
  EXPECT_EQ(doc["extensionsUsed"], Json::array({"KHR_lights_punctual", "KHR_materials_ior",
                                                "KHR_materials_transmission"}));
  EXPECT_FALSE(doc.contains("extensionsRequired"));
}

TEST(GltfMaterials, OwnMaterialsReadBackExactlyFromExtras) {
  Scene scene = mirrorAndGlass();
  ReadResult back = parseScene(materialsWritten(scene).dump(), "own.gltf");
  ASSERT_TRUE(back.ok());
  ASSERT_EQ(back.scene.objects.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(back.scene.objects[i].material, scene.objects[i].material);
  EXPECT_TRUE(withCode(back.diagnostics, DiagnosticCode::GltfExtrasStale).empty());
}

TEST(GltfMaterials, WithoutExtrasTheMappingIsInvertedWhereGltfHoldsTheValue) {
  Scene scene = mirrorAndGlass();
  Json doc = materialsWritten(scene);
  for (Json& material : doc["materials"]) material.erase("extras");
  ReadResult back = parseScene(doc.dump(), "stripped.gltf");
  ASSERT_TRUE(back.ok());
  const Material& mirror = back.scene.objects[0].material;
  EXPECT_NEAR(mirror.reflectivity, 0.9, 1e-12);
  EXPECT_NEAR(mirror.colour.x, 0.05, 1e-12);
  EXPECT_NEAR(mirror.shininess, 200, 1e-9);
  EXPECT_EQ(mirror.transparency, 0.0);
  // The glass's COLOUR comes back as its diffuse colour (AMBIENT + DIFFUSE
  // then 1); its REFLECTIVITY, which the IOR's Fresnel term stands for, is
  // lost.
  const Material& glass = back.scene.objects[1].material;
  EXPECT_NEAR(glass.transparency, 0.9, 1e-12);
  EXPECT_EQ(glass.ri, 1.5);
  EXPECT_NEAR(glass.colour.y, 0.95 * 0.05, 1e-12);
  EXPECT_NEAR(glass.shininess, 200, 1e-9);
  EXPECT_EQ(glass.reflectivity, 0.0);
  EXPECT_EQ(back.scene.objects[2].material.colour, scene.objects[2].material.colour);
  EXPECT_NEAR(back.scene.objects[2].material.shininess, 60, 1e-9);
}

TEST(GltfMaterials, AFullMetalFromAnotherProgramIsAMirror) {
  // A gold of Blender's: metallic 1, roughness 0.2. Its tint is lost.
  gltf::PbrMaterial gold;
  gold.baseColor = {1.0, 0.766, 0.336, 1.0};
  gold.metallic = 1.0;
  gold.roughness = 0.2;
  Material m = gltf::materialFromPbr(gold);
  EXPECT_NEAR(m.reflectivity, 1.0, 1e-12);
  EXPECT_EQ(m.colour, glm::dvec3(0.0));
  EXPECT_NEAR(m.shininess, 2 / std::pow(0.2, 4) - 2, 1e-9);
}

}  // namespace
}  // namespace scene
