#include "scenefile/diagnostic.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "libscene/testing/test_support.h"

namespace scene {
namespace {

using scene::testing::readText;

TEST(DiagnosticCodes, NamesAreUniqueKebabCase) {
  std::set<std::string_view> names;
  for (DiagnosticCode code : allDiagnosticCodes()) {
    std::string_view name = codeName(code);
    EXPECT_TRUE(names.insert(name).second) << name;
    EXPECT_NE(name, "unknown");
    EXPECT_FALSE(name.empty());
    for (char c : name) EXPECT_TRUE((c >= 'a' && c <= 'z') || c == '-') << name;
  }
}

// The values are what the enum declares, in order, with nothing left out:
// codeName finds each code at its value.
TEST(DiagnosticCodes, AllCodesAreTheEnumInOrder) {
  const std::vector<DiagnosticCode>& codes = allDiagnosticCodes();
  for (std::size_t i = 0; i < codes.size(); ++i) {
    EXPECT_EQ(static_cast<std::size_t>(codes[i]), i) << codeName(codes[i]);
  }
  EXPECT_EQ(codes.back(), DiagnosticCode::GltfExtrasLeftOut);
  EXPECT_EQ(codeName(static_cast<DiagnosticCode>(codes.size())), "unknown");
}

TEST(DiagnosticCodes, FromNameReadsEveryNameAndNothingElse) {
  for (DiagnosticCode code : allDiagnosticCodes()) {
    EXPECT_EQ(diagnosticCodeFromName(codeName(code)), code) << codeName(code);
  }
  EXPECT_EQ(diagnosticCodeFromName("unknown"), std::nullopt);
  EXPECT_EQ(diagnosticCodeFromName(""), std::nullopt);
  EXPECT_EQ(diagnosticCodeFromName("Invalid-Number"), std::nullopt);
  EXPECT_EQ(diagnosticCodeFromName("invalid-number "), std::nullopt);
}

// The names codes had before they were renamed, from the same list.
struct Alias {
  DiagnosticCode code;
  std::string_view oldName;
};
const std::vector<Alias>& aliases() {
  static const std::vector<Alias> list = {
#define SCENEFILE_DIAGNOSTIC(enumerator, name)
#define SCENEFILE_DIAGNOSTIC_ALIAS(enumerator, oldName) Alias{DiagnosticCode::enumerator, oldName},
#include "scenefile/diagnostic_codes.def"
  };
  return list;
}

TEST(DiagnosticCodes, OldNamesStillFindTheirCode) {
  EXPECT_EQ(diagnosticCodeFromName("loss-pov"), DiagnosticCode::LossPov);
  EXPECT_EQ(codeName(DiagnosticCode::LossPov), "pov-write-loss");
  EXPECT_EQ(diagnosticCodeFromName("pov-loss"), DiagnosticCode::PovLoss);
  std::set<std::string_view> oldNames;
  for (const Alias& alias : aliases()) {
    EXPECT_EQ(diagnosticCodeFromName(alias.oldName), alias.code) << alias.oldName;
    EXPECT_NE(codeName(alias.code), alias.oldName);
    EXPECT_TRUE(oldNames.insert(alias.oldName).second) << alias.oldName;
    // An old name that is some code's name now would find that code instead.
    for (DiagnosticCode code : allDiagnosticCodes()) {
      EXPECT_NE(codeName(code), alias.oldName) << alias.oldName << " is in use again";
    }
  }
}

// The rows of the table under `## heading` in a Markdown text: the cells of
// each line that starts with '|', header and rule left out.
std::vector<std::vector<std::string>> tableRows(const std::string& text,
                                                const std::string& heading) {
  std::vector<std::vector<std::string>> rows;
  std::size_t at = text.find("\n## " + heading + "\n");
  if (at == std::string::npos) return rows;
  std::istringstream lines(text.substr(at + 1));
  std::string line;
  std::getline(lines, line);  // the heading itself
  bool header = true;
  while (std::getline(lines, line) && !line.starts_with("## ")) {
    if (!line.starts_with("|")) continue;
    if (header) {
      header = false;
      continue;
    }
    if (line.starts_with("|---")) continue;
    std::vector<std::string> cells;
    std::size_t start = 1;
    for (std::size_t bar; (bar = line.find('|', start)) != std::string::npos; start = bar + 1) {
      std::string cell = line.substr(start, bar - start);
      cell.erase(0, cell.find_first_not_of(' '));
      cell.erase(cell.find_last_not_of(' ') + 1);
      cells.push_back(cell);
    }
    rows.push_back(cells);
  }
  return rows;
}

// `name` in backquotes, as the tables write a code, or "" for another cell.
std::string quotedCode(const std::string& cell) {
  if (cell.size() < 3 || cell.front() != '`' || cell.back() != '`') return "";
  return cell.substr(1, cell.size() - 2);
}

// The code of a row of "Codes": `name` after its anchor, <a id="name"></a>,
// which an editor's link to the code's entry points at; "" when the row has
// no such anchor or it names another code.
std::string anchoredCode(const std::string& cell) {
  const std::string open = "<a id=\"";
  const std::string close = "\"></a>";
  std::size_t end = cell.find(close);
  if (!cell.starts_with(open) || end == std::string::npos) return "";
  std::string anchor = cell.substr(open.size(), end - open.size());
  std::string name = quotedCode(cell.substr(end + close.size()));
  return anchor == name ? name : "";
}

std::string diagnosticsDoc() {
  return readText(std::filesystem::path(SCENE_DOCS_DIR) / "DIAGNOSTICS.md");
}

// The table in docs/DIAGNOSTICS.md and the list in diagnostic_codes.def
// name the same codes, each once.
TEST(DiagnosticCodes, TheTableListsEveryCodeOnceAndNothingElse) {
  std::vector<std::vector<std::string>> rows = tableRows(diagnosticsDoc(), "Codes");
  ASSERT_FALSE(rows.empty()) << "no table under '## Codes' in DIAGNOSTICS.md";
  std::map<std::string, int> rowsOf;
  for (const std::vector<std::string>& row : rows) {
    ASSERT_FALSE(row.empty());
    std::string name = anchoredCode(row[0]);
    EXPECT_FALSE(name.empty()) << "a row of the table names no code after its anchor: " << row[0];
    ++rowsOf[name];
    EXPECT_TRUE(diagnosticCodeFromName(name).has_value())
        << "the table documents '" << name << "', which is no code";
    if (std::optional<DiagnosticCode> code = diagnosticCodeFromName(name)) {
      EXPECT_EQ(codeName(*code), name) << "the table documents the old name '" << name << "'";
    }
  }
  for (DiagnosticCode code : allDiagnosticCodes()) {
    std::string name(codeName(code));
    EXPECT_EQ(rowsOf[name], 1) << name << " has " << rowsOf[name] << " rows in the table";
  }
}

// Each old name has its row in "Renamed codes", pointing at the code's name.
TEST(DiagnosticCodes, TheRenamedTableListsEveryOldName) {
  std::map<std::string, std::string> renamed;
  for (const std::vector<std::string>& row : tableRows(diagnosticsDoc(), "Renamed codes")) {
    ASSERT_GE(row.size(), 3u);
    std::string oldName = quotedCode(row[0]);
    EXPECT_TRUE(renamed.emplace(oldName, quotedCode(row[1])).second) << oldName << " twice";
    EXPECT_EQ(row[2], "0.1.0") << oldName;
  }
  EXPECT_EQ(renamed.size(), aliases().size());
  for (const Alias& alias : aliases()) {
    auto row = renamed.find(std::string(alias.oldName));
    ASSERT_NE(row, renamed.end()) << alias.oldName << " is not in the renamed codes table";
    EXPECT_EQ(row->second, codeName(alias.code)) << alias.oldName;
  }
}

// Every [`name`] the documents cite is a code's name now, not an old one.
TEST(DiagnosticCodes, TheDocsCiteOnlyCurrentNames) {
  for (const auto& entry : std::filesystem::directory_iterator(SCENE_DOCS_DIR)) {
    if (entry.path().extension() != ".md") continue;
    std::string text = readText(entry.path());
    for (std::size_t at = text.find("[`"); at != std::string::npos; at = text.find("[`", at + 2)) {
      // [`x`](link) is a link with code for its text, not a citation.
      std::size_t end = text.find('`', at + 2);
      if (end == std::string::npos) break;
      if (text.compare(end, 2, "`]") != 0 || text.compare(end, 3, "`](") == 0) continue;
      std::string name = text.substr(at + 2, end - at - 2);
      std::optional<DiagnosticCode> code = diagnosticCodeFromName(name);
      EXPECT_TRUE(code && codeName(*code) == name)
          << entry.path().filename().string() << " cites [`" << name << "`], no current code";
    }
  }
}

// Every code a file can draw from a check appears in the expected
// diagnostics of the corpus; the conversion codes are pinned by
// writers_test.cpp, gltf_writer_test.cpp, gltf_lights_test.cpp, gltf_no_extras_test.cpp and
// obj_writer_test.cpp, which a
// check never reports,
// and cannot-read-file by read_file_test.cpp (the tools print it as a file
// error, without the code).
TEST(DiagnosticCodes, EveryCheckCodeIsExercisedByTheCorpus) {
  const std::set<DiagnosticCode> conversionOnly = {
      DiagnosticCode::LossMaterial,           DiagnosticCode::LossCameraRoll,
      DiagnosticCode::MatrixNotExpressible,   DiagnosticCode::MatrixApproximated,
      DiagnosticCode::CameraRollApproximated, DiagnosticCode::DroppedOutputFile,
      DiagnosticCode::IgnoredLightMatrix,     DiagnosticCode::PlaneMadeFinite,
      DiagnosticCode::GltfValueClamped,       DiagnosticCode::GltfExtrasOnly,
      DiagnosticCode::GltfMatrixSplit,        DiagnosticCode::GltfLightLeftOut,
      DiagnosticCode::CannotReadFile,         DiagnosticCode::ObjWriteLoss,
      DiagnosticCode::GltfExtrasLeftOut};
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

TEST(HintText, SaysEachRemedyInTheCallersWords) {
  std::vector<Remedy> remedies{{Setting::Width, "640"}, {Setting::Height, "480"}};
  auto words = [](const Remedy& r) { return std::string(settingName(r.setting)) + "=" + r.value; };
  EXPECT_EQ(hintText("render with {0} and {1}", remedies, words),
            "render with width=640 and height=480");
  // Braces that name no remedy are the hint's own text.
  EXPECT_EQ(hintText("a block {2} {x} {", remedies, words), "a block {2} {x} {");
  EXPECT_EQ(hintText("{0}", {}, words), "{0}");
}

TEST(Setting, EveryOneHasAStableName) {
  std::set<std::string_view> names;
  for (int i = 0; i <= static_cast<int>(Setting::OutputPath); ++i) {
    std::string_view name = settingName(static_cast<Setting>(i));
    EXPECT_NE(name, "unknown") << i;
    EXPECT_TRUE(names.insert(name).second) << name;
  }
  EXPECT_EQ(settingName(Setting::MaxFileSize), "max-file-size");
}

}  // namespace
}  // namespace scene
