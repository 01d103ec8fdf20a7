// Lights through glTF both ways: the writer's intensity, our own extras
// (believed only while they match), and the map back of lights from other
// programs at the reference distance of the scene read (docs/GLTF.md,
// "Lights").
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "libscene/formats/gltf/gltf_writer.h"
#include "libscene/testing/test_support.h"
#include "scenefile/read.h"

namespace scene {
namespace {

using Json = nlohmann::json;
using testing::withCode;

// The documented mapping, written out here rather than taken from the code
// under test: sRGB's curve, a reference surface of 0.8, 683 * pi lux per 1.
double decode(double v) {
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}
double encode(double v) {
  return v <= 0.0031308 ? v * 12.92 : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
}
constexpr double kSurface = 0.8;
constexpr double kLux = 683 * std::numbers::pi;

// A camera at (0, 0, 5) looking down -Z at a unit cube: the camera's ray
// meets it at (0, 0, 1). LIGHT 1 is 5 from there, LIGHT 2 is 3.
const std::string kScene = testing::kCameraRecord +
                           "LIGHT\n0.9 0.6 0.3\n1 0 0 0\n0 1 0 3\n0 0 1 5\n0 0 0 1\n"
                           "LIGHT\n2 2 2\n1 0 0 0\n0 1 0 0\n0 0 1 4\n0 0 0 1\n"
                           "CUBE\n0.5 0.5 0.5\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";

Json written(const Scene& scene, const GltfWriteOptions& options = {}) {
  DiagnosticList out;
  std::optional<GltfFiles> files = writeGltf(scene, testing::conversionWith(options), false, out);
  EXPECT_TRUE(files.has_value());
  return files ? Json::parse(files->main) : Json();
}

Scene original() {
  ReadResult read = parseScene(kScene, "lights.sf");
  EXPECT_TRUE(read.ok());
  return read.scene;
}

Json& lightOf(Json& doc, int i) {
  return doc["extensions"]["KHR_lights_punctual"]["lights"][i];
}

TEST(GltfLights, TheWriterMatchesEachLightAtItsReferenceDistance) {
  Json doc = written(original());
  for (auto [i, distance, colour] :
       {std::tuple{0, 5.0, glm::dvec3(0.9, 0.6, 0.3)}, std::tuple{1, 3.0, glm::dvec3(2.0)}}) {
    const Json& light = lightOf(doc, i);
    double peak = decode(kSurface * colour.x) / kSurface * kLux;
    EXPECT_NEAR(light["intensity"].get<double>() / (peak * distance * distance), 1.0, 1e-12);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(light["color"][c].get<double>(),
                  decode(kSurface * colour[c]) / decode(kSurface * colour.x), 1e-15);
    }
    EXPECT_EQ(doc["nodes"][1 + i]["extras"]["sf"]["referenceDistance"].get<double>(), distance);
  }
}

TEST(GltfLights, OwnLightsReadBackExactly) {
  Scene scene = original();
  ReadResult back = parseScene(written(scene).dump(), "lights.gltf");
  ASSERT_TRUE(back.ok());
  ASSERT_EQ(back.scene.lights.size(), 2u);
  EXPECT_EQ(back.scene.lights[0].colour, scene.lights[0].colour);
  EXPECT_EQ(back.scene.lights[1].colour, scene.lights[1].colour);
  EXPECT_TRUE(withCode(back.diagnostics, DiagnosticCode::GltfExtrasStale).empty());
  EXPECT_TRUE(withCode(back.diagnostics, DiagnosticCode::LightFalloff).empty());
}

TEST(GltfLights, ALightWithoutExtrasMapsBackAtTheReferenceDistanceOfTheSceneRead) {
  // As another program writes it: no extras anywhere. The cube is fitted
  // from its mesh in floats, so the reference point moves by rounding only.
  Scene scene = original();
  Json doc = written(scene);
  for (Json& node : doc["nodes"]) node.erase("extras");
  for (Json& material : doc["materials"]) material.erase("extras");
  ReadResult back = parseScene(doc.dump(), "stripped.gltf");
  ASSERT_TRUE(back.ok());
  ASSERT_EQ(back.scene.lights.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(back.scene.lights[i].colour[c], scene.lights[i].colour[c], 1e-6);
    }
  }
  std::vector<Diagnostic> falloff = withCode(back.diagnostics, DiagnosticCode::LightFalloff);
  ASSERT_EQ(falloff.size(), 2u);
  EXPECT_NE(falloff[0].message.find("LIGHT colour 0.9 0.6 0.3 matches it at the reference "
                                    "distance 5, from the light to the point the camera looks at"),
            std::string::npos)
      << falloff[0].message;
}

