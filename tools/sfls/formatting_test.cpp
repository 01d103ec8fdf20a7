#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "scenefile/layout.h"
#include "tools/sfls/feature_test_support.h"
#include "tools/sfls/features.h"
#include "tools/sfls/lsp_json.h"

namespace sfls {
namespace {

using feature_test::Opened;
using feature_test::openSource;
using feature_test::openText;

// The document's text with `edits` applied as a client applies them: each
// range in the text before any edit, so from the last to the first.
std::string applied(const Document& document, const nlohmann::json& edits) {
  Document copy(document.uri(), document.version(), document.text());
  for (auto edit = edits.rbegin(); edit != edits.rend(); ++edit) {
    copy.applyChange((*edit)["range"].get<LspRange>(), (*edit)["newText"].get<std::string>());
  }
  return copy.text();
}

nlohmann::json formatAll(const Opened& opened) {
  return formattingEdits(opened.document, *opened.analysis, std::nullopt);
}

TEST(Formatting, GivesTheCanonicalLayoutOfEveryValidFile) {
  std::filesystem::path folder = std::filesystem::path(SCENE_TESTDATA_DIR) / "valid";
  int formatted = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    std::string name = entry.path().filename().string();
    if (!name.ends_with(".sf") && !name.ends_with(".txt")) continue;
    Opened opened = openSource("testdata/valid/" + name);
    if (!opened.analysis->result.ok() || !opened.analysis->format) continue;
    std::optional<std::string> layout =
        scene::canonicalLayout(opened.document.text(), *opened.analysis->format);
    ASSERT_TRUE(layout) << name;
    nlohmann::json edits = formatAll(opened);
    EXPECT_EQ(applied(opened.document, edits), *layout) << name;
    // Laid out, the text takes no more edits.
    Opened again = openText(*layout, name);
    EXPECT_EQ(formatAll(again), nlohmann::json::array()) << name;
    ++formatted;
  }
  EXPECT_GT(formatted, 40);
}

TEST(Formatting, EditsOnlyTheBlanksThatDiffer) {
  std::optional<std::string> layout =
      scene::canonicalLayout(feature_test::readSource("testdata/valid/all-primitives.txt"),
                             scene::Format::InstructionFile);
  ASSERT_TRUE(layout);
  // The camera's "  LOCATION 0 1 8", indented by four and with a doubled
  // blank.
  std::string text = *layout;
  std::size_t at = text.find("  LOCATION 0 1 8");
  ASSERT_NE(at, std::string::npos);
  auto line = static_cast<std::uint32_t>(std::count(text.begin(), text.begin() + at, '\n'));
  text.replace(at, 16, "    LOCATION 0  1 8");
  Opened messy = openText(text, "scene.txt");
  nlohmann::json edits = formatAll(messy);
  ASSERT_EQ(edits.size(), 2u);
  EXPECT_EQ(edits[0]["range"].get<LspRange>(), (LspRange{{line, 2}, {line, 4}}));
  EXPECT_EQ(edits[0]["newText"], "");
  EXPECT_EQ(edits[1]["range"].get<LspRange>(), (LspRange{{line, 15}, {line, 16}}));
  EXPECT_EQ(applied(messy.document, edits), *layout);
}

TEST(Formatting, KeepsCrLfLineEndsWhole) {
  // The first line's LF is the text's line ending: each CRLF becomes an LF,
  // which takes an edit that ends past the LF, since the protocol has no
  // position between a CR and its LF.
  Opened opened = openText(
      "CAMERA  \n0 0 0\r\n1 0 0 0\r\n0 1 0 0\r\n0 0 1 0\r\n0 0 0 1\r\n\r\n\r\n\r\n"
      "LIGHT\r\n1 1 1\r\n1 0 0 0\r\n0 1 0 0\r\n0 0 1 0\r\n0 0 0 1\r\n");
  ASSERT_TRUE(opened.analysis->result.ok());
  std::optional<std::string> layout =
      scene::canonicalLayout(opened.document.text(), scene::Format::SceneFile);
  ASSERT_TRUE(layout);
  ASSERT_EQ(layout->find('\r'), std::string::npos);
  EXPECT_EQ(applied(opened.document, formatAll(opened)), *layout);
}

TEST(Formatting, RangeFormattingEditsOnlyTheLinesInTheRange) {
  Opened messy = openSource("testdata/valid/tabs-and-extra-blanks.txt");
  nlohmann::json all = formatAll(messy);
  nlohmann::json some = formattingEdits(messy.document, *messy.analysis, LspRange{{1, 0}, {3, 0}});
  ASSERT_FALSE(some.empty());
  EXPECT_LT(some.size(), all.size());
  for (const nlohmann::json& edit : some) {
    EXPECT_GE(edit["range"]["start"]["line"], 1);
    EXPECT_LE(edit["range"]["end"]["line"], 3);
  }
}

TEST(Formatting, LeavesATextWithErrorsAlone) {
  Opened broken = openSource("testdata/invalid/camera-extra-token.sf");
  ASSERT_FALSE(broken.analysis->result.ok());
  EXPECT_EQ(formatAll(broken), nlohmann::json::array());
  Opened pov = openText("camera { location <0, 0, -5> look_at <0, 0, 0> }\n", "scene.pov");
  EXPECT_EQ(formatAll(pov), nlohmann::json::array());
}

}  // namespace
}  // namespace sfls
