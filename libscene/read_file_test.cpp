// Reading by path: the size checked before a byte is read, what cannot be
// read a diagnostic, and the quoted lines kept when the text is not.
#include "scenefile/read_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "libscene/testing/test_support.h"
#include "scenefile/diagnostic_format.h"

namespace scene {
namespace {

namespace fs = std::filesystem;

TEST(ReadFile, ReadsAndParsesByPath) {
  fs::path path = fs::path(SCENE_TESTDATA_DIR) / ".." / "examples" / "red-sphere.sf";
  ReadResult result = readSceneFile(path);
  EXPECT_TRUE(result.ok()) << formatDiagnostics(result.diagnostics);
  EXPECT_EQ(result.diagnostics.file(), path.string());
  EXPECT_EQ(result.scene.objects.size(), 2u);  // the sphere and its floor
}

TEST(ReadFile, AFolderOrAMissingFileIsCannotReadFile) {
  for (const fs::path& path : {fs::path(::testing::TempDir()), fs::path("/no/such/file.sf")}) {
    SourceText source = readSourceFile(path);
    EXPECT_FALSE(source.text);
    EXPECT_FALSE(source.tooLarge());
    ASSERT_EQ(source.diagnostics.items().size(), 1u) << path;
    EXPECT_EQ(source.diagnostics.items()[0].code, DiagnosticCode::CannotReadFile);
    EXPECT_EQ(source.diagnostics.items()[0].message, "cannot read the file: " + source.readError);
    EXPECT_FALSE(readSceneFile(path).ok());
  }
  EXPECT_EQ(readSourceFile(::testing::TempDir()).readError, "it is a directory");
  // The cause as the system's error, which a caller can tell apart.
  EXPECT_EQ(readSourceFile(::testing::TempDir()).readErrorCode, std::errc::is_a_directory);
  EXPECT_EQ(readSourceFile("/no/such/file.sf").readErrorCode, std::errc::no_such_file_or_directory);
  EXPECT_EQ(readFileBytes("/no/such/file.sf").code, std::errc::no_such_file_or_directory);
}

TEST(ReadFile, AFileAboveTheLimitIsRefusedByItsSize) {
  fs::path path = testing::writeTempFile("read_file_large.sf", std::string(100, '#'));
  ReadOptions options;
  options.maxFileSize = 99;
  SourceText source = readSourceFile(path, options, "shown.sf");
  EXPECT_TRUE(source.tooLarge());
  DiagnosticFormOptions brief;
  brief.form = DiagnosticForm::Short;
  EXPECT_EQ(formatDiagnostics(source.diagnostics, brief),
            "shown.sf: error: the file is 100 bytes, more than the limit of 99 "
            "[file-too-large]\n  hint: raise the limit with max-file-size=100 if the file is "
            "meant to be this large\n");
  options.maxFileSize = 100;
  EXPECT_EQ(readSourceFile(path, options).text, std::string(100, '#'));
}

TEST(ReadFile, AStreamIsReadToOneBytePastTheLimit) {
  std::istringstream in(std::string(10, 'x'));
  ReadOptions options;
  options.maxFileSize = 9;
  SourceText source = readSourceStream(in, "<stdin>", options);
  EXPECT_TRUE(source.tooLarge());
  EXPECT_EQ(source.diagnostics.file(), "<stdin>");
  std::istringstream whole("abc");
  EXPECT_EQ(readSourceStream(whole, "<stdin>").text, "abc");
}

TEST(ReadFile, QuotesTheLinesItsDiagnosticsPointAt) {
  fs::path path = testing::writeTempFile("read_file_bad.sf", "CAMERA\n0 0 nan\n");
  SourceExcerpts quotes;
  ReadResult result = readSceneFile(path, {}, &quotes);
  ASSERT_FALSE(result.ok());
  std::string text = formatDiagnostics(result.diagnostics, {}, &quotes);
  EXPECT_NE(text.find("    2 | 0 0 nan\n"), std::string::npos) << text;
}

}  // namespace
}  // namespace scene