TEST(GltfLights, StaleExtrasAreIgnoredAndTheLightMapsBack) {
  Json doc = written(original());
  double intensity = lightOf(doc, 0)["intensity"].get<double>();
  lightOf(doc, 0)["intensity"] = 2 * intensity;  // turned up in another program
  ReadResult back = parseScene(doc.dump(), "edited.gltf");
  ASSERT_TRUE(back.ok());
  std::vector<Diagnostic> stale = withCode(back.diagnostics, DiagnosticCode::GltfExtrasStale);
  ASSERT_EQ(stale.size(), 1u);
  EXPECT_NE(stale[0].message.find("'LIGHT 1'"), std::string::npos);
  // Twice the light at the reference point, in linear terms.
  double want = encode(2 * decode(kSurface * 0.9)) / kSurface;
  EXPECT_NEAR(back.scene.lights[0].colour.x, want, 1e-12);
  EXPECT_GT(back.scene.lights[0].colour.x, 0.9);
  EXPECT_EQ(back.scene.lights[1].colour, glm::dvec3(2.0));
  // Extras whose reference distance is not a positive number are no extras.
  Json bad = written(original());
  bad["nodes"][1]["extras"]["sf"]["referenceDistance"] = -1.0;
  ReadResult ignored = parseScene(bad.dump(), "bad.gltf");
  ASSERT_TRUE(ignored.ok());
  EXPECT_NEAR(ignored.scene.lights[0].colour.x, 0.9, 1e-12);
  EXPECT_EQ(withCode(ignored.diagnostics, DiagnosticCode::LightFalloff).size(), 1u);
}

TEST(GltfLights, FilesWrittenBeforeTheReferenceDistanceStillReadBackExactly) {
  // Then the intensity was the colour's largest channel, and the colour the
  // channels over it.
  Json doc = written(original());
  lightOf(doc, 0)["intensity"] = 0.9;
  lightOf(doc, 0)["color"] = Json::array({1.0, 0.6 / 0.9, 0.3 / 0.9});
  doc["nodes"][1]["extras"]["sf"].erase("referenceDistance");
  ReadResult back = parseScene(doc.dump(), "old.gltf");
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back.scene.lights[0].colour, glm::dvec3(0.9, 0.6, 0.3));
  EXPECT_TRUE(withCode(back.diagnostics, DiagnosticCode::GltfExtrasStale).empty());
}

TEST(GltfLights, WithoutObjectsTheLightIsMatchedAtTheCamera) {
  Json doc = {
      {"asset", {{"version", "2.0"}}},
      {"extensionsUsed", {"KHR_lights_punctual"}},
      {"extensions",
       {{"KHR_lights_punctual",
         {{"lights",
           {{{"type", "point"}, {"color", {1.0, 0.5, 0.0}}, {"intensity", 36 * kLux}},
            {{"type", "directional"}, {"intensity", kLux}}}}}}}},
      {"cameras", {{{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.1}}}}}},
      {"nodes",
       {{{"camera", 0}, {"translation", {0, 0, 10}}},
        {{"name", "Lamp"},
         {"translation", {0, 0, 4}},
         {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}},
        {{"name", "Sun"}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}}}},
      {"scenes", {{{"nodes", {0, 1, 2}}}}}};
  ReadResult read = parseScene(doc.dump(), "lamp.gltf");
  ASSERT_TRUE(read.ok());
  ASSERT_EQ(read.scene.lights.size(), 2u);
  // 36 * 683 * pi cd, 6 away: linear 1 (and 0.5) on the reference surface.
  EXPECT_NEAR(read.scene.lights[0].colour.x, encode(kSurface) / kSurface, 1e-12);
  EXPECT_NEAR(read.scene.lights[0].colour.y, encode(kSurface * 0.5) / kSurface, 1e-12);
  EXPECT_EQ(read.scene.lights[0].colour.z, 0.0);
  // Lux fall off no more than a LIGHT: no distance, no falloff note.
  EXPECT_NEAR(read.scene.lights[1].colour.x, encode(kSurface) / kSurface, 1e-12);
  std::vector<Diagnostic> falloff = withCode(read.diagnostics, DiagnosticCode::LightFalloff);
  ASSERT_EQ(falloff.size(), 1u);
  EXPECT_NE(falloff[0].message.find("at the reference distance 6, from the light to the camera "
                                    "(0 0 10), since no object gives a point to look at"),
            std::string::npos)
      << falloff[0].message;
}

