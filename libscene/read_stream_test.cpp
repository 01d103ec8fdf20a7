// Streaming a scene file (streamSceneFile) gives what reading it whole
// gives: the same objects, each once and in order, the same camera, lights
// and diagnostics, for any window and thread count; its memory stays within
// a window's.
#include "scenefile/read_stream.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "libscene/formats/sf/sf_writer.h"
#include "libscene/testing/random_scenes.h"
#include "libscene/testing/test_support.h"
#include "scenefile/diagnostic_format.h"
#include "scenefile/read_file.h"
#include "scenefile/source_excerpt.h"

namespace scene {
namespace {

namespace fs = std::filesystem;
using testing::kCameraRecord;
using testing::kLightRecord;

struct Streamed {
  StreamReadResult result;
  std::vector<Object> objects;  // as the sink saw them, batch after batch
  std::size_t batches = 0;
};

Streamed stream(const fs::path& path, ReadOptions options) {
  Streamed out;
  out.result = streamSceneFile(path, options, [&](std::span<const Object> batch) {
    EXPECT_FALSE(batch.empty());
    out.objects.insert(out.objects.end(), batch.begin(), batch.end());
    ++out.batches;
  });
  return out;
}

// The streamed read against readSceneFile's, spans included.
void expectSameAsWhole(const fs::path& path, const ReadOptions& options) {
  SCOPED_TRACE(path.string() + ", window " + std::to_string(options.sceneFile.windowBytes) +
               ", threads " + std::to_string(options.threads));
  ReadResult whole = readSceneFile(path, options);
  Streamed streamed = stream(path, options);
  EXPECT_EQ(formatDiagnostics(streamed.result.read.diagnostics),
            formatDiagnostics(whole.diagnostics));
  EXPECT_EQ(streamed.result.read.diagnostics.items(), whole.diagnostics.items());
  EXPECT_EQ(streamed.result.objectCount, streamed.objects.size());
  EXPECT_TRUE(streamed.result.read.scene.objects.empty());
  Scene header = whole.scene;
  header.objects.clear();
  EXPECT_EQ(streamed.result.read.scene, header);
  EXPECT_EQ(streamed.result.read.scene.camera.span, whole.scene.camera.span);
  ASSERT_EQ(streamed.objects.size(), whole.scene.objects.size());
  for (std::size_t k = 0; k < whole.scene.objects.size(); ++k) {
    ASSERT_EQ(streamed.objects[k], whole.scene.objects[k]) << "object " << k;
    ASSERT_EQ(streamed.objects[k].span, whole.scene.objects[k].span) << "object " << k;
  }
}

ReadOptions withWindow(std::size_t windowBytes, unsigned threads) {
  ReadOptions options;
  options.sceneFile.windowBytes = windowBytes;
  options.threads = threads;
  return options;
}

const std::size_t kWindows[] = {200, 777, 4096, SceneFileReadOptions{}.windowBytes};

TEST(ReadStream, TheCorpusReadsAsWhole) {
  int files = 0;
  for (const char* folder : {"", "hostile"}) {
    for (const auto& entry :
         fs::recursive_directory_iterator(fs::path(SCENE_TESTDATA_DIR) / folder)) {
      std::error_code error;
      if (entry.is_symlink(error) || !entry.is_regular_file(error) ||
          entry.path().extension() == ".expect") {
        continue;
      }
      if (folder[0] == '\0' && entry.path().string().find("/hostile/") != std::string::npos) {
        continue;
      }
      ++files;
      for (unsigned threads : {1u, 2u, 3u}) {
        for (std::size_t window : {kWindows[0], kWindows[1]}) {
          expectSameAsWhole(entry.path(), withWindow(window, threads));
        }
      }
    }
  }
  EXPECT_GT(files, 100);
}

// Seeded random scenes, written as scene files, at every window size.
TEST(ReadStream, RandomScenesReadAsWhole) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    testing::RandomSceneGenerator generator(seed);
    Scene scene = generator.scene(seed % 2 == 0);
    fs::path path = testing::writeTempFile("read_stream_random.sf", writeSceneFile(scene));
    for (unsigned threads : {1u, 2u, 3u}) {
      for (std::size_t window : kWindows) expectSameAsWhole(path, withWindow(window, threads));
    }
  }
}

