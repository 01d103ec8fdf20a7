// Every feature, at every kind of position of every file of the test
// corpus, broken and hostile files too: an answer of the protocol's shape,
// with its ranges on the lines asked about, and never a crash.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "tools/sfls/feature_test_support.h"
#include "tools/sfls/features.h"
#include "tools/sfls/lsp_json.h"

namespace sfls {
namespace {

using feature_test::Opened;
using feature_test::openSource;

std::vector<std::string> corpus() {
  std::vector<std::string> files;
  for (std::string folder : {"valid", "invalid", "hostile/sf", "hostile/instructions", "fuzz"}) {
    std::filesystem::path path = std::filesystem::path(SCENE_TESTDATA_DIR) / folder;
    if (!std::filesystem::is_directory(path)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(path)) {
      std::string name = entry.path().filename().string();
      bool lineFormat = name.ends_with(".sf") || name.ends_with(".txt");
      // The largest hostile files test the readers' limits, not positions.
      if (lineFormat && entry.file_size() < 256 * 1024) {
        files.push_back("testdata/" + folder + "/" + name);
      }
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

void expectRangeOnLine(const nlohmann::json& range, std::uint32_t line, const std::string& where) {
  LspRange r = range.get<LspRange>();
  EXPECT_EQ(r.start.line, line) << where;
  EXPECT_EQ(r.end.line, line) << where;
  EXPECT_LE(r.start.character, r.end.character) << where;
}

void checkPosition(const Opened& opened, LspPosition position, const std::string& where) {
  const Analysis* checked = opened.analysis.get();
  for (const Analysis* analysis : {checked, static_cast<const Analysis*>(nullptr)}) {
    nlohmann::json answer = hover(opened.document, analysis, position);
    if (!answer.is_null()) {
      EXPECT_FALSE(answer["contents"]["value"].get<std::string>().empty()) << where;
      expectRangeOnLine(answer["range"], position.line, where);
    }
    nlohmann::json list = completion(opened.document, analysis, position, true);
    for (const nlohmann::json& item : list.at("items")) {
      EXPECT_FALSE(item["label"].get<std::string>().empty()) << where;
      expectRangeOnLine(item["textEdit"]["range"], position.line, where);
    }
  }
}

TEST(FeaturePositions, AnswerEverywhereInEveryFileOfTheCorpus) {
  std::vector<std::string> files = corpus();
  ASSERT_GT(files.size(), 100u);
  for (const std::string& file : files) {
    Opened opened = openSource(file);
    const Document& document = opened.document;
    std::uint32_t lines = std::min(document.lineCount(), 400u);
    for (std::uint32_t line = 0; line < lines; ++line) {
      auto length = static_cast<std::uint32_t>(document.lineText(line).size());
      for (std::uint32_t character : {0u, 1u, 3u, length / 2, length, length + 4}) {
        checkPosition(opened, {line, character},
                      file + ":" + std::to_string(line) + ":" + std::to_string(character));
      }
    }
    EXPECT_TRUE(documentSymbols(document, *opened.analysis).is_array()) << file;
    EXPECT_TRUE(foldingRanges(document, *opened.analysis).is_array()) << file;
    EXPECT_TRUE(formattingEdits(document, *opened.analysis, std::nullopt).is_array()) << file;
  }
}

}  // namespace
}  // namespace sfls
