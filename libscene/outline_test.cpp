#include "scenefile/outline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include "libscene/testing/test_support.h"
#include "scenefile/read.h"

namespace scene {
namespace {

namespace fs = std::filesystem;

using scene::testing::readText;

// What holds for the outline of any text: items in the order they start,
// each inside the one that holds it, and innermostAt finding them.
void expectWellFormed(const Outline& outline) {
  for (std::size_t i = 0; i < outline.items.size(); ++i) {
    const OutlineItem& item = outline.items[i];
    ASSERT_LE(item.firstLine, item.lastLine) << i;
    if (i > 0) {
      ASSERT_LT(outline.items[i - 1].firstLine, item.firstLine) << i;
    }
    if (item.parent != Outline::kNoParent) {
      ASSERT_LT(item.parent, i);
      const OutlineItem& parent = outline.items[item.parent];
      ASSERT_LE(parent.firstLine, item.firstLine);
      ASSERT_GE(parent.lastLine, item.lastLine);
    }
    ASSERT_EQ(outline.innermostAt(item.firstLine), &item) << i;
  }
}

std::vector<const OutlineItem*> itemsOf(const Outline& outline, OutlineKind kind) {
  std::vector<const OutlineItem*> out;
  for (const OutlineItem& item : outline.items) {
    if (item.kind == kind) out.push_back(&item);
  }
  return out;
}

// A valid file's outline numbers its lights and objects as the scene holds
// them, each at the line the reader records.
TEST(OutlineOf, AgreesWithTheSceneOnEveryValidFile) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(SCENE_TESTDATA_DIR) / "valid")) {
    std::string ext = entry.path().extension().string();
    if (ext != ".sf" && ext != ".txt") continue;
    SCOPED_TRACE(entry.path().filename().string());
    std::string text = readText(entry.path());
    ReadResult read = parseScene(text, entry.path().string());
    ASSERT_TRUE(read.ok());
    Format format = ext == ".sf" ? Format::SceneFile : Format::InstructionFile;
    Outline outline = outlineOf(text, format);
    expectWellFormed(outline);
    for (const OutlineItem& item : outline.items) EXPECT_TRUE(item.complete);
    std::vector<const OutlineItem*> cameras = itemsOf(outline, OutlineKind::Camera);
    ASSERT_EQ(cameras.size(), 1u);
    EXPECT_EQ(cameras[0]->firstLine, read.scene.camera.span.line);
    std::vector<const OutlineItem*> lights = itemsOf(outline, OutlineKind::Light);
    ASSERT_EQ(lights.size(), read.scene.lights.size());
    for (std::size_t i = 0; i < lights.size(); ++i) {
      EXPECT_EQ(lights[i]->number, i + 1);
      EXPECT_EQ(lights[i]->firstLine, read.scene.lights[i].span.line);
    }
    std::vector<const OutlineItem*> objects = itemsOf(outline, OutlineKind::Object);
    ASSERT_EQ(objects.size(), read.scene.objects.size());
    for (std::size_t i = 0; i < objects.size(); ++i) {
      EXPECT_EQ(objects[i]->number, i + 1);
      EXPECT_EQ(objects[i]->firstLine, read.scene.objects[i].span.line);
      EXPECT_EQ(objects[i]->objectKind, read.scene.objects[i].kind);
    }
    EXPECT_EQ(itemsOf(outline, OutlineKind::OutputFile).size(), read.scene.outputFile ? 1u : 0u);
    ++files;
  }
  EXPECT_GT(files, 40);
}

TEST(OutlineOf, SceneFileRecordsAndOneCutShort) {
  std::string text =
      "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 5\n0 0 0 1\n\n"
      "  sphere\n1 0 0\n\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n\n"
      "LIGHT\n1 1 1\n1 0 0 3\n"
      "CUBE\n1 1 1\n";
  Outline outline = outlineOf(text, Format::SceneFile);
  expectWellFormed(outline);
  ASSERT_EQ(outline.items.size(), 4u);
  const OutlineItem& sphere = outline.items[1];
  EXPECT_EQ(sphere.kind, OutlineKind::Object);
  EXPECT_EQ(sphere.objectKind, ObjectKind::Sphere);
  EXPECT_EQ(sphere.number, 1u);
  EXPECT_EQ(sphere.firstLine, 8u);
  EXPECT_EQ(sphere.lastLine, 14u);
  EXPECT_TRUE(sphere.complete);
  EXPECT_EQ(sphere.name, (SourceSpan{8, 3, 6}));
  const OutlineItem& light = outline.items[2];
  EXPECT_EQ(light.number, 1u);
  EXPECT_EQ(light.firstLine, 16u);
  EXPECT_EQ(light.lastLine, 18u);
  EXPECT_FALSE(light.complete);
  EXPECT_EQ(outline.items[3].number, 2u);
  EXPECT_EQ(outline.items[3].lastLine, 20u);
  EXPECT_EQ(outline.innermostAt(7), nullptr);
  EXPECT_EQ(outline.innermostAt(10), &sphere);
  EXPECT_EQ(outline.innermostAt(99), nullptr);
}

