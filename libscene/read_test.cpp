#include "scenefile/read.h"

#include <gtest/gtest.h>

#include <string>

#include "libscene/testing/test_support.h"

namespace scene {
namespace {

using testing::withCode;

TEST(CheckFileSize, RefusesOnlyAboveTheLimit) {
  ReadOptions options;
  options.maxFileSize = 100;
  DiagnosticList out("big.sf");
  EXPECT_TRUE(checkFileSize(100, options, out));
  EXPECT_TRUE(out.empty());
  EXPECT_FALSE(checkFileSize(101, options, out));
  ASSERT_EQ(out.items().size(), 1u);
  const Diagnostic& d = out.items()[0];
  EXPECT_EQ(d.code, DiagnosticCode::FileTooLarge);
  EXPECT_EQ(d.severity, Severity::Error);
  EXPECT_EQ(d.file, "big.sf");
  EXPECT_EQ(d.message, "the file is 101 bytes, more than the limit of 100");
  EXPECT_EQ(d.hint, "raise the limit with {0} if the file is meant to be this large");
  EXPECT_EQ(d.remedies, (std::vector<Remedy>{{Setting::MaxFileSize, "101"}}));
}

TEST(CheckFileSize, AnInputOfUnknownSizeIsOverTheLimitWithTheSameCure) {
  ReadOptions options;
  options.maxFileSize = 100;
  DiagnosticList out("-");
  EXPECT_FALSE(checkFileSize(101, options, out, "the input", false));
  ASSERT_EQ(out.items().size(), 1u);
  EXPECT_EQ(out.items()[0].message, "the input is more than the limit of 100 bytes");
  EXPECT_EQ(out.items()[0].remedies, (std::vector<Remedy>{{Setting::MaxFileSize, ""}}));
}

TEST(CheckFileSize, TheDefaultIsOneGibibyte) {
  ReadOptions options;
  DiagnosticList out;
  EXPECT_TRUE(checkFileSize(std::uint64_t{1} << 30, options, out));
  EXPECT_FALSE(checkFileSize((std::uint64_t{1} << 30) + 1, options, out));
}

// parseScene refuses an over-large text in every format before any reader
// sees it: one error and nothing else.
TEST(ParseScene, RefusesTextAboveMaxFileSizeInEveryFormat) {
  std::string scene = testing::kCameraRecord + testing::kLightRecord;
  const std::string texts[] = {
      scene,
      "OUTPUT_FILE a.ppm\nSTART CAMERA\nLOCATION 0 0 5\nLOOK_AT 0 0 0\nEND CAMERA\n",
      "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": []}",
      "camera { location <0, 0, -5> look_at 0 }\nsphere { 0, 1 }\n",
  };
  for (const std::string& text : texts) {
    ReadOptions options;
    options.maxFileSize = text.size() - 1;
    ReadResult refused = parseScene(text, "in", options);
    ASSERT_EQ(refused.diagnostics.items().size(), 1u) << text;
    EXPECT_EQ(refused.diagnostics.items()[0].code, DiagnosticCode::FileTooLarge) << text;
    options.maxFileSize = text.size();
    EXPECT_TRUE(
        withCode(parseScene(text, "in", options).diagnostics, DiagnosticCode::FileTooLarge).empty())
        << text;
  }
}

// The POV-Ray reader shares maxObjects through parseScene.
TEST(ParseScene, PassesMaxObjectsToThePovRayReader) {
  std::string text = "camera { location <0, 0, -5> look_at 0 }\nsphere { 0, 1 }\nsphere { 1, 1 }\n";
  ReadOptions options;
  options.maxObjects = 1;
  ReadResult r = parseScene(text, "in.pov", options);
  EXPECT_EQ(withCode(r.diagnostics, DiagnosticCode::TooManyObjects).size(), 1u);
  options.maxObjects = 2;
  EXPECT_TRUE(
      withCode(parseScene(text, "in.pov", options).diagnostics, DiagnosticCode::TooManyObjects)
          .empty());
}

}  // namespace
}  // namespace scene
