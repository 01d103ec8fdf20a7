#include "scenefile/diagnostic.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace scene {
namespace {

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

TEST(DiagnosticCodes, NamesAreUniqueKebabCase) {
  std::set<std::string_view> names;
  for (DiagnosticCode code : allDiagnosticCodes()) {
    std::string_view name = codeName(code);
    EXPECT_TRUE(names.insert(name).second) << name;
    EXPECT_NE(name, "unknown");
    for (char c : name) EXPECT_TRUE((c >= 'a' && c <= 'z') || c == '-') << name;
  }
}

TEST(DiagnosticCodes, EveryCodeIsDocumented) {
  std::string table = readText(std::filesystem::path(SCENE_DOCS_DIR) / "DIAGNOSTICS.md");
  for (DiagnosticCode code : allDiagnosticCodes()) {
    std::string row = "| `" + std::string(codeName(code)) + "` |";
    EXPECT_NE(table.find(row), std::string::npos) << codeName(code) << " is not in the table";
  }
}

// Every code a file can draw from sfcheck appears in the expected
// diagnostics of the corpus; the conversion codes are pinned by
// writers_test.cpp and gltf_writer_test.cpp, which sfcheck never reports.
TEST(DiagnosticCodes, EveryCheckCodeIsExercisedByTheCorpus) {
  const std::set<DiagnosticCode> conversionOnly = {
      DiagnosticCode::LossMaterial,           DiagnosticCode::LossCameraRoll,
      DiagnosticCode::MatrixNotExpressible,   DiagnosticCode::MatrixApproximated,
      DiagnosticCode::CameraRollApproximated, DiagnosticCode::DroppedOutputFile,
      DiagnosticCode::IgnoredLightMatrix,     DiagnosticCode::PlaneMadeFinite,
      DiagnosticCode::GltfValueClamped,       DiagnosticCode::GltfExtrasOnly,
      DiagnosticCode::GltfMatrixSplit};
  std::string expected;
  for (const auto& entry :
       std::filesystem::recursive_directory_iterator(std::filesystem::path(SCENE_TESTDATA_DIR))) {
    if (entry.path().extension() == ".expect") expected += readText(entry.path());
  }
  for (DiagnosticCode code : allDiagnosticCodes()) {
    if (conversionOnly.count(code)) continue;
    std::string tag = "[" + std::string(codeName(code)) + "]";
    EXPECT_NE(expected.find(tag), std::string::npos)
        << codeName(code) << " appears in no testdata/**/*.expect";
  }
}

TEST(DiagnosticList, CountsAndStopsAtTheLimit) {
  DiagnosticList list("f.sf", 3);
  list.warning(DiagnosticCode::NoLight, {1, 1, 0}, "w");
  for (int i = 0; i < 5; ++i) list.error(DiagnosticCode::InvalidNumber, {2, 1, 1}, "e");
  EXPECT_EQ(list.errorCount(), 3u);
  EXPECT_EQ(list.warningCount(), 1u);
  EXPECT_TRUE(list.full());
  ASSERT_EQ(list.items().size(), 5u);  // 1 warning, 3 errors, 1 note
  EXPECT_EQ(list.items().back().code, DiagnosticCode::TooManyErrors);
  EXPECT_EQ(list.items().back().message, "too many errors; stopped after 3");
  EXPECT_EQ(list.items()[1].file, "f.sf");
}

TEST(DiagnosticList, KeepsCountingWarningsPastWhatItStores) {
  DiagnosticList list("f.sf", 10);
  for (int i = 0; i < 100; ++i) list.warning(DiagnosticCode::ColourAboveOne, {1, 1, 0}, "w");
  EXPECT_EQ(list.warningCount(), 100u);
  EXPECT_EQ(list.items().size(), 20u);
  EXPECT_FALSE(list.hasErrors());
}

}  // namespace
}  // namespace scene