TEST(OutlineOf, InstructionBlocksNestAndUnclosedOnesEndAtTheNextStart) {
  std::string text =
      "OUTPUT_FILE a.ppm\n"       // 1
      "START CAMERA\n"            // 2
      "LOCATION 0 0 5\n"          // 3
      "\n"                        // 4
      "START OBJECT cube\n"       // 5
      "  START MATERIAL\n"        // 6
      "    COLOUR 1 0 0\n"        // 7
      "  START TRANSFORMATION\n"  // 8
      "    SCALE 1 2 3\n"         // 9
      "  END TRANSFORMATION\n"    // 10
      "END OBJECT\n"              // 11
      "START LIGHT\n"             // 12
      "  LOCATION 1 1 1\n";       // 13
  Outline outline = outlineOf(text, Format::InstructionFile);
  expectWellFormed(outline);
  ASSERT_EQ(outline.items.size(), 6u);
  EXPECT_EQ(outline.items[0].kind, OutlineKind::OutputFile);
  EXPECT_EQ(outline.items[0].name, (SourceSpan{1, 1, 11}));
  const OutlineItem& camera = outline.items[1];
  EXPECT_EQ(camera.lastLine, 3u);
  EXPECT_FALSE(camera.complete);
  const OutlineItem& object = outline.items[2];
  EXPECT_EQ(object.objectKind, ObjectKind::Cube);
  EXPECT_EQ(object.number, 1u);
  EXPECT_EQ(object.name, (SourceSpan{5, 1, 17}));
  EXPECT_EQ(object.firstLine, 5u);
  EXPECT_EQ(object.lastLine, 11u);
  EXPECT_TRUE(object.complete);
  const OutlineItem& material = outline.items[3];
  EXPECT_EQ(material.kind, OutlineKind::Material);
  EXPECT_EQ(material.parent, 2u);
  EXPECT_EQ(material.lastLine, 7u);
  EXPECT_FALSE(material.complete);
  EXPECT_EQ(outline.items[4].kind, OutlineKind::Transformation);
  EXPECT_EQ(outline.items[4].lastLine, 10u);
  EXPECT_TRUE(outline.items[4].complete);
  EXPECT_EQ(outline.items[5].number, 1u);
  EXPECT_EQ(outline.items[5].lastLine, 13u);
  EXPECT_EQ(outline.innermostAt(9), &outline.items[4]);
  EXPECT_EQ(outline.innermostAt(11), &object);
  EXPECT_EQ(outline.innermostAt(4), nullptr);
}

TEST(OutlineOf, NothingForTheOtherFormats) {
  EXPECT_TRUE(outlineOf("{\"asset\": {}}", Format::Gltf).items.empty());
  EXPECT_TRUE(outlineOf("sphere { 0, 1 }", Format::Pov).items.empty());
  EXPECT_TRUE(placeAt("sphere { 0, 1 }", Format::Pov, 0, 1, 1).words.empty());
}

// Any text gives some outline, and every place in it some answer.
TEST(OutlineOf, AnyTextInEitherFormat) {
  std::vector<std::string> texts;
  for (const char* folder : {"hostile/sf", "hostile/instructions", "invalid", "fuzz"}) {
    fs::path dir = fs::path(SCENE_TESTDATA_DIR) / folder;
    if (!fs::exists(dir)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
      if (entry.is_regular_file()) texts.push_back(readText(entry.path()));
    }
  }
  const char* words[] = {"CAMERA",       "light",       "SPHERE",        "START",  "END",
                         "OBJECT",       "MATERIAL",    "cube",          "COLOUR", "1",
                         "\xEF\xBB\xBF", "OUTPUT_FILE", "\r\n",          "\n",     "\n",
                         "\t",           "#",           "TRANSFORMATION"};
  std::mt19937_64 rng(11);
  for (int round = 0; round < 500; ++round) {
    std::string text;
    for (int i = static_cast<int>(rng() % 300); i > 0; --i) {
      text += words[rng() % std::size(words)];
      text += rng() % 3 ? " " : "";
    }
    texts.push_back(text);
  }
  std::string bytes(1 << 16, '\0');
  for (char& c : bytes) c = static_cast<char>(rng());
  texts.push_back(bytes);
  for (const std::string& text : texts) {
    for (Format format : {Format::SceneFile, Format::InstructionFile}) {
      Outline outline = outlineOf(text, format);
      expectWellFormed(outline);
      // A place on each of the first lines, at a column in or past them.
      std::size_t lineStart = 0;
      for (std::uint32_t line = 1; line <= 40 && lineStart <= text.size(); ++line) {
        TextPlace place = placeAt(text, format, lineStart, line, 1 + rng() % 20);
        EXPECT_LE(place.wordIndex, place.words.size());
        if (place.block) {
          EXPECT_LE(place.blockFirstLine, line);
        }
        std::size_t newline = text.find('\n', lineStart);
        if (newline == std::string::npos) break;
        lineStart = newline + 1;
      }
    }
  }
}

