#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tools/sfls/feature_test_support.h"
#include "tools/sfls/features.h"

namespace sfls {
namespace {

using feature_test::Opened;
using feature_test::openSource;
using feature_test::openText;
using ::testing::ElementsAre;

std::vector<std::string> names(const nlohmann::json& symbols) {
  std::vector<std::string> out;
  for (const nlohmann::json& symbol : symbols) out.push_back(symbol["name"]);
  return out;
}

nlohmann::json position(std::uint32_t line, std::uint32_t character) {
  return {{"line", line}, {"character", character}};
}

TEST(DocumentSymbols, ListTheRecordsByKindAndNumber) {
  Opened opened = openSource("testdata/valid/all-primitives.sf");
  nlohmann::json symbols = documentSymbols(opened.document, *opened.analysis);
  EXPECT_THAT(names(symbols),
              ElementsAre("CAMERA", "LIGHT 1", "PLANE 1", "SPHERE 2", "CYLINDER 3", "CUBE 4"));
  const nlohmann::json& sphere = symbols[3];
  EXPECT_EQ(sphere["kind"], 19);
  EXPECT_EQ(sphere["range"]["start"], position(18, 0));
  EXPECT_EQ(sphere["range"]["end"], position(23, 7));
  EXPECT_EQ(sphere["selectionRange"]["start"], position(18, 0));
  EXPECT_EQ(sphere["selectionRange"]["end"], position(18, 6));
  EXPECT_FALSE(sphere.contains("children"));
}

TEST(DocumentSymbols, NestTheSectionsInTheirObjects) {
  Opened opened = openSource("testdata/valid/all-primitives.txt");
  nlohmann::json symbols = documentSymbols(opened.document, *opened.analysis);
  EXPECT_THAT(names(symbols), ElementsAre("OUTPUT_FILE", "CAMERA", "LIGHT 1", "PLANE 1", "SPHERE 2",
                                          "CYLINDER 3", "CUBE 4"));
  EXPECT_EQ(symbols[0]["detail"], "primitives.ppm");
  EXPECT_EQ(symbols[0]["kind"], 1);
  const nlohmann::json& cube = symbols[6];
  EXPECT_EQ(cube["range"]["start"], position(33, 0));
  EXPECT_EQ(cube["range"]["end"], position(41, 10));
  EXPECT_EQ(cube["selectionRange"]["end"]["line"], 33);
  ASSERT_THAT(names(cube["children"]), ElementsAre("MATERIAL", "TRANSFORMATION"));
  EXPECT_EQ(cube["children"][1]["kind"], 18);
  EXPECT_EQ(cube["children"][1]["range"]["start"], position(37, 0));
  EXPECT_EQ(cube["children"][1]["range"]["end"], position(40, 20));
}

// A camera and `spheres` spheres.
std::string manySpheres(std::size_t spheres) {
  std::string text = "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 5\n0 0 0 1\n";
  for (std::size_t i = 0; i < spheres; ++i) {
    text += "SPHERE\n1 1 1\n1 0 0 " + std::to_string(i) + "\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
  }
  return text;
}

TEST(DocumentSymbols, ListTheFirstItemsAndSayHowManyMore) {
  Opened opened = openText(manySpheres(kMaxOutlineItems + 50));
  nlohmann::json symbols = documentSymbols(opened.document, *opened.analysis);
  ASSERT_EQ(symbols.size(), kMaxOutlineItems + 1);
  EXPECT_EQ(symbols[kMaxOutlineItems - 1]["name"],
            "SPHERE " + std::to_string(kMaxOutlineItems - 1));
  const nlohmann::json& rest = symbols.back();
  EXPECT_EQ(rest["name"], "51 more items not listed");
  EXPECT_EQ(rest["range"]["start"], position(6 * kMaxOutlineItems, 0));
  EXPECT_EQ(rest["range"]["end"]["line"], 6 * (kMaxOutlineItems + 51) - 1);
  EXPECT_EQ(foldingRanges(opened.document, *opened.analysis).size(), kMaxOutlineItems);
}

TEST(FoldingRanges, FoldEveryItemOfMoreThanOneLine) {
  Opened opened = openSource("testdata/valid/all-primitives.txt");
  nlohmann::json ranges = foldingRanges(opened.document, *opened.analysis);
  // The camera, the light, four objects and their eight sections; not
  // OUTPUT_FILE, a single line.
  ASSERT_EQ(ranges.size(), 14u);
  EXPECT_EQ(ranges[0], (nlohmann::json{{"startLine", 1}, {"endLine", 4}}));
  EXPECT_EQ(ranges.back(), (nlohmann::json{{"startLine", 37}, {"endLine", 40}}));
  Opened records = openSource("testdata/valid/all-primitives.sf");
  nlohmann::json recordRanges = foldingRanges(records.document, *records.analysis);
  ASSERT_EQ(recordRanges.size(), 6u);
  EXPECT_EQ(recordRanges[5], (nlohmann::json{{"startLine", 30}, {"endLine", 35}}));
}

}  // namespace
}  // namespace sfls
