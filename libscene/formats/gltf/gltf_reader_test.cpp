#include "libscene/formats/gltf/gltf_reader.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>

#include "libscene/formats/gltf/gltf_writer.h"
#include "libscene/testing/random_cases.h"
#include "libscene/testing/test_support.h"
#include "scenefile/mesh.h"
#include "scenefile/read.h"

namespace scene {
namespace {

using Json = nlohmann::json;
namespace fs = std::filesystem;
using testing::withCode;

// A glTF as another program writes it: meshes of the library's primitives
// (rounded to float), put on nodes by the caller.
class ThirdParty {
 public:
  // Adds a mesh of `mesh` moved by `bake` into its own vertices; returns its index.
  int addMesh(const TriangleMesh& mesh, const glm::dmat4& bake, int primitives = 1) {
    std::vector<float> xyz;
    for (const glm::vec3& p : mesh.positions) {
      glm::dvec3 q(bake * glm::dvec4(glm::dvec3(p), 1.0));
      xyz.insert(xyz.end(),
                 {static_cast<float>(q.x), static_cast<float>(q.y), static_cast<float>(q.z)});
    }
    int position = addAccessor(xyz.data(), xyz.size() * 4, mesh.positions.size(), "VEC3", 5126);
    Json prims = Json::array();
    std::size_t per = mesh.indices.size() / 3 / primitives * 3;
    for (int p = 0; p < primitives; ++p) {
      std::size_t begin = p * per, end = p + 1 == primitives ? mesh.indices.size() : begin + per;
      std::vector<std::uint32_t> part(mesh.indices.begin() + begin, mesh.indices.begin() + end);
      int indices = addAccessor(part.data(), part.size() * 4, part.size(), "SCALAR", 5125);
      prims.push_back({{"attributes", {{"POSITION", position}}}, {"indices", indices}});
    }
    doc_["meshes"].push_back({{"primitives", prims}});
    return static_cast<int>(doc_["meshes"].size() - 1);
  }
  Json& doc() { return doc_; }
  std::string text() {
    Json d = doc_;
    d["buffers"] = Json::array({{{"byteLength", data_.size()},
                                 {"uri", "data:application/octet-stream;base64," + base64()}}});
    return d.dump();
  }

 private:
  int addAccessor(const void* bytes, std::size_t size, std::size_t count, const char* type,
                  int componentType) {
    std::size_t offset = data_.size();
    data_.append(static_cast<const char*>(bytes), size);
    doc_["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}});
    doc_["accessors"].push_back({{"bufferView", doc_["bufferViews"].size() - 1},
                                 {"componentType", componentType},
                                 {"count", count},
                                 {"type", type}});
    return static_cast<int>(doc_["accessors"].size() - 1);
  }
  std::string base64() const {
    static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < data_.size(); i += 3) {
      std::uint32_t v = static_cast<unsigned char>(data_[i]) << 16;
      if (i + 1 < data_.size()) v |= static_cast<unsigned char>(data_[i + 1]) << 8;
      if (i + 2 < data_.size()) v |= static_cast<unsigned char>(data_[i + 2]);
      out += k[v >> 18 & 63];
      out += k[v >> 12 & 63];
      out += i + 1 < data_.size() ? k[v >> 6 & 63] : '=';
      out += i + 2 < data_.size() ? k[v & 63] : '=';
    }
    return out;
  }

  Json doc_ = {{"asset", {{"version", "2.0"}}},
               {"meshes", Json::array()},
               {"accessors", Json::array()},
               {"bufferViews", Json::array()}};
  std::string data_;
};

glm::dmat4 scaleMatrix(double x, double y, double z) {
  glm::dmat4 m(1.0);
  m[0][0] = x;
  m[1][1] = y;
  m[2][2] = z;
  return m;
}

double difference(const glm::dmat4& a, const glm::dmat4& b) {
  double d = 0.0;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) d = std::max(d, std::abs(a[c][r] - b[c][r]));
  }
  return d;
}

