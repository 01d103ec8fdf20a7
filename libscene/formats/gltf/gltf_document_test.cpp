#include "libscene/formats/gltf/gltf_document.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <fstream>
#include <new>
#include <nlohmann/json.hpp>
#include <string>

#include "libscene/formats/gltf/gltf_json_scan.h"
#include "libscene/formats/gltf/gltf_reader.h"
#include "libscene/formats/gltf/gltf_writer.h"
#include "libscene/testing/test_support.h"
#include "scenefile/read.h"

namespace scene {
namespace {

using Json = nlohmann::json;
using testing::withCode;

// A file of no mesh at all, with a camera: valid but for what a test sets.
Json cameraOnly() {
  return Json::parse(R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}],
    "nodes": [{"camera": 0}],
    "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}]})");
}

TEST(GltfDocument, AnIndexOfTheWrongTypeIsAnErrorAtItsPointerAndLine) {
  for (const char* value : {"-1", "0.5", "\"0\"", "null", "4294967296", "true", "[0]"}) {
    std::string text =
        std::string("{\"asset\": {\"version\": \"2.0\"},\n\"nodes\": [{},\n {\"mesh\": ") + value +
        "}],\n\"meshes\": []}";
    for (bool noLoss : {false, true}) {
      ReadOptions options;
      options.noLoss = noLoss;
      ReadResult read = parseGltf(text, "i.gltf", ".", options);
      ASSERT_FALSE(read.ok()) << value;
      const Diagnostic& d = read.diagnostics.items().front();
      EXPECT_EQ(d.message.rfind("/nodes/1/mesh ", 0), 0u) << d.message;
      EXPECT_EQ(d.span.line, 3u) << value;
      EXPECT_EQ(d.span.column, 11u) << value;
    }
  }
}

TEST(GltfDocument, EveryIndexTheReaderFollowsIsChecked) {
  const char* cases[][2] = {
      {"/scenes/0/nodes/0", R"({"scenes": [{"nodes": ["0"]}]})"},
      {"/nodes/0/children/0", R"({"nodes": [{"children": [-2]}]})"},
      {"/meshes/0/primitives/0/attributes/POSITION",
       R"({"meshes": [{"primitives": [{"attributes": {"POSITION": 1.5}}]}]})"},
      {"/meshes/0/primitives/0/indices",
       R"({"meshes": [{"primitives": [{"attributes": {}, "indices": null}]}]})"},
      {"/meshes/0/primitives", R"({"meshes": [{"primitives": []}]})"},
      {"/meshes/0", R"({"meshes": [{"name": "no primitives"}]})"},
      {"/bufferViews/0/buffer", R"({"bufferViews": [{"buffer": 7, "byteLength": 4}]})"},
      {"/nodes/0", R"({"nodes": [3]})"},
  };
  for (const auto& [pointer, text] : cases) {
    Json doc = Json::parse(text);
    doc["asset"] = {{"version", "2.0"}};
    std::vector<gltf::DocumentProblem> found = gltf::checkDocument(doc, false);
    ASSERT_EQ(found.size(), 1u) << text;
    EXPECT_EQ(found[0].pointer, pointer);
    EXPECT_EQ(found[0].severity, Severity::Error);
  }
}

TEST(GltfDocument, ANodeTransformOfTheWrongTypeOrShapeIsAnErrorAtTheNode) {
  const char* cases[][2] = {
      {"/nodes/0/translation/0", R"({"translation": ["1", 0, 0]})"},
      {"/nodes/0/translation", R"({"translation": {"x": 5}})"},
      {"/nodes/0/translation", R"({"translation": [1, 2, 3, 4]})"},
      {"/nodes/0/matrix/3", R"({"matrix": [1, 0, 0, false, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]})"},
      {"/nodes/0/matrix", R"({"matrix": []})"},
      {"/nodes/0/scale/2", R"({"scale": [1, 1, {}]})"},
      {"/nodes/0/scale", R"({"scale": 2})"},
      {"/nodes/0/rotation", R"({"rotation": [0, 0, 0, 0]})"},
      {"/nodes/0/rotation", R"({"rotation": [0, 0, 0, 0.99]})"},
      {"/nodes/0/rotation/1", R"({"rotation": [0, null, 0, 1]})"},
      {"/nodes/0/scale", R"({"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1],
                             "scale": [1, 1, 1]})"},
  };
  for (const auto& [pointer, node] : cases) {
    Json doc = {{"asset", {{"version", "2.0"}}}, {"nodes", {Json::parse(node)}}};
    std::vector<gltf::DocumentProblem> found = gltf::checkDocument(doc, false);
    ASSERT_EQ(found.size(), 1u) << node;
    EXPECT_EQ(found[0].pointer, pointer) << node;
    EXPECT_EQ(found[0].severity, Severity::Error);
    EXPECT_NE(found[0].message.find("node 0"), std::string::npos) << found[0].message;
  }
  // Within the Khronos validator's tolerance a rotation is a unit
  // quaternion, and the reader normalises it.
  for (const char* node :
       {R"({"rotation": [0, 0, 0, 0.9924]})", R"({"rotation": [0, 0, 0, 1.0076]})",
        R"({"rotation": [0.5, 0.5, 0.5, 0.5]})",
        R"({"translation": [1e300, 0, -1e-300], "scale": [0, 0, 0]})"}) {
    Json doc = {{"asset", {{"version", "2.0"}}}, {"nodes", {Json::parse(node)}}};
    EXPECT_TRUE(gltf::checkDocument(doc, false).empty()) << node;
  }
}

