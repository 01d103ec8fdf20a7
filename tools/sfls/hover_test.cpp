#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "scenefile/keywords.h"
#include "tools/sfls/feature_test_support.h"
#include "tools/sfls/features.h"

namespace sfls {
namespace {

using feature_test::Opened;
using feature_test::openSource;
using feature_test::openText;
using ::testing::HasSubstr;
using ::testing::StartsWith;

// The hover's Markdown at a 0-based line and character; empty for none.
std::string hoverText(const Opened& opened, std::uint32_t line, std::uint32_t character,
                      bool checked = true) {
  nlohmann::json answer =
      hover(opened.document, checked ? opened.analysis.get() : nullptr, {line, character});
  if (answer.is_null()) return "";
  EXPECT_EQ(answer["contents"]["kind"], "markdown");
  return answer["contents"]["value"].get<std::string>();
}

// A camera, a light and three objects, the third a sphere moved up by 2.5.
constexpr const char* kThreeObjects =
    "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 5\n0 0 0 1\n\n"
    "LIGHT\n1 1 1\n1 0 0 4\n0 1 0 4\n0 0 1 4\n0 0 0 1\n\n"
    "PLANE\n0.5 0.5 0.5\n1 0 0 0\n0 1 0 -1\n0 0 1 0\n0 0 0 1\n\n"
    "CUBE\n0 0 1\n1 0 0 2\n0 1 0 0\n0 0 1 0\n0 0 0 1\n\n"
    "SPHERE\n1 0 0\n1 0 0 0\n0 1 0 2.5\n0 0 1 0\n0 0 0 1\n";

TEST(Hover, NamesTheMatrixEntryUnderTheCursor) {
  Opened opened = openText(kThreeObjects);
  ASSERT_TRUE(opened.analysis->result.ok());
  // Line 31 (from 0) is the sphere's second matrix row, "0 1 0 2.5".
  nlohmann::json answer = hover(opened.document, opened.analysis.get(), {31, 7});
  ASSERT_FALSE(answer.is_null());
  EXPECT_EQ(answer["contents"]["value"], "SPHERE 3, row 2, column 4: translation along y");
  EXPECT_EQ(answer["range"]["start"], (nlohmann::json{{"line", 31}, {"character", 6}}));
  EXPECT_EQ(answer["range"]["end"], (nlohmann::json{{"line", 31}, {"character", 9}}));
}

TEST(Hover, WithoutTheCheckNamesTheKindAlone) {
  Opened opened = openText(kThreeObjects);
  EXPECT_EQ(hoverText(opened, 31, 7, false), "SPHERE, row 2, column 4: translation along y");
}

TEST(Hover, NamesTheColourChannels) {
  Opened opened = openSource("testdata/valid/all-primitives.sf");
  EXPECT_THAT(hoverText(opened, 19, 2), StartsWith("SPHERE 2, colour: green"));
  EXPECT_THAT(hoverText(opened, 7, 4), StartsWith("LIGHT 1, colour: blue"));
  EXPECT_THAT(hoverText(opened, 1, 0), StartsWith("CAMERA, colour: red\n\nIgnored"));
}

TEST(Hover, ShowsAnObjectsMaterialAndWorldBounds) {
  Opened opened = openSource("testdata/valid/all-primitives.sf");
  std::string sphere = hoverText(opened, 18, 2);
  EXPECT_THAT(sphere, StartsWith("**SPHERE 2**"));
  EXPECT_THAT(sphere, HasSubstr("- COLOUR 1 0 0\n- AMBIENT 0.1 (default)\n"));
  EXPECT_THAT(sphere, HasSubstr("- RI 1 (default)"));
  EXPECT_THAT(sphere, HasSubstr("- x from -4 to -2\n- y from -1 to 1\n- z from -1 to 1"));
  std::string cylinder = hoverText(opened, 24, 0);
  EXPECT_THAT(cylinder, HasSubstr("- x from -0.5 to 0.5\n- y from -1 to 1\n- z from -0.5 to 0.5"));
  EXPECT_THAT(hoverText(opened, 12, 0),
              HasSubstr("World-space bounds: none, a plane is unbounded"));
}

TEST(Hover, ShowsTheCameraAndALight) {
  Opened opened = openSource("testdata/valid/all-primitives.sf");
  std::string camera = hoverText(opened, 0, 3);
  EXPECT_THAT(camera, HasSubstr("- eye 0 1 8\n- forward 0 0 -1\n- up 0 1 0\n"));
  EXPECT_THAT(camera, HasSubstr("vertical field of view 60 degrees"));
  EXPECT_THAT(hoverText(opened, 6, 0), HasSubstr("- position 5 5 5\n- colour 1 1 1"));
}

TEST(Hover, ExplainsAKeywordFromTheTable) {
  Opened opened = openSource("examples/blue-cube.txt");
  const scene::KeywordInfo* ambient =
      scene::findKeyword("AMBIENT", scene::Format::InstructionFile, scene::KeywordPlace::Material);
  ASSERT_NE(ambient, nullptr);
  // Line 21 (from 0) is "    AMBIENT 0.15".
  std::string text = hoverText(opened, 21, 6);
  EXPECT_THAT(text, StartsWith("**AMBIENT**"));
  EXPECT_THAT(text, HasSubstr(std::string(ambient->meaning)));
  EXPECT_THAT(text, HasSubstr("Valid: " + std::string(ambient->range)));
  // Its number is the keyword's argument.
  EXPECT_THAT(hoverText(opened, 21, 13), StartsWith("`a` of **AMBIENT**"));
  // Line 20 (from 0) is "    COLOUR 0.0 0.0 1.0".
  EXPECT_THAT(hoverText(opened, 20, 16), StartsWith("`g` (green) of **COLOUR**"));
}

TEST(Hover, ShowsTheMatrixOfAnOperationAndOfTheSection) {
  Opened opened = openSource("testdata/valid/all-primitives.txt");
  // Line 38 (from 0) is "    SCALE 0.5 0.5 0.5" of the cube, object 4.
  std::string scale = hoverText(opened, 38, 5);
  EXPECT_THAT(scale, StartsWith("**SCALE**"));
  EXPECT_THAT(scale,
              HasSubstr("```\n0.5   0   0 0\n  0 0.5   0 0\n  0   0 0.5 0\n  0   0   0 1\n```"));
  // "START TRANSFORMATION": SCALE then TRANSLATE 3 0 0.
  EXPECT_THAT(hoverText(opened, 37, 10), HasSubstr("0.5   0   0 3\n"));
  std::string cube = hoverText(opened, 33, 14);
  EXPECT_THAT(cube, StartsWith("**CUBE 4**"));
  EXPECT_THAT(cube, HasSubstr("- x from 2.5 to 3.5"));
  EXPECT_THAT(hoverText(opened, 1, 8), HasSubstr("- eye 0 1 8"));
}

TEST(Hover, AnswersNothingWhereNothingStands) {
  Opened opened = openSource("testdata/valid/all-primitives.txt");
  EXPECT_EQ(hoverText(opened, 2, 0), "");    // the indentation
  EXPECT_EQ(hoverText(opened, 900, 0), "");  // past the end
  Opened pov = openText("camera { location <0, 0, -5> look_at <0, 0, 0> }\n", "scene.pov");
  EXPECT_EQ(hoverText(pov, 0, 2), "");
}

}  // namespace
}  // namespace sfls