TEST(GltfReader, ComposesTheHierarchyAndBakesTheMeshSizeIntoTheMatrix) {
  ThirdParty file;
  int sphere = file.addMesh(sphereMesh(24), scaleMatrix(0.5, 0.5, 0.5));
  file.doc()["nodes"] = {{{"name", "parent"},
                          {"translation", {1, 2, 3}},
                          {"rotation", {0, 0.7071067811865476, 0, 0.7071067811865476}},
                          {"scale", {2, 2, 2}},
                          {"children", {1}}},
                         {{"name", "ball"},
                          {"mesh", sphere},
                          {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 4, 1}}},
                         {{"name", "eye"}, {"camera", 0}, {"translation", {0, 0, 10}}}};
  file.doc()["cameras"] = {
      {{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}};
  file.doc()["scenes"] = {{{"nodes", {0, 2}}}};
  ReadResult read = parseScene(file.text(), "third.gltf");
  ASSERT_TRUE(read.ok()) << read.diagnostics.items().front().message;
  ASSERT_EQ(read.scene.objects.size(), 1u);
  // parent: T(1,2,3) Ry(90) S(2); child: T(0,0,4); mesh: radius 0.5.
  glm::dmat4 want(0.0);
  want[0] = {0, 0, -1, 0};
  want[1] = {0, 1, 0, 0};
  want[2] = {1, 0, 0, 0};
  want[3] = {1 + 8, 2, 3, 1};
  EXPECT_LT(difference(read.scene.objects[0].matrix, want), 1e-6);
  EXPECT_EQ(read.scene.objects[0].kind, ObjectKind::Sphere);
  EXPECT_EQ(read.scene.camera.matrix[3], glm::dvec4(0, 0, 10, 1));
  std::vector<Diagnostic> fov = withCode(read.diagnostics, DiagnosticCode::CameraFov);
  ASSERT_EQ(fov.size(), 1u);
  ASSERT_EQ(fov[0].remedies.size(), 1u);
  EXPECT_EQ(fov[0].remedies[0].setting, Setting::FieldOfView);
  EXPECT_TRUE(fov[0].remedies[0].value.starts_with("28.64789")) << fov[0].remedies[0].value;
}

TEST(GltfReader, AMeshSplitIntoPrimitivesIsOneShape) {
  ThirdParty file;
  int box = file.addMesh(cubeMesh(), scaleMatrix(1, 2, 3), 3);
  file.doc()["nodes"] = {{{"mesh", box}}};
  ReadResult read = parseScene(file.text(), "split.gltf");
  ASSERT_TRUE(read.ok());
  ASSERT_EQ(read.scene.objects.size(), 1u);
  EXPECT_EQ(read.scene.objects[0].kind, ObjectKind::Cube);
  EXPECT_LT(difference(read.scene.objects[0].matrix, scaleMatrix(1, 2, 3)), 1e-7);
}