TEST(GltfDocument, ValuesGltfBoundsAreErrorsAndWhatAScenefileCannotHoldIsALoss) {
  struct Case {
    const char* pointer;
    Json value;
    Severity severity;
    DiagnosticCode code;
  };
  const Case cases[] = {
      {"/cameras/0/perspective/yfov", 0.0, Severity::Error, DiagnosticCode::GltfInvalid},
      {"/cameras/0/perspective/yfov", -1.0, Severity::Error, DiagnosticCode::GltfInvalid},
      {"/cameras/0/perspective/yfov", 3.5, Severity::Warning, DiagnosticCode::GltfIgnored},
      {"/cameras/0/perspective/aspectRatio", 0.0, Severity::Error, DiagnosticCode::GltfInvalid},
      {"/cameras/0/perspective/aspectRatio", 1.5, Severity::Warning, DiagnosticCode::GltfIgnored},
  };
  for (const Case& c : cases) {
    Json doc = cameraOnly();
    doc[Json::json_pointer(c.pointer)] = c.value;
    std::vector<gltf::DocumentProblem> found = gltf::checkDocument(doc, false);
    ASSERT_EQ(found.size(), 1u) << c.pointer << " " << c.value;
    EXPECT_EQ(found[0].pointer, c.pointer);
    EXPECT_EQ(found[0].severity, c.severity);
    EXPECT_EQ(found[0].code, c.code);
    if (c.severity == Severity::Warning) {
      EXPECT_EQ(gltf::checkDocument(doc, true)[0].severity, Severity::Error);
    }
  }
}

TEST(GltfDocument, LightsAndEmission) {
  Json doc = cameraOnly();
  doc["extensions"]["KHR_lights_punctual"]["lights"] =
      Json::parse(R"([{"type": "point", "intensity": -1}, {"type": "point", "range": 5},
                      {"type": "point", "color": [2, 0, 0], "intensity": 1e308},
                      {"type": "point", "range": 0}])");
  doc["materials"] =
      Json::parse(R"([{"emissiveFactor": [0, 0.5, 0]}, {"emissiveFactor": [0, 0, 0]}])");
  std::vector<gltf::DocumentProblem> found = gltf::checkDocument(doc, false);
  ASSERT_EQ(found.size(), 5u);
  EXPECT_EQ(found[0].pointer, "/materials/0/emissiveFactor");
  EXPECT_EQ(found[0].severity, Severity::Warning);
  EXPECT_EQ(found[1].pointer, "/extensions/KHR_lights_punctual/lights/0/intensity");
  EXPECT_EQ(found[1].code, DiagnosticCode::GltfInvalid);
  EXPECT_EQ(found[2].pointer, "/extensions/KHR_lights_punctual/lights/1/range");
  EXPECT_EQ(found[2].severity, Severity::Warning);
  EXPECT_EQ(found[3].pointer, "/extensions/KHR_lights_punctual/lights/2/intensity");
  EXPECT_EQ(found[3].code, DiagnosticCode::ValueNotFinite);
  EXPECT_EQ(found[4].pointer, "/extensions/KHR_lights_punctual/lights/3/range");
  EXPECT_EQ(found[4].code, DiagnosticCode::GltfInvalid);
}

TEST(GltfDocument, ObjectsAreCountedFromTheBytesAndAgainstMaxGltfNodes) {
  EXPECT_EQ(gltf::scanJson(
                R"({"asset": {"a": [{}]}, "nodes": [{}, {"children": [{}]}], "materials": [{}],)"
                R"( "x": "nodes", "cameras": [{}, {}]})",
                kMaxJsonDepth)
                .objects,
            2u + 5u + 4u);
  std::string text = R"({"asset": {"version": "2.0"}, "nodes": [{}, {}, {}, {}]})";
  ReadOptions options;
  options.gltf.maxNodes = 3;
  ReadResult read = parseGltf(text, "n.gltf", ".", options);
  ASSERT_EQ(withCode(read.diagnostics, DiagnosticCode::GltfTooManyNodes).size(), 1u);
  options.gltf.maxNodes = 4;
  EXPECT_TRUE(withCode(parseGltf(text, "n.gltf", ".", options).diagnostics,
                       DiagnosticCode::GltfTooManyNodes)
                  .empty());
  // Primitives count too, once the document is parsed.
  Json doc = Json::parse(text);
  doc["meshes"] = Json::parse(R"([{"primitives": [{}, {}]}])");
  EXPECT_EQ(gltf::countObjects(doc), 7u);
}