std::string sphere(int k) {
  return "SPHERE\n0.5 0.5 0.5\n1 0 0 " + std::to_string(k) + "\n0 1 0 0\n0 0 1 -10\n0 0 0 1\n";
}

std::string manySpheres(int count, int lightEvery = 0) {
  std::string text = kCameraRecord;
  for (int k = 0; k < count; ++k) {
    if (lightEvery > 0 && k % lightEvery == 0) text += kLightRecord;
    text += sphere(k);
  }
  return text;
}

TEST(ReadStream, TheSinkSeesEveryObjectOnceInOrder) {
  fs::path path = testing::writeTempFile("read_stream_order.sf", manySpheres(3000, 100));
  for (unsigned threads : {1u, 2u, 3u}) {
    std::vector<std::uint64_t> estimates;
    Streamed streamed;
    streamed.result = streamSceneFile(
        path, withWindow(1000, threads),
        [&](std::span<const Object> batch) {
          EXPECT_EQ(estimates.size(), 1u) << "the estimate comes first";
          streamed.objects.insert(streamed.objects.end(), batch.begin(), batch.end());
          ++streamed.batches;
        },
        nullptr, [&](std::uint64_t objects) { estimates.push_back(objects); });
    // Objects and lights, by the first window's bytes an object, and a
    // little over.
    ASSERT_EQ(estimates.size(), 1u);
    EXPECT_GE(estimates[0], 3030u);
    EXPECT_LE(estimates[0], 3030u * 11 / 10 + 1024);
    ASSERT_TRUE(streamed.result.read.ok()) << formatDiagnostics(streamed.result.read.diagnostics);
    EXPECT_FALSE(streamed.result.readWhole);
    EXPECT_GT(streamed.batches, 10u);
    ASSERT_EQ(streamed.objects.size(), 3000u);
    for (int k = 0; k < 3000; ++k) {
      ASSERT_EQ(streamed.objects[k].matrix[3][0], k) << k;
    }
    EXPECT_EQ(streamed.result.read.scene.lights.size(), 30u);
  }
}

// An error in the second window and one in the last are reported at their
// line and column, as the whole-file reader reports them.
TEST(ReadStream, ErrorsInLaterWindowsAreWhereTheyAre) {
  const int kSpheres = 400;
  for (int at : {10, kSpheres - 1}) {
    std::string text = kCameraRecord;
    for (int k = 0; k < kSpheres; ++k)
      text += k == at ? "SPHERE\n0.5 0.5 oops\n1 0 0 0\n0 1 0 0\n0 0 1 -10\n0 0 0 1\n" : sphere(k);
    fs::path path = testing::writeTempFile("read_stream_error.sf", text);
    ReadOptions options = withWindow(500, 2);
    Streamed streamed = stream(path, options);
    EXPECT_TRUE(streamed.result.readWhole);
    ASSERT_FALSE(streamed.result.read.ok());
    const Diagnostic& first = streamed.result.read.diagnostics.items().front();
    // The camera's 6 lines, then 6 a sphere: the colour line is the second.
    EXPECT_EQ(first.span.line, static_cast<std::uint32_t>(6 + 6 * at + 2));
    EXPECT_EQ(first.span.column, 9u);
    expectSameAsWhole(path, options);
  }
}

TEST(ReadStream, TheLimitsHoldAsForTheWholeRead) {
  fs::path path = testing::writeTempFile("read_stream_limits.sf", manySpheres(200));
  ReadOptions options = withWindow(300, 2);
  options.maxObjects = 150;
  expectSameAsWhole(path, options);
  EXPECT_EQ(stream(path, options).result.read.diagnostics.items().front().code,
            DiagnosticCode::TooManyObjects);
  options.maxObjects = 200;
  EXPECT_TRUE(stream(path, options).result.read.ok());
  options.maxFileSize = fs::file_size(path) - 1;
  expectSameAsWhole(path, options);
  Streamed refused = stream(path, options);
  EXPECT_EQ(refused.result.read.diagnostics.items().front().code, DiagnosticCode::FileTooLarge);
  EXPECT_TRUE(refused.objects.empty());
}

