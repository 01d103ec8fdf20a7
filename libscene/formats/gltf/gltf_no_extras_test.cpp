// The glTF written without extras (GltfWriteOptions::extras): nothing of
// ours in the file, the loss said once, and the file read back by fitting
// each mesh.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "libscene/formats/gltf/gltf_writer.h"
#include "libscene/testing/test_support.h"
#include "scenefile/read.h"

namespace scene {
namespace {

using Json = nlohmann::json;
using testing::withCode;

// The four primitives, with an OUTPUT_FILE, an AMBIENT and a COLOUR that
// only extras hold exactly.
Scene fourPrimitives() {
  ReadResult read = parseScene(testing::kCameraRecord + testing::kLightRecord +
                                   "SPHERE\n1 0 0\n1 0 0 -3\n0 1 0 0\n0 0 1 -2\n0 0 0 1\n"
                                   "CUBE\n0 1 0\n0.5 0 0 0\n0 0.5 0 0\n0 0 0.5 -2\n0 0 0 1\n"
                                   "CYLINDER\n0 0 1\n1 0 0 3\n0 1 0 0\n0 0 1 -2\n0 0 0 1\n"
                                   "PLANE\n2 2 2\n1 0 0 0\n0 1 0 -1\n0 0 1 0\n0 0 0 1\n",
                               "four.sf");
  EXPECT_TRUE(read.ok());
  read.scene.objects[0].material.ambient = 0.3;
  read.scene.outputFile = "out.png";
  return read.scene;
}

std::string written(const Scene& scene, bool extras, DiagnosticList& out) {
  GltfWriteOptions options;
  options.extras = extras;
  std::optional<GltfFiles> files = writeGltf(scene, testing::conversionWith(options), false, out);
  EXPECT_TRUE(files.has_value());
  return files ? files->main : "";
}

TEST(GltfNoExtras, TheFileHoldsNoExtrasAnywhere) {
  DiagnosticList out;
  std::string text = written(fourPrimitives(), false, out);
  EXPECT_EQ(text.find("\"extras\""), std::string::npos) << text;
  Json doc = Json::parse(text);
  EXPECT_EQ(doc["nodes"].size(), 6u);
  EXPECT_EQ(doc["meshes"].size(), 4u);
}

TEST(GltfNoExtras, TheLossIsReportedOnceAndNoHintPointsAtExtras) {
  DiagnosticList out;
  written(fourPrimitives(), false, out);
  std::vector<Diagnostic> left = withCode(out, DiagnosticCode::GltfExtrasLeftOut);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].severity, Severity::Warning);
  EXPECT_NE(left[0].message.find("the glTF is written without extras"), std::string::npos);
  for (const Diagnostic& d : out.items()) {
    EXPECT_EQ(d.message.find("rides in extras"), std::string::npos) << d.message;
    EXPECT_EQ(d.hint.find("rides in extras"), std::string::npos) << d.hint;
  }
  // AMBIENT, which only extras could hold, is a plain loss.
  EXPECT_TRUE(withCode(out, DiagnosticCode::GltfExtrasOnly).empty());
  std::vector<Diagnostic> ambient = withCode(out, DiagnosticCode::LossMaterial);
  ASSERT_EQ(ambient.size(), 1u);
  EXPECT_EQ(ambient[0].severity, Severity::Warning);
  EXPECT_EQ(ambient[0].message,
            "AMBIENT 0.3 of SPHERE object 1 has no glTF counterpart and is dropped: the glTF is "
            "written without extras");
  // Where no loss is allowed, it is an error, and nothing is written.
  GltfWriteOptions options;
  options.extras = false;
  ConversionOptions strict = testing::conversionWith(options);
  strict.noLoss = true;
  DiagnosticList refused;
  EXPECT_FALSE(writeGltf(fourPrimitives(), strict, false, refused).has_value());
  ASSERT_EQ(withCode(refused, DiagnosticCode::GltfExtrasLeftOut).size(), 1u);
  EXPECT_EQ(withCode(refused, DiagnosticCode::GltfExtrasLeftOut)[0].severity, Severity::Error);
}

TEST(GltfNoExtras, ReadsBackByMeshFittingWithTheSameKinds) {
  Scene scene = fourPrimitives();
  DiagnosticList out;
  ReadResult back = parseScene(written(scene, false, out), "plain.gltf");
  ASSERT_TRUE(back.ok());
  EXPECT_FALSE(withCode(back.diagnostics, DiagnosticCode::GltfMeshFit).empty());
  ASSERT_EQ(back.scene.objects.size(), scene.objects.size());
  std::multiset<ObjectKind> want;
  std::multiset<ObjectKind> got;
  for (const Object& o : scene.objects) want.insert(o.kind);
  for (const Object& o : back.scene.objects) got.insert(o.kind);
  EXPECT_EQ(got, want);
  EXPECT_FALSE(back.scene.outputFile.has_value());
}

TEST(GltfNoExtras, TheDefaultKeepsEveryExtras) {
  DiagnosticList out;
  Json doc = Json::parse(written(fourPrimitives(), true, out));
  EXPECT_TRUE(withCode(out, DiagnosticCode::GltfExtrasLeftOut).empty());
  EXPECT_EQ(withCode(out, DiagnosticCode::GltfExtrasOnly).size(), 1u);
  EXPECT_EQ(doc["asset"]["extras"]["sf"]["outputFile"], "out.png");
  for (const char* array : {"nodes", "meshes", "materials"}) {
    for (const Json& item : doc[array]) EXPECT_TRUE(item["extras"].contains("sf")) << item.dump();
  }
  // Read back from extras, exactly.
  ReadResult back = parseScene(doc.dump(), "exact.gltf");
  ASSERT_TRUE(back.ok());
  EXPECT_TRUE(withCode(back.diagnostics, DiagnosticCode::GltfMeshFit).empty());
  EXPECT_EQ(back.scene.objects[0].material.ambient, 0.3);
}

}  // namespace
}  // namespace scene
