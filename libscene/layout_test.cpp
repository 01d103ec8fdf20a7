#include "scenefile/layout.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "libscene/formats/instruction/instruction_writer.h"
#include "libscene/formats/sf/sf_writer.h"
#include "libscene/testing/random_scenes.h"
#include "libscene/testing/test_support.h"
#include "libscene/text/text_lines.h"
#include "scenefile/convert.h"
#include "scenefile/read.h"

namespace scene {
namespace {

namespace fs = std::filesystem;

using scene::testing::readText;

std::vector<std::string_view> wordsOf(std::string_view text) {
  std::vector<std::string_view> words;
  LineCursor cursor(text);
  while (cursor.next()) {
    for (std::size_t i = 0; i < cursor.storedTokens(); ++i) words.push_back(cursor.token(i).text);
  }
  return words;
}

std::string layoutOf(std::string_view text, Format format) {
  std::optional<std::string> laid = canonicalLayout(text, format);
  EXPECT_TRUE(laid.has_value());
  return laid.value_or("");
}

struct ValidFile {
  std::string name;
  std::string text;
  Format format;
};

std::vector<ValidFile> validFiles() {
  std::vector<ValidFile> files;
  for (const auto& entry : fs::directory_iterator(fs::path(SCENE_TESTDATA_DIR) / "valid")) {
    std::string ext = entry.path().extension().string();
    if (ext != ".sf" && ext != ".txt") continue;
    files.push_back({entry.path().filename().string(), readText(entry.path()),
                     ext == ".sf" ? Format::SceneFile : Format::InstructionFile});
  }
  return files;
}

// Laying out keeps every word and the scene it reads as, and a second time
// changes nothing.
TEST(CanonicalLayout, KeepsTheWordsAndTheSceneOfEveryValidFile) {
  std::vector<ValidFile> files = validFiles();
  ASSERT_GT(files.size(), 40u);
  for (const ValidFile& file : files) {
    SCOPED_TRACE(file.name);
    std::string laid = layoutOf(file.text, file.format);
    EXPECT_EQ(layoutOf(laid, file.format), laid);
    EXPECT_EQ(wordsOf(laid), wordsOf(file.text));
    ReadResult before = parseSceneAs(file.format, file.text, file.name);
    ReadResult after = parseSceneAs(file.format, laid, file.name);
    ASSERT_TRUE(after.ok());
    EXPECT_EQ(after.scene, before.scene);
    EXPECT_EQ(after.diagnostics.items().size(), before.diagnostics.items().size());
  }
}

// What the writers write is already laid out.
TEST(CanonicalLayout, AWritersOutputIsAFixedPoint) {
  std::vector<std::string> sceneFiles;
  std::vector<std::string> instructionFiles;
  ConversionOptions approximate;
  approximate.instructions.approximate = true;
  auto add = [&](const Scene& s) {
    sceneFiles.push_back(writeSceneFile(s));
    DiagnosticList out;
    if (auto text = writeInstructionFile(s, approximate, out)) instructionFiles.push_back(*text);
  };
  for (const ValidFile& file : validFiles()) add(parseSceneAs(file.format, file.text, "").scene);
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    add(testing::RandomSceneGenerator(seed).scene(false));
  }
  ASSERT_GT(instructionFiles.size(), 40u);
  for (const std::string& text : sceneFiles) EXPECT_EQ(layoutOf(text, Format::SceneFile), text);
  for (const std::string& text : instructionFiles) {
    EXPECT_EQ(layoutOf(text, Format::InstructionFile), text);
  }
}

// `text` with blanks, tabs and blank lines added at random where they mean
// nothing, and a keyword or two in lower case.
std::string scrambled(std::string_view text, std::mt19937_64& rng) {
  static const char* blanks[] = {" ", "  ", "\t", " \t "};
  std::string out;
  LineCursor cursor(text);
  while (cursor.next()) {
    for (int n = static_cast<int>(rng() % 3); n > 0; --n) out += "\n";
    if (rng() % 2) out += blanks[rng() % 4];
    for (std::size_t i = 0; i < cursor.storedTokens(); ++i) {
      if (i) out += blanks[rng() % 4];
      std::string word(cursor.token(i).text);
      if (rng() % 8 == 0 && word[0] >= 'A' && word[0] <= 'Z' && word != "OUTPUT_FILE") {
        for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      }
      out += word;
    }
    if (rng() % 3 == 0) out += blanks[rng() % 4];
    out += "\n";
    if (rng() % 4 == 0) out += rng() % 2 ? "\n" : "  \t\n";
  }
  return out;
}

std::string withCrlf(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '\n') out += '\r';
    out += c;
  }
  return out;
}