// A file of 50 windows holds no more than two windows' text (the one parsed
// and the next, read meanwhile) and a window's objects.
TEST(ReadStream, MemoryStaysWithinTheWindow) {
  const std::size_t kWindow = 16384;
  std::string text = manySpheres(1);
  while (text.size() < 50 * kWindow) text += sphere(static_cast<int>(text.size() % 1000));
  fs::path path = testing::writeTempFile("read_stream_memory.sf", text);
  for (unsigned threads : {1u, 2u}) {
    Streamed streamed = stream(path, withWindow(kWindow, threads));
    ASSERT_TRUE(streamed.result.read.ok());
    EXPECT_FALSE(streamed.result.readWhole);
    const StreamReadMemory& memory = streamed.result.memory;
    EXPECT_GT(memory.textBytes, 0u);
    EXPECT_LE(memory.textBytes, 2 * kWindow * threads);
    // An object per some 60 bytes of text at most.
    EXPECT_GT(memory.modelBytes, 0u);
    EXPECT_LE(memory.modelBytes, 2 * kWindow * threads / 60 * sizeof(Object));
  }
}

// The entries of /proc/self/fd: the files this process holds open.
std::size_t openFiles() {
  std::size_t count = 0;
  for (const auto& entry : fs::directory_iterator("/proc/self/fd")) {
    (void)entry;
    ++count;
  }
  return count;
}

// The whole-file checks of a streamed file quote its lines as a whole read
// does: a file with no LIGHT is warned at its CAMERA, whose line is
// quoted, at any window and thread count.
TEST(ReadStream, QuotesTheHeaderAsTheWholeReadDoes) {
  const std::string text = manySpheres(3000);
  fs::path path = testing::writeTempFile("read_stream_quotes.sf", text);
  SourceExcerpts wholeQuotes;
  ReadResult whole = readSceneFile(path, ReadOptions{});
  wholeQuotes.capture(path.string(), text, whole.diagnostics);
  ASSERT_EQ(whole.diagnostics.items().size(), 1u);
  ASSERT_EQ(whole.diagnostics.items()[0].code, DiagnosticCode::NoLight);
  const std::string expected = formatDiagnostics(whole.diagnostics, {}, &wholeQuotes);
  ASSERT_NE(expected.find("CAMERA"), std::string::npos) << expected;
  for (std::size_t window : {std::size_t{777}, std::size_t{4096}}) {
    for (unsigned threads : {1u, 2u}) {
      SourceExcerpts quotes;
      StreamReadResult streamed = streamSceneFile(
          path, withWindow(window, threads), [](std::span<const Object>) {}, &quotes);
      EXPECT_FALSE(streamed.readWhole);
      EXPECT_EQ(formatDiagnostics(streamed.read.diagnostics, {}, &quotes), expected)
          << "window " << window << ", threads " << threads;
    }
  }
}

// A sink that throws (a caller's limit, memory) ends the read with its
// exception, the file closed and the reading thread stopped.
TEST(ReadStream, ASinksExceptionLeavesNoFileOpen) {
  fs::path path = testing::writeTempFile("read_stream_throwing_sink.sf", manySpheres(3000));
  const std::size_t before = openFiles();
  for (unsigned threads : {1u, 2u}) {
    std::size_t batches = 0;
    auto throwing = [&](std::span<const Object>) {
      if (++batches == 2) throw std::length_error("too many objects");
    };
    EXPECT_THROW(streamSceneFile(path, withWindow(1000, threads), throwing), std::length_error);
    EXPECT_EQ(batches, 2u);
  }
  EXPECT_EQ(openFiles(), before);
}

}  // namespace
}  // namespace scene
