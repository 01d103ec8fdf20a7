#include "libscene/formats/gltf/gltf_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>

#include "libscene/formats/gltf/glb.h"
#include "libscene/formats/gltf/gltf_reader.h"
#include "libscene/testing/test_support.h"
#include "scenefile/read.h"

namespace scene {
namespace {

using Json = nlohmann::json;
using testing::withCode;

Scene sceneOf(const std::string& text) {
  ReadResult read = parseScene(text, "t.sf");
  EXPECT_TRUE(read.ok());
  return read.scene;
}

const std::string kScene = testing::kCameraRecord + testing::kLightRecord +
                           "SPHERE\n1 0 0\n2 0 0 20\n0 1 0 0\n0 0 1 0\n0 0 0 1\n"
                           "PLANE\n0 1 0\n1 0 0 0\n0 1 0 -1\n0 0 1 0\n0 0 0 1\n"
                           "CUBE\n0 0 1\n2 0 0 1\n0 2 0 0\n0 0 2 0\n0 0 0 1\n";

struct Written {
  Json doc;
  std::string bin;
  DiagnosticList diagnostics;
};

Written write(const Scene& scene, GltfWriteOptions options = {}, bool binary = false) {
  Written w;
  std::optional<GltfFiles> files =
      writeGltf(scene, testing::conversionWith(options), binary, w.diagnostics);
  EXPECT_TRUE(files.has_value());
  if (!files) return w;
  if (binary) {
    std::string error;
    std::optional<GlbChunks> chunks = decodeGlb(files->main, error);
    EXPECT_TRUE(chunks) << error;
    w.doc = Json::parse(chunks->json);
    w.bin = std::string(chunks->bin.value_or(""));
  } else {
    w.doc = Json::parse(files->main);
    w.bin = files->buffer;
  }
  return w;
}

const Json& nodeNamed(const Json& doc, const std::string& name) {
  for (const Json& node : doc["nodes"]) {
    if (node["name"] == name) return node;
  }
  ADD_FAILURE() << "no node " << name;
  static const Json none;
  return none;
}

TEST(GltfWriter, NodeMatricesAreWrittenColumnsFirstWithFullPrecision) {
  Scene scene = sceneOf(testing::kCameraRecord +
                        "SPHERE\n1 1 1\n0.1 0 0 1.0000000000000002\n0 0.2 0 -3\n0 0 0.3 "
                        "0.30000000000000004\n0 0 0 1\n");
  Written w = write(scene);
  const Json& m = nodeNamed(w.doc, "SPHERE 1")["matrix"];
  ASSERT_EQ(m.size(), 16u);
  // Column by column: the translation is the last four entries.
  EXPECT_EQ(m[0].get<double>(), 0.1);
  EXPECT_EQ(m[5].get<double>(), 0.2);
  EXPECT_EQ(m[10].get<double>(), 0.3);
  EXPECT_EQ(m[12].get<double>(), 1.0000000000000002);
  EXPECT_EQ(m[13].get<double>(), -3.0);
  EXPECT_EQ(m[14].get<double>(), 0.30000000000000004);
  EXPECT_EQ(m[15].get<double>(), 1.0);
  // The camera's node holds the camera-to-world matrix.
  EXPECT_EQ(nodeNamed(w.doc, "CAMERA")["matrix"][14].get<double>(), 5.0);
}

TEST(GltfWriter, MeshesCarryBoundsUnitNormalsAndAlignedViews) {
  Scene scene = sceneOf(kScene);
  for (bool binary : {false, true}) {
    Written w = write(scene, {}, binary);
    ASSERT_EQ(w.doc["buffers"].size(), 1u);
    std::string data = w.bin;
    if (!binary) {
      // Embedded: decode what the data URI holds.
      std::string uri = w.doc["buffers"][0]["uri"];
      ASSERT_EQ(uri.rfind("data:application/octet-stream;base64,", 0), 0u);
      EXPECT_EQ(w.doc["buffers"][0]["byteLength"].get<std::size_t>() % 4, 0u);
      continue;
    }
    EXPECT_EQ(data.size() % 4, 0u);
    EXPECT_EQ(w.doc["buffers"][0]["byteLength"].get<std::size_t>(), data.size());
    for (const Json& view : w.doc["bufferViews"]) {
      EXPECT_EQ(view["byteOffset"].get<std::size_t>() % 4, 0u);
      EXPECT_LE(view["byteOffset"].get<std::size_t>() + view["byteLength"].get<std::size_t>(),
                data.size());
    }
    // Three kinds, one vertex set each: the meshes share accessors.
    std::set<int> positions;
    for (const Json& mesh : w.doc["meshes"]) {
      const Json& prim = mesh["primitives"][0];
      int position = prim["attributes"]["POSITION"];
      int normal = prim["attributes"]["NORMAL"];
      positions.insert(position);
      const Json& a = w.doc["accessors"][position];
      ASSERT_TRUE(a.contains("min") && a.contains("max"));
      const Json& view = w.doc["bufferViews"][a["bufferView"].get<int>()];
      std::size_t count = a["count"];
      std::vector<float> xyz(3 * count);
      std::memcpy(xyz.data(), data.data() + view["byteOffset"].get<std::size_t>(), 12 * count);
      for (int k = 0; k < 3; ++k) {
        float lo = xyz[k], hi = xyz[k];
        for (std::size_t i = 0; i < count; ++i) {
          lo = std::min(lo, xyz[3 * i + k]);
          hi = std::max(hi, xyz[3 * i + k]);
        }
        EXPECT_EQ(a["min"][k].get<double>(), lo);
        EXPECT_EQ(a["max"][k].get<double>(), hi);
      }
      const Json& na = w.doc["accessors"][normal];
      const Json& nview = w.doc["bufferViews"][na["bufferView"].get<int>()];
      std::vector<float> n(3 * count);
      std::memcpy(n.data(), data.data() + nview["byteOffset"].get<std::size_t>(), 12 * count);
      for (std::size_t i = 0; i < count; ++i) {
        EXPECT_NEAR(std::sqrt(n[3 * i] * n[3 * i] + n[3 * i + 1] * n[3 * i + 1] +
                              n[3 * i + 2] * n[3 * i + 2]),
                    1.0, 1e-6);
      }
    }
    EXPECT_EQ(positions.size(), 3u);
  }
}

TEST(GltfWriter, TheInfinitePlaneIsMadeFiniteWithAWarning) {
  Scene scene = sceneOf(kScene);
  Written w = write(scene);
  std::vector<Diagnostic> finite = withCode(w.diagnostics, DiagnosticCode::PlaneMadeFinite);
  ASSERT_EQ(finite.size(), 1u);
  EXPECT_EQ(finite[0].severity, Severity::Warning);
  EXPECT_EQ(finite[0].span.line, 19u);
  // Sized from the scene's bounds: the sphere reaches past x = 20.
  EXPECT_NE(finite[0].message.find("half-size 64"), std::string::npos) << finite[0].message;
  EXPECT_EQ(withCode(w.diagnostics, DiagnosticCode::LightFalloff).size(), 1u);
  // noLoss: an error, and nothing written.
  DiagnosticList out;
  EXPECT_FALSE(writeGltf(scene, testing::noLossConversion(), false, out).has_value());
  EXPECT_TRUE(out.hasErrors());
}

TEST(GltfWriter, CameraLightsAndMaterialsMapAsDocumented) {
  Scene scene = sceneOf(testing::kCameraRecord +
                        "LIGHT\n2 1 0.5\n1 0 0 1\n0 1 0 2\n0 0 1 3\n0 0 0 1\n"
                        "SPHERE\n1.5 0.25 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n");
  Object& sphere = scene.objects[0];
  sphere.material.shininess = 30;
  sphere.material.specular = 0.5;
  sphere.material.transparency = 0.25;
  sphere.material.ri = 1.33;
  sphere.material.ambient = 0.2;
  GltfWriteOptions options;
  options.yfovDegrees = 45;
  options.width = 640;
  options.height = 480;
  Written w = write(scene, options);
  const Json& perspective = w.doc["cameras"][0]["perspective"];
  EXPECT_DOUBLE_EQ(perspective["yfov"].get<double>(), 45 * std::acos(-1.0) / 180);
  EXPECT_DOUBLE_EQ(perspective["aspectRatio"].get<double>(), 640.0 / 480.0);
  // The light at (1, 2, 3) is matched 3 from where the camera's ray meets
  // the sphere, (0, 0, 1), for a surface of COLOUR 0.8: each channel is
  // decoded from sRGB there, and 683 * pi lux shows as 1 (docs/GLTF.md).
  const Json& light = w.doc["extensions"]["KHR_lights_punctual"]["lights"][0];
  EXPECT_EQ(light["type"], "point");
  auto decode = [](double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  };
  EXPECT_NEAR(light["intensity"].get<double>() / (decode(1.6) / 0.8 * 683 * std::acos(-1.0) * 9),
              1.0, 1e-12);
  EXPECT_NEAR(light["color"][0].get<double>(), 1.0, 1e-15);
  EXPECT_NEAR(light["color"][1].get<double>(), decode(0.8) / decode(1.6), 1e-15);
  EXPECT_NEAR(light["color"][2].get<double>(), decode(0.4) / decode(1.6), 1e-15);
  const Json& lightNode = nodeNamed(w.doc, "LIGHT 1");
  EXPECT_EQ(lightNode["extras"]["sf"]["colour"], Json::array({2.0, 1.0, 0.5}));
  EXPECT_EQ(lightNode["extras"]["sf"]["referenceDistance"].get<double>(), 3.0);
  std::vector<Diagnostic> falloff = withCode(w.diagnostics, DiagnosticCode::LightFalloff);
  ASSERT_EQ(falloff.size(), 1u);
  EXPECT_NE(falloff[0].message.find("reference distance 3, from the light to the point the "
                                    "camera looks at, on the first object its forward ray meets, "
                                    "(0 0 1)"),
            std::string::npos)
      << falloff[0].message;
  // COLOUR (clamped) times AMBIENT + DIFFUSE (1.1, clamped), plus the
  // weight of TRANSPARENCY 0.25, which transmits that weight's share of the
  // largest channel; the refracted share is sharp (docs/GLTF.md).
  const Json& m = w.doc["materials"][0];
  double g = 0.25;
  EXPECT_EQ(m["pbrMetallicRoughness"]["baseColorFactor"], Json::array({1.0, 0.25 + g, g, 1.0}));
  EXPECT_EQ(m["pbrMetallicRoughness"]["metallicFactor"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(m["pbrMetallicRoughness"]["roughnessFactor"].get<double>(),
                   (1 - g / (1 + g)) * std::pow(2.0 / 32.0, 0.25));
  EXPECT_EQ(m["extensions"]["KHR_materials_ior"]["ior"].get<double>(), 1.33);
  EXPECT_DOUBLE_EQ(
      m["extensions"]["KHR_materials_transmission"]["transmissionFactor"].get<double>(),
      g / (1 + g));
  EXPECT_EQ(m["extensions"]["KHR_materials_specular"]["specularFactor"].get<double>(), 0.5);
  EXPECT_EQ(m["extras"]["sf"]["colour"], Json::array({1.5, 0.25, 0.0}));
  EXPECT_EQ(m["extras"]["sf"]["ambient"].get<double>(), 0.2);
  // The colour above 1 is clamped with a warning; AMBIENT rides in extras.
  EXPECT_EQ(withCode(w.diagnostics, DiagnosticCode::GltfValueClamped).size(), 1u);
  EXPECT_EQ(withCode(w.diagnostics, DiagnosticCode::GltfExtrasOnly).size(), 1u);
  // A default material carries no extension at all.
  Written plain =
      write(sceneOf(testing::kCameraRecord + "CUBE\n1 1 1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n"));
  EXPECT_FALSE(plain.doc["materials"][0].contains("extensions"));
  EXPECT_FALSE(plain.doc.contains("extensionsUsed"));
}

TEST(GltfWriter, ShearAndLargeScalesBecomeChainsOfTrsNodes) {
  Scene scene = sceneOf(testing::kCameraRecord +
                        "CUBE\n1 1 1\n1 0.5 0 2\n0 1 0 0\n0 0 1 0\n0 0 0 1\n"
                        "SPHERE\n1 1 1\n0 -300 0 0\n200 0 0 0\n0 0 1 0\n0 0 0 1\n");
  Written w = write(scene);
  EXPECT_EQ(withCode(w.diagnostics, DiagnosticCode::GltfMatrixSplit).size(), 1u);
  // The cube: translation and rotation, scale, rotation; the sphere has no
  // shear and needs no third node.
  ASSERT_EQ(w.doc["scenes"][0]["nodes"].size(), 3u);
  auto matrixOf = [](const Json& node) {
    glm::dmat4 m;
    for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = node["matrix"][i].get<double>();
    return m;
  };
  for (std::size_t root = 1; root < 3; ++root) {
    int index = w.doc["scenes"][0]["nodes"][root];
    glm::dmat4 product(1.0);
    for (;;) {
      const Json& node = w.doc["nodes"][index];
      glm::dmat4 m = matrixOf(node);
      EXPECT_TRUE(gltf::isTrsMatrix(m));
      product = product * m;
      if (!node.contains("children")) break;
      index = node["children"][0];
    }
    EXPECT_LT(gltf::matrixDistance(product, scene.objects[root - 1].matrix), 1e-15);
  }
}

TEST(GltfWriter, ExternalBufferIsNamedByItsUri) {
  GltfWriteOptions options;
  options.externalBuffer = "my scene.bin";
  Written w = write(sceneOf(kScene), options);
  EXPECT_EQ(w.doc["buffers"][0]["uri"], "my%20scene.bin");
  EXPECT_EQ(w.doc["buffers"][0]["byteLength"].get<std::size_t>(), w.bin.size());
}

TEST(Glb, EncodesAndDecodesWithPaddingAndRejectsBadLengths) {
  std::string file = encodeGlb("{\"a\":1}", std::string("\x01\x02\x03", 3));
  EXPECT_EQ(file.size() % 4, 0u);
  std::string error;
  std::optional<GlbChunks> chunks = decodeGlb(file, error);
  ASSERT_TRUE(chunks) << error;
  EXPECT_EQ(chunks->json, "{\"a\":1} ");
  EXPECT_EQ(chunks->bin->substr(0, 3), std::string("\x01\x02\x03", 3));
  std::string cut = file.substr(0, file.size() - 4);
  EXPECT_FALSE(decodeGlb(cut, error));
  EXPECT_NE(error.find("length"), std::string::npos);
  std::string lying = file;
  lying[12] = '\x7f';  // the JSON chunk claims more than there is
  lying[15] = '\x7f';
  EXPECT_FALSE(decodeGlb(lying, error));
}

}  // namespace
}  // namespace scene
