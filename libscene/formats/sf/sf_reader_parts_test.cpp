// Reading a scene file in parts on several threads (parseSceneFileInParts)
// gives exactly what reading it whole gives, or nothing.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <random>
#include <string>

#include "libscene/formats/sf/sf_reader.h"
#include "libscene/testing/test_support.h"

namespace scene {
namespace {

using testing::kCameraRecord;

// A valid scene of `objects` objects of every kind, with seeded random
// colours and matrices, and a light after every 1,000th object, so that
// lights fall in every part.
std::string bigScene(int objects, std::uint32_t seed, const std::string& newline = "\n") {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.05, 0.95), offset(-100.0, 100.0);
  const char* kinds[] = {"SPHERE", "CUBE", "CYLINDER", "SPHERE"};
  std::string text = kCameraRecord;
  auto line = [&](std::initializer_list<double> values) {
    std::string out;
    for (double v : values) {
      char number[32];
      std::snprintf(number, sizeof number, "%.9g", v);
      out += (out.empty() ? "" : " ") + std::string(number);
    }
    return out + newline;
  };
  for (int k = 0; k < objects; ++k) {
    if (k % 1000 == 0) {
      text += "LIGHT" + newline + line({unit(random), unit(random), unit(random)}) +
              line({1, 0, 0, offset(random)}) + line({0, 1, 0, 50}) +
              line({0, 0, 1, offset(random)}) + line({0, 0, 0, 1});
    }
    text += std::string(kinds[k % 4]) + newline + line({unit(random), unit(random), unit(random)}) +
            line({unit(random) + 0.5, 0.1, 0, offset(random)}) +
            line({0, unit(random) + 0.5, 0.2, offset(random)}) +
            line({0.1, 0, unit(random) + 0.5, offset(random)}) + line({0, 0, 0, 1});
  }
  return text;
}

ReadOptions oneThread() {
  ReadOptions options;
  options.threads = 1;
  return options;
}

void expectSameRead(const ReadResult& whole, const ReadResult& inParts) {
  EXPECT_EQ(whole.scene, inParts.scene);
  EXPECT_EQ(whole.diagnostics.items(), inParts.diagnostics.items());
  // Every record where the file has it (operator== leaves spans out).
  ASSERT_EQ(whole.scene.objects.size(), inParts.scene.objects.size());
  for (std::size_t k = 0; k < whole.scene.objects.size(); ++k) {
    ASSERT_EQ(whole.scene.objects[k].span, inParts.scene.objects[k].span) << "object " << k;
  }
  ASSERT_EQ(whole.scene.lights.size(), inParts.scene.lights.size());
  for (std::size_t k = 0; k < whole.scene.lights.size(); ++k) {
    ASSERT_EQ(whole.scene.lights[k].span, inParts.scene.lights[k].span) << "light " << k;
  }
  EXPECT_EQ(whole.scene.camera.span, inParts.scene.camera.span);
}

TEST(SceneFileReaderInParts, GivesTheWholeFileReadersSceneAtAnyCount) {
  for (const std::string& newline : {std::string("\n"), std::string("\r\n")}) {
    for (const std::string& bom : {std::string(), std::string("\xEF\xBB\xBF")}) {
      std::string text = bom + bigScene(3000, 7, newline);
      ReadResult whole = parseSceneFile(text, "big.sf", oneThread());
      ASSERT_TRUE(whole.ok());
      ASSERT_EQ(whole.scene.objects.size(), 3000u);
      for (unsigned parts : {2u, 3u, 7u, 64u}) {
        std::optional<ReadResult> inParts = parseSceneFileInParts(text, "big.sf", {}, parts);
        ASSERT_TRUE(inParts.has_value()) << parts << " parts";
        expectSameRead(whole, *inParts);
      }
    }
  }
}

TEST(SceneFileReaderInParts, TheWholeFileChecksStillRun) {
  // Objects but no light: the whole-file warning that nothing is lit.
  std::string text = kCameraRecord;
  for (int k = 0; k < 200; ++k) {
    text += "CUBE\n0.5 0.5 0.5\n1 0 0 " + std::to_string(3 * k) + "\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
  }
  ReadResult whole = parseSceneFile(text, "dark.sf", oneThread());
  ASSERT_FALSE(whole.diagnostics.empty());
  std::optional<ReadResult> inParts = parseSceneFileInParts(text, "dark.sf", {}, 4);
  ASSERT_TRUE(inParts.has_value());
  expectSameRead(whole, *inParts);
}

// Any diagnostic in a part, the CAMERA anywhere but first, or more objects
// than allowed: nothing, and parseSceneFile reads the file whole, with the
// whole file's diagnostics.
TEST(SceneFileReaderInParts, LeavesToTheWholeFileReaderEveryFileWithADiagnostic) {
  const std::string valid = bigScene(3000, 11);
  const std::size_t late = valid.size() * 9 / 10, early = valid.size() / 10;
  auto atRecord = [&](std::size_t from) { return valid.find("\nCUBE\n", from) + 1; };
  struct Damage {
    const char* what;
    std::string text;
  } damages[] = {
      {"a bad number late",
       valid.substr(0, atRecord(late) + 7) + "x" + valid.substr(atRecord(late) + 8)},
      {"a second camera late",
       valid.substr(0, atRecord(late)) + kCameraRecord + valid.substr(atRecord(late))},
      {"a comment early",
       valid.substr(0, atRecord(early)) + "# note\n" + valid.substr(atRecord(early))},
      {"a truncated record late", valid.substr(0, atRecord(late) + 5) +
                                      valid.substr(valid.find('\n', atRecord(late) + 6) + 1)},
      {"the camera last", valid.substr(kCameraRecord.size()) + kCameraRecord},
      {"a lower-case name late",
       valid.substr(0, atRecord(late)) + "cube" + valid.substr(atRecord(late) + 4)},
  };
  for (const Damage& damage : damages) {
    ReadResult whole = parseSceneFile(damage.text, "bad.sf", oneThread());
    EXPECT_FALSE(whole.diagnostics.empty()) << damage.what;
    EXPECT_FALSE(parseSceneFileInParts(damage.text, "bad.sf", {}, 4).has_value()) << damage.what;
  }
  ReadOptions few;
  few.maxObjects = 2500;
  EXPECT_FALSE(parseSceneFileInParts(valid, "big.sf", few, 4).has_value());
  few.threads = 1;
  EXPECT_FALSE(parseSceneFile(valid, "big.sf", few).ok());
}

// Past kMinBytesInParts, parseSceneFile itself reads in parts: the same
// scene and diagnostics at 1, 2 and 5 threads, for a clean file and for one
// with an error in its last part.
TEST(SceneFileReaderInParts, ParseSceneFileGivesOneResultAtAnyThreadCount) {
  std::string text = bigScene(40000, 3);
  ASSERT_GE(text.size(), kMinBytesInParts);
  std::string damaged = text;
  damaged[damaged.rfind("\n0 0 0 1\n") + 1] = '2';  // the last row must be 0 0 0 1
  for (const std::string& input : {text, damaged}) {
    ReadResult whole = parseSceneFile(input, "big.sf", oneThread());
    for (unsigned threads : {2u, 5u}) {
      ReadOptions options;
      options.threads = threads;
      expectSameRead(whole, parseSceneFile(input, "big.sf", options));
    }
  }
}

}  // namespace
}  // namespace scene
