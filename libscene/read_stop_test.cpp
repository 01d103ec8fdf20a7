// ReadOptions::stop: a read asked to stop returns early with what it has.
#include <gtest/gtest.h>

#include <stop_token>
#include <string>

#include "libscene/testing/test_support.h"
#include "scenefile/read.h"

namespace scene {
namespace {

std::string sceneFileOf(int spheres) {
  std::string text = testing::kCameraRecord;
  for (int i = 0; i < spheres; ++i) {
    text += "\nSPHERE\n1 0 0\n1 0 0 " + std::to_string(i) + "\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
  }
  return text;
}

std::string instructionFileOf(int spheres) {
  std::string text = "OUTPUT_FILE a.ppm\nSTART CAMERA\nLOCATION 0 0 5\nLOOK_AT 0 0 0\nEND CAMERA\n";
  for (int i = 0; i < spheres; ++i) {
    text += "START OBJECT SPHERE\nSTART TRANSFORMATION\nTRANSLATE " + std::to_string(i) +
            " 0 0\nEND TRANSFORMATION\nEND OBJECT\n";
  }
  return text;
}

ReadOptions stopped(std::stop_source& source, unsigned threads) {
  ReadOptions options;
  options.threads = threads;
  options.stop = source.get_token();
  source.request_stop();
  return options;
}

TEST(ReadStop, AStoppedReadOfEitherLineFormatReadsNoFurther) {
  // 100,000 records: 6 MB, read in parts on two threads unless stopped.
  std::string sceneFile = sceneFileOf(100'000);
  std::string instructionFile = instructionFileOf(100'000);
  for (unsigned threads : {1u, 2u}) {
    SCOPED_TRACE(threads);
    std::stop_source source;
    ReadOptions options = stopped(source, threads);
    EXPECT_LT(parseScene(sceneFile, "a.sf", options).scene.objects.size(), 5000u);
    EXPECT_LT(parseScene(instructionFile, "a.txt", options).scene.objects.size(), 5000u);
  }
}

TEST(ReadStop, ATokenNotStoppedReadsTheWhole) {
  std::stop_source source;
  ReadOptions options;
  options.stop = source.get_token();
  ReadResult sf = parseScene(sceneFileOf(10'000), "a.sf", options);
  EXPECT_TRUE(sf.ok());
  EXPECT_EQ(sf.scene.objects.size(), 10'000u);
  ReadResult instructions = parseScene(instructionFileOf(10'000), "a.txt", options);
  EXPECT_TRUE(instructions.ok());
  EXPECT_EQ(instructions.scene.objects.size(), 10'000u);
}

}  // namespace
}  // namespace scene