TEST(CanonicalLayout, AnyBlanksGiveTheCanonicalText) {
  std::mt19937_64 rng(2024);
  for (const ValidFile& file : validFiles()) {
    SCOPED_TRACE(file.name);
    std::string canonical = layoutOf(file.text, file.format);
    bool bom = canonical.starts_with("\xEF\xBB\xBF");
    std::string_view body = std::string_view(canonical).substr(bom ? 3 : 0);
    bool crlf = canonical.find("\r\n") != std::string::npos;
    for (int round = 0; round < 20; ++round) {
      std::string text = scrambled(body, rng);
      bool toCrlf = rng() % 2;
      if (toCrlf) text = withCrlf(text);
      std::string expected(body);
      if (toCrlf && !crlf) expected = withCrlf(expected);
      if (!toCrlf && crlf) {
        std::erase(expected, '\r');
      }
      EXPECT_EQ(layoutOf(text, file.format), expected) << text;
    }
  }
}

TEST(CanonicalLayout, IndentsBlocksAndSeparatesTopLevelOnes) {
  std::string text =
      "\xEF\xBB\xBF"
      "OUTPUT_FILE a.ppm\r\nstart camera\r\n LOCATION 0 0 5\r\n\r\n\tLOOK_AT 0 0 0\r\n"
      "END   CAMERA\r\nSTART OBJECT sphere\r\nSTART MATERIAL\r\nCOLOUR  1e0 .5 -0\r\n"
      "END MATERIAL\r\n\r\n\r\nEND OBJECT";
  EXPECT_EQ(layoutOf(text, Format::InstructionFile),
            "\xEF\xBB\xBF"
            "OUTPUT_FILE a.ppm\r\n\r\nSTART CAMERA\r\n  LOCATION 0 0 5\r\n"
            "  LOOK_AT 0 0 0\r\nEND CAMERA\r\n\r\nSTART OBJECT SPHERE\r\n  START MATERIAL\r\n"
            "    COLOUR 1e0 .5 -0\r\n  END MATERIAL\r\nEND OBJECT\r\n");
  EXPECT_EQ(layoutOf("\n\n  camera\n0 0 0 \nSPHERE\n1 1 1", Format::SceneFile),
            "CAMERA\n0 0 0\n\nSPHERE\n1 1 1\n");
  EXPECT_EQ(layoutOf("", Format::SceneFile), "");
}

// However deep a text nests its STARTs, no line is indented more than the
// format nests: the layout's size stays in proportion to the text's.
TEST(CanonicalLayout, NoTextIndentsDeeperThanTheFormatNests) {
  std::string text;
  for (int i = 0; i < 10'000; ++i) text += "START OBJECT CUBE\nSTART MATERIAL\nSTART X\n";
  std::string laid = layoutOf(text, Format::InstructionFile);
  EXPECT_LT(laid.size(), 2 * text.size());
}

// Any text, however broken, lays out to a text that lays out to itself.
TEST(CanonicalLayout, AnyTextTwiceIsOnce) {
  std::vector<std::string> texts;
  for (const char* folder : {"hostile/sf", "hostile/instructions", "invalid"}) {
    for (const auto& entry :
         fs::recursive_directory_iterator(fs::path(SCENE_TESTDATA_DIR) / folder)) {
      if (entry.is_regular_file()) texts.push_back(readText(entry.path()));
    }
  }
  const char* words[] = {"CAMERA", "light", "SPHERE", "START", "end", "OBJECT", "MATERIAL",
                         "1",      "\r",    "\r\n",   "\n",    "\t",  " ",      "\xEF\xBB\xBF"};
  std::mt19937_64 rng(5);
  for (int round = 0; round < 500; ++round) {
    std::string text;
    for (int i = static_cast<int>(rng() % 200); i > 0; --i) text += words[rng() % std::size(words)];
    texts.push_back(text);
  }
  for (const std::string& text : texts) {
    for (Format format : {Format::SceneFile, Format::InstructionFile}) {
      std::optional<std::string> laid = canonicalLayout(text, format);
      if (laid) {
        EXPECT_EQ(canonicalLayout(*laid, format), laid) << text;
      }
    }
  }
}

TEST(CanonicalLayout, NothingForOtherFormatsOrForALineOfEndlessWords) {
  EXPECT_FALSE(canonicalLayout("sphere { 0, 1 }", Format::Pov));
  EXPECT_FALSE(canonicalLayout("{}", Format::Gltf));
  std::string words(100, 'x');
  for (std::size_t i = 1; i < words.size(); i += 2) words[i] = ' ';
  EXPECT_FALSE(canonicalLayout("CAMERA\n" + words + "\n", Format::SceneFile));
}

}  // namespace
}  // namespace scene
