#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tools/sfls/feature_test_support.h"
#include "tools/sfls/features.h"

namespace sfls {
namespace {

using feature_test::Opened;
using feature_test::openText;
using ::testing::ElementsAre;
using ::testing::IsEmpty;
using ::testing::UnorderedElementsAre;

nlohmann::json itemsAt(const Opened& opened, std::uint32_t line, std::uint32_t character,
                       bool snippets = false) {
  nlohmann::json list =
      completion(opened.document, opened.analysis.get(), {line, character}, snippets);
  EXPECT_EQ(list["isIncomplete"], false);
  return list["items"];
}

std::vector<std::string> labels(const nlohmann::json& items) {
  std::vector<std::string> out;
  for (const nlohmann::json& item : items) out.push_back(item["label"]);
  return out;
}

// `text` with `line` put in before line `before` (from 0).
std::string withLine(const std::string& text, std::size_t before, const std::string& line) {
  std::size_t at = 0;
  for (std::size_t i = 0; i < before; ++i) at = text.find('\n', at) + 1;
  return text.substr(0, at) + line + "\n" + text.substr(at);
}

// `text` with line `index` (from 0) replaced by `line`.
std::string withLineReplaced(const std::string& text, std::size_t index, const std::string& line) {
  std::size_t at = 0;
  for (std::size_t i = 0; i < index; ++i) at = text.find('\n', at) + 1;
  return text.substr(0, at) + line + text.substr(text.find('\n', at));
}

TEST(Completion, OffersRecordNamesWhereARecordStarts) {
  std::string text = feature_test::readSource("testdata/valid/all-primitives.sf");
  Opened opened = openText(withLine(text, 6, ""));
  // The file has its one CAMERA: a second would be an error.
  EXPECT_THAT(labels(itemsAt(opened, 6, 0)),
              UnorderedElementsAre("LIGHT", "PLANE", "SPHERE", "CYLINDER", "CUBE"));
  Opened empty = openText("\n");
  EXPECT_THAT(labels(itemsAt(empty, 0, 0)),
              UnorderedElementsAre("CAMERA", "LIGHT", "PLANE", "SPHERE", "CYLINDER", "CUBE"));
  // Inside a record the lines hold numbers only.
  EXPECT_THAT(labels(itemsAt(opened, 3, 0)), IsEmpty());
}

TEST(Completion, ReplacesThePartlyTypedWord) {
  std::string text = feature_test::readSource("testdata/valid/all-primitives.sf");
  Opened opened = openText(text + "\nSPH");
  nlohmann::json items = itemsAt(opened, 37, 3);
  ASSERT_FALSE(items.empty());
  for (const nlohmann::json& item : items) {
    EXPECT_EQ(item["textEdit"]["range"]["start"], (nlohmann::json{{"line", 37}, {"character", 0}}));
    EXPECT_EQ(item["textEdit"]["range"]["end"], (nlohmann::json{{"line", 37}, {"character", 3}}));
    EXPECT_EQ(item["insertTextFormat"], 1);
    EXPECT_TRUE(item.contains("detail"));
    EXPECT_EQ(item["documentation"]["kind"], "markdown");
  }
}

TEST(Completion, OffersWholeRecordsAsSnippets) {
  std::string text = feature_test::readSource("testdata/valid/all-primitives.sf");
  Opened opened = openText(withLine(text, 6, ""));
  nlohmann::json items = itemsAt(opened, 6, 0, true);
  nlohmann::json sphere;
  for (const nlohmann::json& item : items) {
    if (item["label"] == "SPHERE record") sphere = item;
  }
  ASSERT_FALSE(sphere.is_null());
  EXPECT_EQ(sphere["insertTextFormat"], 2);
  EXPECT_EQ(sphere["filterText"], "SPHERE");
  EXPECT_EQ(sphere["textEdit"]["newText"],
            "SPHERE\n${1:1} ${2:1} ${3:1}\n1 0 0 ${4:0}\n0 1 0 ${5:0}\n0 0 1 ${6:0}\n0 0 0 1\n$0");
}

TEST(Completion, OffersOutputFileOnlyFirst) {
  std::string text = feature_test::readSource("testdata/valid/all-primitives.txt");
  Opened between = openText(withLine(text, 5, ""), "scene.txt");
  EXPECT_THAT(labels(itemsAt(between, 5, 0)), ElementsAre("START"));
  // A blank first line of an instruction file.
  Opened first = openText(withLine(text, 0, ""), "scene.txt");
  EXPECT_THAT(labels(itemsAt(first, 0, 0)), UnorderedElementsAre("OUTPUT_FILE", "START"));
}

TEST(Completion, OffersBlockNamesAndObjectKindsAfterStart) {
  std::string text = feature_test::readSource("testdata/valid/all-primitives.txt");
  Opened block = openText(withLine(text, 5, "START "), "scene.txt");
  EXPECT_THAT(labels(itemsAt(block, 5, 6)), UnorderedElementsAre("LIGHT", "OBJECT"));
  Opened kind = openText(withLine(text, 5, "START OBJECT "), "scene.txt");
  EXPECT_THAT(labels(itemsAt(kind, 5, 13)),
              UnorderedElementsAre("PLANE", "SPHERE", "CYLINDER", "CUBE"));
}

TEST(Completion, OffersTheMaterialKeysNotGivenYet) {
  std::string text = feature_test::readSource("testdata/valid/all-primitives.txt");
  // After line 19 (from 0), "    COLOUR 1 0 0" of the sphere's material.
  Opened opened = openText(withLine(text, 20, "    "), "scene.txt");
  EXPECT_THAT(labels(itemsAt(opened, 20, 4)),
              UnorderedElementsAre("AMBIENT", "DIFFUSE", "SPECULAR", "SHININESS", "REFLECTIVITY",
                                   "TRANSPARENCY", "RI", "END MATERIAL"));
}

TEST(Completion, OffersOperationsInsideATransformation) {
  std::string text = feature_test::readSource("testdata/valid/all-primitives.txt");
  // After line 22 (from 0), "    TRANSLATE -3 0 0" of the sphere.
  Opened operations = openText(withLine(text, 23, "    "), "scene.txt");
  EXPECT_THAT(labels(itemsAt(operations, 23, 4)),
              UnorderedElementsAre("SCALE", "TRANSLATE", "ROTATE_X", "ROTATE_Y", "ROTATE_Z",
                                   "END TRANSFORMATION"));
}

TEST(Completion, OffersTheSectionsAnObjectHasNot) {
  std::string text = feature_test::readSource("testdata/valid/material-only.txt");
  // Before line 14 (from 0), "END OBJECT" of an object with a MATERIAL.
  Opened object = openText(withLine(text, 14, ""), "scene.txt");
  EXPECT_THAT(labels(itemsAt(object, 14, 0)), UnorderedElementsAre("START", "END OBJECT"));
  EXPECT_THAT(labels(itemsAt(object, 14, 0, true)),
              UnorderedElementsAre("START", "END OBJECT", "START TRANSFORMATION section"));
  Opened end = openText(withLine(text, 14, "END "), "scene.txt");
  EXPECT_THAT(labels(itemsAt(end, 14, 4)), UnorderedElementsAre("OBJECT"));
  Opened section = openText(withLine(text, 14, "START "), "scene.txt");
  EXPECT_THAT(labels(itemsAt(section, 14, 6)), UnorderedElementsAre("TRANSFORMATION"));
  // The sphere of all-primitives.txt has both: line 24 (from 0) is its END.
  std::string both = feature_test::readSource("testdata/valid/all-primitives.txt");
  Opened full = openText(withLine(both, 24, "  "), "scene.txt");
  EXPECT_THAT(labels(itemsAt(full, 24, 2)), UnorderedElementsAre("END OBJECT"));
}

TEST(Completion, LeavesOutTheCameraKeysGiven) {
  std::string text = feature_test::readSource("testdata/valid/all-primitives.txt");
  // Line 3 (from 0), "  LOOK_AT 0 0 0", left blank.
  Opened opened = openText(withLineReplaced(text, 3, "  "), "scene.txt");
  EXPECT_THAT(labels(itemsAt(opened, 3, 2)), UnorderedElementsAre("LOOK_AT", "END CAMERA"));
}

TEST(Completion, OffersBlocksAsSnippetsWithTabStops) {
  std::string text = feature_test::readSource("testdata/valid/all-primitives.txt");
  Opened opened = openText(withLine(text, 5, ""), "scene.txt");
  nlohmann::json items = itemsAt(opened, 5, 0, true);
  EXPECT_THAT(labels(items),
              UnorderedElementsAre("START", "START LIGHT block", "START OBJECT block"));
  for (const nlohmann::json& item : items) {
    if (item["label"] != "START OBJECT block") continue;
    EXPECT_EQ(item["insertTextFormat"], 2);
    EXPECT_THAT(item["textEdit"]["newText"].get<std::string>(),
                ::testing::StartsWith("START OBJECT ${1|PLANE,SPHERE,CYLINDER,CUBE|}\n"));
  }
  // A keyword's arguments become tab stops: line 7 (from 0), the light's
  // "  COLOUR 1 1 1", left blank.
  Opened light = openText(withLineReplaced(text, 7, "  "), "scene.txt");
  nlohmann::json keys = itemsAt(light, 7, 2, true);
  EXPECT_THAT(labels(keys), UnorderedElementsAre("COLOUR", "END LIGHT"));
  for (const nlohmann::json& item : keys) {
    if (item["label"] != "COLOUR") continue;
    EXPECT_EQ(item["insertTextFormat"], 2);
    EXPECT_THAT(
        item["textEdit"]["newText"].get<std::string>(),
        ::testing::MatchesRegex("COLOUR \\$\\{1:[a-z]+\\} \\$\\{2:[a-z]+\\} \\$\\{3:[a-z]+\\}"));
  }
}

}  // namespace
}  // namespace sfls