TEST(GltfReader, AMeshThatIsNoPrimitiveIsSkippedOrFailsUnderNoLoss) {
  ThirdParty file;
  TriangleMesh pyramid;
  pyramid.positions = {{0, 1, 0}, {-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
  pyramid.normals = pyramid.positions;
  pyramid.indices = {0, 1, 4, 0, 4, 3, 0, 3, 2, 0, 2, 1, 1, 2, 3, 1, 3, 4};
  int mesh = file.addMesh(pyramid, glm::dmat4(1.0));
  file.doc()["nodes"] = {{{"name", "Pyramid"}, {"mesh", mesh}}};
  ReadResult read = parseScene(file.text(), "p.gltf");
  EXPECT_TRUE(read.ok());
  EXPECT_TRUE(read.scene.objects.empty());
  std::vector<Diagnostic> skipped =
      withCode(read.diagnostics, DiagnosticCode::GltfMeshNotPrimitive);
  ASSERT_EQ(skipped.size(), 1u);
  EXPECT_NE(skipped[0].message.find("'Pyramid'"), std::string::npos);
  ReadOptions strict;
  strict.noLoss = true;
  EXPECT_FALSE(parseScene(file.text(), "p.gltf", strict).ok());
}

TEST(GltfReader, ExtrasThatNoLongerMatchAreIgnored) {
  ReadResult original = parseScene(
      testing::kCameraRecord + "CUBE\n0.5 0.5 0.5\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n", "a.sf");
  DiagnosticList out;
  std::optional<GltfFiles> files = writeGltf(original.scene, {}, false, out);
  ASSERT_TRUE(files);
  Json doc = Json::parse(files->main);
  doc["nodes"][1]["matrix"][13] = 2.0;  // moved up in another program
  doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"][0] = 1.0;
  ReadResult read = parseScene(doc.dump(), "edited.gltf");
  ASSERT_TRUE(read.ok());
  ASSERT_EQ(read.scene.objects.size(), 1u);
  EXPECT_EQ(read.scene.objects[0].matrix[3], glm::dvec4(0, 2, 0, 1));
  EXPECT_EQ(read.scene.objects[0].material.colour, glm::dvec3(1.0, 0.5, 0.5));
  EXPECT_EQ(withCode(read.diagnostics, DiagnosticCode::GltfExtrasStale).size(), 2u);
}

TEST(GltfReader, ReadsExternalBuffersFromItsOwnFolderOnly) {
  fs::path dir = fs::temp_directory_path() / ("sfgltf-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "inner");
  ReadResult original = parseScene(
      testing::kCameraRecord + "SPHERE\n1 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n", "a.sf");
  GltfWriteOptions options;
  options.externalBuffer = "scene.bin";
  DiagnosticList out;
  std::optional<GltfFiles> files =
      writeGltf(original.scene, testing::conversionWith(options), false, out);
  ASSERT_TRUE(files);
  std::ofstream(dir / "scene.bin", std::ios::binary) << files->buffer;
  std::ofstream(dir / "inner" / "scene.gltf", std::ios::binary) << files->main;
  std::ofstream(dir / "scene.gltf", std::ios::binary) << files->main;
  // Beside the buffer: read.
  ReadResult good = parseScene(files->main, (dir / "scene.gltf").string());
  EXPECT_TRUE(good.ok());
  EXPECT_EQ(good.scene, original.scene);
  // One folder down, the same URI names nothing.
  ReadResult missing = parseScene(files->main, (dir / "inner" / "scene.gltf").string());
  EXPECT_EQ(withCode(missing.diagnostics, DiagnosticCode::GltfExternalFile).size(), 1u);
  // A link inside the folder that leads out of it.
  fs::create_symlink(dir / "scene.bin", dir / "inner" / "scene.bin");
  ReadResult linked = parseScene(files->main, (dir / "inner" / "scene.gltf").string());
  ASSERT_EQ(withCode(linked.diagnostics, DiagnosticCode::GltfExternalFile).size(), 1u);
  EXPECT_NE(linked.diagnostics.items()[0].message.find("through a link"), std::string::npos);
  fs::remove_all(dir);
}

TEST(GltfReader, VerticesAreCountedOverTheWholeFileAgainstMaxGltfVertices) {
  ThirdParty file;
  TriangleMesh cube = cubeMesh();
  int small = file.addMesh(cube, glm::dmat4(1.0));
  int large = file.addMesh(cube, scaleMatrix(2, 2, 2));
  file.doc()["nodes"] = {{{"mesh", small}}, {{"mesh", large}}};
  ReadOptions options;
  options.gltf.maxVertices = cube.positions.size();  // room for one mesh
  ReadResult read = parseScene(file.text(), "two.gltf", options);
  std::vector<Diagnostic> tooLarge = withCode(read.diagnostics, DiagnosticCode::GltfTooLarge);
  ASSERT_EQ(tooLarge.size(), 1u);
  std::string n = std::to_string(cube.positions.size());
  EXPECT_EQ(tooLarge[0].message, "accessor 2 (POSITION) has " + n + " elements; at most " + n +
                                     " are read from a file, and " + n + " were read before it");

  options.gltf.maxVertices = 2 * cube.positions.size();
  ReadResult raised = parseScene(file.text(), "two.gltf", options);
  EXPECT_TRUE(raised.ok());
  EXPECT_EQ(raised.scene.objects.size(), 2u);
}

TEST(GltfReader, StopsAtTheFirstObjectOrLightPastMaxObjects) {
  ThirdParty file;
  int sphere = file.addMesh(sphereMesh(24), glm::dmat4(1.0));
  file.doc()["nodes"] = {{{"mesh", sphere}},
                         {{"mesh", sphere}, {"translation", {3, 0, 0}}},
                         {{"name", "third"}, {"mesh", sphere}, {"translation", {6, 0, 0}}}};
  ReadOptions options;
  options.maxObjects = 2;
  ReadResult read = parseScene(file.text(), "three.gltf", options);
  std::vector<Diagnostic> tooMany = withCode(read.diagnostics, DiagnosticCode::TooManyObjects);
  ASSERT_EQ(tooMany.size(), 1u);
  EXPECT_EQ(tooMany[0].message,
            "the file has more than 2 objects and lights: reading stops at node 2 'third'");
  EXPECT_EQ(read.diagnostics.errorCount(), 1u);

  options.maxObjects = 3;
  ReadResult raised = parseScene(file.text(), "three.gltf", options);
  EXPECT_TRUE(raised.ok());
  EXPECT_EQ(raised.scene.objects.size(), 3u);
}

TEST(GltfReader, AnExternalBufferLargerThanMaxFileSizeIsNotRead) {
  fs::path dir = fs::temp_directory_path() / ("sfgltf-limit-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  ReadResult original = parseScene(
      testing::kCameraRecord + "SPHERE\n1 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n", "a.sf");
  GltfWriteOptions write;
  write.externalBuffer = "scene.bin";
  DiagnosticList out;
  std::optional<GltfFiles> files =
      writeGltf(original.scene, testing::conversionWith(write), false, out);
  ASSERT_TRUE(files);
  std::ofstream(dir / "scene.bin", std::ios::binary) << files->buffer;
  ReadOptions options;
  options.maxFileSize = files->main.size();  // the .gltf fits, its buffer does not
  ASSERT_GT(files->buffer.size(), options.maxFileSize);
  ReadResult refused = parseScene(files->main, (dir / "scene.gltf").string(), options);
  std::vector<Diagnostic> tooLarge = withCode(refused.diagnostics, DiagnosticCode::FileTooLarge);
  ASSERT_EQ(tooLarge.size(), 1u);
  EXPECT_NE(tooLarge[0].message.find("buffer 0's file 'scene.bin' is " +
                                     std::to_string(files->buffer.size()) + " bytes"),
            std::string::npos)
      << tooLarge[0].message;
  options.maxFileSize = files->buffer.size() + files->main.size();
  EXPECT_TRUE(parseScene(files->main, (dir / "scene.gltf").string(), options).ok());
  fs::remove_all(dir);
}

TEST(GltfReader, FormatDetection) {
  EXPECT_EQ(detectFormat("  \n{\"asset\":{}}"), Format::Gltf);
  EXPECT_EQ(detectFormat(std::string("glTF\x02\0\0\0", 8)), Format::Glb);
  EXPECT_EQ(detectFormat("CAMERA\n"), Format::SceneFile);
  // Garbage after the magic is a GLB with an error, not a crash.
  ReadResult bad = parseScene(std::string("glTF\x02\0\0\0\xff\xff\xff\xff", 12), "x.glb");
  EXPECT_EQ(withCode(bad.diagnostics, DiagnosticCode::GltfInvalidGlb).size(), 1u);
}

TEST(GltfReader, MalformedJsonIsReportedAtItsLine) {
  ReadResult read =
      parseScene("{\n\"asset\": {\"version\": \"2.0\"},\n\"nodes\": [1,,]\n}", "x.gltf");
  std::vector<Diagnostic> d = withCode(read.diagnostics, DiagnosticCode::GltfInvalidJson);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].span.line, 3u);
  EXPECT_EQ(d[0].span.column, 13u);
}

// Damaged copies of a valid file (bytes flipped, cut short, digits changed)
// are read without a crash: each is a scene or a list of errors.
TEST(GltfReader, SurvivesThousandsOfDamagedFiles) {
  ReadResult original = parseScene(testing::kCameraRecord + testing::kLightRecord +
                                       "CUBE\n0.5 0.5 0.5\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n"
                                       "SPHERE\n1 0 0\n2 0 0 1\n0 2 0 0\n0 0 2 0\n0 0 0 1\n",
                                   "a.sf");
  std::mt19937_64 rng(99);
  for (bool binary : {false, true}) {
    GltfWriteOptions options;
    options.segments = 6;
    DiagnosticList out;
    std::string file =
        writeGltf(original.scene, testing::conversionWith(options), binary, out)->main;
    int read = 0;
    for (int i = 0; i < testing::randomCases(3000); ++i) {
      std::string damaged = file;
      switch (rng() % 4) {
        case 0:
          damaged.resize(rng() % damaged.size());
          break;
        case 1:
          for (int k = 0; k < 4; ++k) damaged[rng() % damaged.size()] = static_cast<char>(rng());
          break;
        default: {
          // A digit changed keeps the JSON valid but moves a count, an
          // offset or an index.
          for (int k = 0; k < 3; ++k) {
            std::size_t at = rng() % damaged.size();
            if (std::isdigit(static_cast<unsigned char>(damaged[at]))) {
              damaged[at] = static_cast<char>('0' + rng() % 10);
            }
          }
        }
      }
      ReadResult r = parseScene(damaged, binary ? "damaged.glb" : "damaged.gltf");
      read += r.ok();
    }
    EXPECT_GT(read, 0);
  }
}

}  // namespace
}  // namespace scene