// Texts that nest or repeat without end, `blocks` times over.
struct EndlessTexts {
  std::string nested = "OUTPUT_FILE a.ppm\n";
  std::string repeated;
  std::string unended = "OUTPUT_FILE a.ppm\nSTART OBJECT SPHERE\n";

  explicit EndlessTexts(int blocks) {
    for (int i = 0; i < blocks; ++i) {
      nested += "START OBJECT SPHERE\nSTART MATERIAL\n";
      repeated += "CAMERA\n";
      unended += "SCALE 1 1 1\nEND MATERIAL\n";
    }
  }
};

// A place on the last line of an instruction file, `times` over.
void placeAtTheEnd(const std::string& text, int times) {
  std::size_t lastLine = text.rfind('\n', text.size() - 2) + 1;
  auto line = static_cast<std::uint32_t>(std::count(text.begin(), text.end(), '\n'));
  for (int i = 0; i < times; ++i) placeAt(text, Format::InstructionFile, lastLine, line, 1);
}

// Texts that nest or repeat without end cost time in proportion to their
// size, and a place in them no more than a few thousand lines' reading.
// Both are ratios of times taken in one run, so that a slow machine or a
// sanitizer divides out: ten times the text costs about ten times the
// outline's time (a hundred, were it quadratic) and the same time for a
// place at its end (ten times, were the whole text read back). Each time is
// the fastest of three, taken in turn, so that what else the machine runs
// weighs on neither side alone.
TEST(OutlineOf, EndlessNestingAndRepetitionInLinearTime) {
  EndlessTexts small(10'000);
  EndlessTexts large(100'000);
  EXPECT_EQ(outlineOf(large.nested, Format::InstructionFile).items.size(), 200'001u);
  EXPECT_EQ(outlineOf(large.repeated, Format::SceneFile).items.size(), 100'000u);
  EXPECT_EQ(outlineOf(large.unended, Format::InstructionFile).items.size(), 2u);

  auto outlineTime = [](const EndlessTexts& texts) {
    auto start = std::chrono::steady_clock::now();
    outlineOf(texts.nested, Format::InstructionFile);
    outlineOf(texts.repeated, Format::SceneFile);
    outlineOf(texts.unended, Format::InstructionFile);
    return testing::secondsSince(start);
  };
  auto placeTime = [](const EndlessTexts& texts) {
    auto start = std::chrono::steady_clock::now();
    placeAtTheEnd(texts.nested, 50);
    placeAtTheEnd(texts.unended, 50);
    return testing::secondsSince(start);
  };
  double inf = std::numeric_limits<double>::infinity();
  double smallOutline = inf, largeOutline = inf, smallPlace = inf, largePlace = inf;
  for (int run = 0; run < 3; ++run) {
    smallOutline = std::min(smallOutline, outlineTime(small));
    largeOutline = std::min(largeOutline, outlineTime(large));
    smallPlace = std::min(smallPlace, placeTime(small));
    largePlace = std::min(largePlace, placeTime(large));
  }
  EXPECT_LT(largeOutline, 30 * smallOutline) << smallOutline << " s, then " << largeOutline;
  EXPECT_LT(largePlace, 4 * smallPlace) << smallPlace << " s, then " << largePlace;
}

TEST(PlaceAt, SceneFileLinesInTheirRecord) {
  std::string text =
      "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 5\n0 0 0 1\n\n"
      "CYLINDER\n1 0 0\n\n1 0 0 0\n0 1  0 7\n";
  std::size_t row2 = text.find("0 1  0 7");
  TextPlace place = placeAt(text, Format::SceneFile, row2, 12, 8);
  EXPECT_EQ(place.block, OutlineKind::Object);
  EXPECT_EQ(place.objectKind, ObjectKind::Cylinder);
  EXPECT_EQ(place.blockFirstLine, 8u);
  EXPECT_EQ(place.recordLine, 3u);
  ASSERT_EQ(place.words.size(), 4u);
  EXPECT_EQ(place.wordIndex, 3u);
  EXPECT_EQ(place.words[3].text, "7");
  EXPECT_EQ(place.words[3].span, (SourceSpan{12, 8, 1}));
  EXPECT_EQ(placeAt(text, Format::SceneFile, row2, 12, 5).wordIndex, 4u);  // between words

  TextPlace name = placeAt(text, Format::SceneFile, 0, 1, 7);
  EXPECT_EQ(name.block, OutlineKind::Camera);
  EXPECT_EQ(name.recordLine, 0u);
  EXPECT_EQ(name.wordIndex, 0u);
  TextPlace between = placeAt(text, Format::SceneFile, text.find("\n\nCYL") + 1, 7, 1);
  EXPECT_FALSE(between.block);
  EXPECT_TRUE(between.words.empty());
  // Six lines on from a record's name: the next record's place, no record's.
  std::string more = text + "0 0 1 0\n0 0 0 1\nSPH\n";
  TextPlace typed = placeAt(more, Format::SceneFile, more.find("SPH"), 15, 4);
  EXPECT_FALSE(typed.block);
  EXPECT_EQ(typed.words[0].text, "SPH");
}

TEST(PlaceAt, SceneFileLineOneAfterAByteOrderMark) {
  std::string text =
      "\xEF\xBB\xBF"
      "CAMERA\r\n0 0 0\r\n";
  TextPlace place = placeAt(text, Format::SceneFile, 0, 1, 1);
  ASSERT_EQ(place.words.size(), 1u);
  EXPECT_EQ(place.words[0].text, "CAMERA");
  EXPECT_EQ(place.words[0].span, (SourceSpan{1, 1, 6}));
  TextPlace colour = placeAt(text, Format::SceneFile, text.find("0 0 0"), 2, 1);
  EXPECT_EQ(colour.recordLine, 1u);
  EXPECT_EQ(colour.words.back().text, "0");
}

TEST(PlaceAt, InstructionFileBlockAndTheKeywordsGivenInIt) {
  std::string text =
      "OUTPUT_FILE a.ppm\n"       // 1
      "START OBJECT SPHERE\n"     // 2
      "  START MATERIAL\n"        // 3
      "    COLOUR 1 0 0\n"        // 4
      "    \n"                    // 5
      "    RI 1.5\n"              // 6
      "  END MATERIAL\n"          // 7
      "  \n"                      // 8
      "  START TRANSFORMATION\n"  // 9
      "  END TRANSFORMATION\n"    // 10
      "END OBJECT\n"              // 11
      "\n"                        // 12
      "START LIGHT\n";            // 13
  auto lineStart = [&](std::uint32_t line) {
    std::size_t at = 0;
    for (std::uint32_t l = 1; l < line; ++l) at = text.find('\n', at) + 1;
    return at;
  };
  TextPlace inMaterial = placeAt(text, Format::InstructionFile, lineStart(5), 5, 5);
  EXPECT_EQ(inMaterial.block, OutlineKind::Material);
  EXPECT_EQ(inMaterial.objectKind, ObjectKind::Sphere);
  EXPECT_EQ(inMaterial.blockFirstLine, 3u);
  EXPECT_EQ(inMaterial.keywordsInBlock, (std::vector<std::string_view>{"COLOUR", "RI"}));
  EXPECT_EQ(inMaterial.wordIndex, 0u);
  EXPECT_TRUE(inMaterial.words.empty());

  TextPlace inObject = placeAt(text, Format::InstructionFile, lineStart(8), 8, 3);
  EXPECT_EQ(inObject.block, OutlineKind::Object);
  EXPECT_EQ(inObject.blockFirstLine, 2u);
  EXPECT_EQ(inObject.keywordsInBlock,
            (std::vector<std::string_view>{"MATERIAL", "TRANSFORMATION"}));

  // A START line is in the block around it.
  TextPlace start = placeAt(text, Format::InstructionFile, lineStart(9), 9, 9);
  EXPECT_EQ(start.block, OutlineKind::Object);
  EXPECT_EQ(start.wordIndex, 1u);
  EXPECT_EQ(start.words[1].text, "TRANSFORMATION");
  TextPlace end = placeAt(text, Format::InstructionFile, lineStart(10), 10, 1);
  EXPECT_EQ(end.block, OutlineKind::Transformation);

  TextPlace topLevel = placeAt(text, Format::InstructionFile, lineStart(12), 12, 1);
  EXPECT_FALSE(topLevel.block);
  EXPECT_FALSE(placeAt(text, Format::InstructionFile, lineStart(13), 13, 1).block);
  EXPECT_FALSE(placeAt(text, Format::InstructionFile, 0, 1, 1).block);
}

}  // namespace
}  // namespace scene