TEST(GltfLights, ALightTooStrongForItsReferenceDistanceIsAnError) {
  // 1e308 cd 1e-200 from the camera, where it is matched: no double holds
  // that colour, and the light is not read as black.
  Json doc = {
      {"asset", {{"version", "2.0"}}},
      {"extensionsUsed", {"KHR_lights_punctual"}},
      {"extensions",
       {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}, {"intensity", 1e308}}}}}}}},
      {"cameras", {{{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.1}}}}}},
      {"nodes",
       {{{"camera", 0}},
        {{"translation", {0, 0, 1e-200}},
         {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}}},
      {"scenes", {{{"nodes", {0, 1}}}}}};
  ReadResult read = parseScene(doc.dump(), "strong.gltf");
  std::vector<Diagnostic> errors = withCode(read.diagnostics, DiagnosticCode::ValueNotFinite);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].message.find("reference distance 1e-200"), std::string::npos)
      << errors[0].message;
  EXPECT_FALSE(read.ok());
}

TEST(GltfLights, NoLightsLeavesEveryLightOutWithAWarningNamingIt) {
  GltfWriteOptions options;
  options.lights = false;
  DiagnosticList out;
  std::optional<GltfFiles> files =
      writeGltf(original(), testing::conversionWith(options), false, out);
  ASSERT_TRUE(files.has_value());
  Json doc = Json::parse(files->main);
  EXPECT_FALSE(doc.contains("extensions"));
  EXPECT_EQ(doc["extensionsUsed"].dump().find("KHR_lights_punctual"), std::string::npos);
  for (const Json& node : doc["nodes"]) EXPECT_NE(node["name"], "LIGHT 1");
  std::vector<Diagnostic> left = withCode(out, DiagnosticCode::GltfLightLeftOut);
  ASSERT_EQ(left.size(), 2u);
  EXPECT_EQ(left[0].severity, Severity::Warning);
  EXPECT_EQ(left[0].message,
            "LIGHT 1 (COLOUR 0.9 0.6 0.3) is left out: the glTF is written without lights");
  EXPECT_TRUE(withCode(out, DiagnosticCode::LightFalloff).empty());
  // The file is all there is: read back, it has no lights.
  ReadResult back = parseScene(files->main, "dark.gltf");
  ASSERT_TRUE(back.ok());
  EXPECT_TRUE(back.scene.lights.empty());
  EXPECT_EQ(back.scene.objects.size(), 1u);
  // Where no loss is allowed, a light left out is an error, and nothing is written.
  ConversionOptions strict = testing::conversionWith(options);
  strict.noLoss = true;
  DiagnosticList refused;
  EXPECT_FALSE(writeGltf(original(), strict, false, refused).has_value());
  EXPECT_EQ(withCode(refused, DiagnosticCode::GltfLightLeftOut)[0].severity, Severity::Error);
}

TEST(GltfLights, WithoutFalloffTheIntensityIsTheColoursLargestChannel) {
  GltfWriteOptions options;
  options.lightFalloff = GltfLightFalloff::None;
  Scene scene = original();
  Json doc = written(scene, options);
  EXPECT_EQ(lightOf(doc, 0)["intensity"].get<double>(), 0.9);
  EXPECT_NEAR(lightOf(doc, 0)["color"][1].get<double>(), 0.6 / 0.9, 1e-15);
  EXPECT_EQ(lightOf(doc, 1)["intensity"].get<double>(), 2.0);
  EXPECT_FALSE(doc["nodes"][1]["extras"]["sf"].contains("referenceDistance"));
  ReadResult back = parseScene(doc.dump(), "f3d.gltf");
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back.scene.lights[0].colour, scene.lights[0].colour);
  EXPECT_EQ(back.scene.lights[1].colour, scene.lights[1].colour);
  EXPECT_TRUE(withCode(back.diagnostics, DiagnosticCode::GltfExtrasStale).empty());
  // A light beyond the floats is clamped there, with a warning.
  scene.lights[1].colour = glm::dvec3(1e300);
  DiagnosticList out;
  std::optional<GltfFiles> files = writeGltf(scene, testing::conversionWith(options), false, out);
  ASSERT_TRUE(files.has_value());
  Json clamped = Json::parse(files->main);
  EXPECT_EQ(lightOf(clamped, 1)["intensity"].get<double>(),
            static_cast<double>(std::numeric_limits<float>::max()));
  EXPECT_EQ(withCode(out, DiagnosticCode::GltfValueClamped).size(), 1u);
}

}  // namespace
}  // namespace scene