TEST(GltfDocument, TinygltfIsGivenOnlyWhatIsRead) {
  Json doc = Json::parse(R"({"asset": {"version": "2.0", "extras": [1, 2, 3]},
    "nodes": [{"extras": {"sf": {"record": "CUBE"}, "junk": [1]},
               "extensions": {"EXT_other": {}, "KHR_lights_punctual": {"light": 0, "x": 1}}}],
    "materials": [{"extras": {"sf": {"colour": [1, 1, 1]}}}],
    "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "junk": [1, 2]}]}}})");
  gltf::OwnExtras own = gltf::trimForTinygltf(doc);
  EXPECT_EQ(own.nodes, std::vector<std::string>{R"({"sf":{"record":"CUBE"}})"});
  EXPECT_EQ(own.materials, std::vector<std::string>{R"({"sf":{"colour":[1,1,1]}})"});
  EXPECT_EQ(doc.dump(), R"({"asset":{"version":"2.0"},"extensions":{"KHR_lights_punctual":)"
                        R"({"lights":[{"type":"point"}]}},"materials":[{}],)"
                        R"("nodes":[{"extensions":{"KHR_lights_punctual":{"light":0}}}]})");
}

// Our own file, edited so that the SPHERE's node points at the CUBE's mesh:
// the extras still say SPHERE, but the mesh is a cube's, so they are stale.
TEST(GltfDocument, ExtrasAreStaleWhenTheNodePointsAtAnotherKindsMesh) {
  ReadResult original = parseScene(testing::kCameraRecord + testing::kLightRecord +
                                       "SPHERE\n1 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n"
                                       "CUBE\n1 0 0\n1 0 0 3\n0 1 0 0\n0 0 1 0\n0 0 0 1\n",
                                   "a.sf");
  ASSERT_TRUE(original.ok());
  DiagnosticList out;
  std::optional<GltfFiles> files = writeGltf(original.scene, {}, false, out);
  ASSERT_TRUE(files);
  Json doc = Json::parse(files->main);
  int sphere = -1, cube = -1;
  for (std::size_t i = 0; i < doc["nodes"].size(); ++i) {
    std::string name = doc["nodes"][i].value("name", "");
    if (name.starts_with("SPHERE")) sphere = static_cast<int>(i);
    if (name.starts_with("CUBE")) cube = static_cast<int>(i);
  }
  ASSERT_GE(sphere, 0);
  ASSERT_GE(cube, 0);
  ReadResult unedited = parseScene(doc.dump(), "own.gltf");
  ASSERT_TRUE(unedited.ok());
  EXPECT_TRUE(withCode(unedited.diagnostics, DiagnosticCode::GltfExtrasStale).empty());
  doc["nodes"][sphere]["mesh"] = doc["nodes"][cube]["mesh"];
  ReadResult read = parseScene(doc.dump(), "edited.gltf");
  ASSERT_TRUE(read.ok());
  ASSERT_EQ(read.scene.objects.size(), 2u);
  EXPECT_EQ(read.scene.objects[0].kind, ObjectKind::Cube);
  EXPECT_EQ(withCode(read.diagnostics, DiagnosticCode::GltfExtrasStale).size(), 1u);
}

// Reads `text` with the address space held to what the process holds now
// and 200 MiB more (enough for the text and its parse, some 80 MiB, not
// for tinygltf's nodes); exits 42 on std::bad_alloc.
[[noreturn]] void readUnderAddressLimit(const std::string& text) {
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0;
  statm >> pages;
  rlim_t limit = pages * static_cast<rlim_t>(sysconf(_SC_PAGESIZE)) + (rlim_t{200} << 20);
  rlimit as{limit, limit};
  setrlimit(RLIMIT_AS, &as);
  try {
    ReadResult read = parseGltf(text, "m.gltf", ".");
    _exit(read.ok() ? 1 : 2);
  } catch (const std::bad_alloc&) {
    _exit(42);
  }
}

// Under a limit on its address space, reading a file of a million nodes
// runs out of memory inside tinygltf, which catches std::bad_alloc and
// returns its text: the reader sends it on as std::bad_alloc, for the tools
// to report, and never as "not a valid glTF 2.0 file".
TEST(GltfReaderDeathTest, OutOfMemoryIsBadAllocNotADiagnostic) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reserves more address space than the limit";
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer)
  GTEST_SKIP() << "the sanitizer reserves more address space than the limit";
#endif
#endif
  std::string text = R"({"asset": {"version": "2.0"}, "nodes": [)";
  for (int i = 0; i < 999'998; ++i) text += "{},";
  text += "{}]}";
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(readUnderAddressLimit(text), ::testing::ExitedWithCode(42), "");
}

}  // namespace
}  // namespace scene
