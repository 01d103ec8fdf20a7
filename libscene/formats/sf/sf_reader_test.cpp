#include "libscene/formats/sf/sf_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "libscene/testing/test_support.h"

namespace scene {
namespace {

using testing::expectOne;
using testing::kCameraRecord;
using testing::kLightRecord;

const std::string kSphere = "SPHERE\n1 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";

ReadResult parse(const std::string& text, const ReadOptions& options = {}) {
  return parseSceneFile(text, "test.sf", options);
}

TEST(SceneFileReader, ReadsAValidScene) {
  ReadResult r = parse(kCameraRecord + kLightRecord + kSphere);
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r.diagnostics.empty());
  ASSERT_EQ(r.scene.lights.size(), 1u);
  ASSERT_EQ(r.scene.objects.size(), 1u);
  EXPECT_EQ(r.scene.camera.matrix[3][2], 5.0);  // row 2, column 3: the eye's z
  EXPECT_EQ(r.scene.lights[0].position(), glm::dvec3(3.0, 3.0, 3.0));
  EXPECT_EQ(r.scene.objects[0].kind, ObjectKind::Sphere);
  EXPECT_EQ(r.scene.objects[0].material.colour, glm::dvec3(1.0, 0.0, 0.0));
  EXPECT_EQ(r.scene.objects[0].material, (Material{glm::dvec3(1.0, 0.0, 0.0)}));
  EXPECT_EQ(r.scene.objects[0].span, (SourceSpan{13, 1, 6}));
  EXPECT_FALSE(r.scene.objects[0].transforms.has_value());
}

TEST(SceneFileReader, ReadsRowsIntoColumnMajorMatrices) {
  ReadResult r = parse(kCameraRecord + "CUBE\n1 1 1\n1 2 3 4\n5 6 7 8\n9 10 11.5 12\n0 0 0 1\n");
  ASSERT_TRUE(r.ok()) << r.diagnostics.items().front().message;
  const glm::dmat4& m = r.scene.objects[0].matrix;
  EXPECT_EQ(m[1][0], 2.0);  // row 0, column 1
  EXPECT_EQ(m[0][1], 5.0);  // row 1, column 0
  EXPECT_EQ(m[3][2], 12.0);
}

TEST(SceneFileReader, AcceptsCrlfBomTabsAndNoFinalNewline) {
  std::string text =
      "\xEF\xBB\xBF"
      "CAMERA\r\n0\t0 0\r\n 1 0 0 0 \r\n0 1 0 0\r\n0 0 1 5\r\n"
      "0 0 0 1\r\n\r\n" +
      kLightRecord + "PLANE\n1 1 1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1";
  ReadResult r = parse(text);
  EXPECT_TRUE(r.ok());
  EXPECT_TRUE(r.diagnostics.empty());
  EXPECT_EQ(r.scene.objects.size(), 1u);
}

TEST(SceneFileReader, EndsALineOfNumbersOnlyWhereALineEnds) {
  // A '\r' ends a line just before its '\n' or at the file's end; anywhere
  // else it is an invalid byte, however the numbers around it read.
  ReadResult last =
      parse(kCameraRecord + kLightRecord + "PLANE\n1 1 1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\r");
  EXPECT_TRUE(last.diagnostics.empty());
  ASSERT_EQ(last.scene.objects.size(), 1u);
  EXPECT_EQ(last.scene.objects[0].matrix[3][3], 1.0);
  for (std::string row : {"1 0\r0 0\n", "1 0 0 0\r\r\n", "1 0 0 0\r \n", "1 0 0 0 \r0\n"}) {
    SCOPED_TRACE(row);
    ReadResult r = parse(kCameraRecord + kLightRecord + "PLANE\n1 1 1\n" + row +
                         "0 1 0 0\n0 0 1 0\n0 0 0 1\n");
    std::size_t column = row.find('\r') + 1;
    expectOne(r.diagnostics, DiagnosticCode::InvalidByte, 15, static_cast<std::uint32_t>(column));
    EXPECT_TRUE(r.scene.objects.empty());
  }
}

TEST(SceneFileReader, StopsAtTheFirstObjectOrLightPastMaxObjects) {
  ReadOptions options;
  options.maxObjects = 2;
  // The light and the first sphere fit; the second sphere (line 19) does not.
  std::string text = kCameraRecord + kLightRecord + kSphere + kSphere + "garbage\n";
  ReadResult r = parse(text, options);
  Diagnostic d = expectOne(r.diagnostics, DiagnosticCode::TooManyObjects, 19, 1);
  EXPECT_EQ(d.message, "the file has more than 2 objects and lights: reading stops here");
  EXPECT_EQ(r.diagnostics.items().size(), 1u);  // nothing after it, not even the garbage
  EXPECT_EQ(r.scene.objects.size(), 1u);

  options.maxObjects = 3;
  EXPECT_TRUE(parse(kCameraRecord + kLightRecord + kSphere + kSphere, options).ok());
  EXPECT_TRUE(parse(kCameraRecord + kLightRecord + kSphere + kSphere).ok());  // the default
}

TEST(SceneFileReader, ColumnsCountFromTheLineNotTheBom) {
  ReadResult r = parse(
      "\xEF\xBB\xBF"
      "camera\n");
  expectOne(r.diagnostics, DiagnosticCode::UnknownKeyword, 1, 1);
}

TEST(SceneFileReader, ReportsBadNumbersAtTheirToken) {
  ReadResult r = parse(kCameraRecord + "SPHERE\n1 0 nan\n1 0 0 0\n0 1 0 1e400\n0 0 1 0\n0 0 0 1\n");
  Diagnostic d = expectOne(r.diagnostics, DiagnosticCode::InvalidNumber, 8, 5);
  EXPECT_EQ(d.span.length, 3u);
  EXPECT_EQ(d.hint, "infinity and not-a-number are not allowed");
  expectOne(r.diagnostics, DiagnosticCode::NumberOutOfRange, 10, 7);
}

TEST(SceneFileReader, ReportsTooFewAndTooManyTokens) {
  ReadResult r = parse(kCameraRecord + "SPHERE\n1 0\n1 0 0 0 9\n0 1 0 0\n0 0 1 0\n0 0 0 1\n");
  Diagnostic few = r.diagnostics.items()[0];
  EXPECT_EQ(few.code, DiagnosticCode::TokenCount);
  EXPECT_EQ(few.span, (SourceSpan{8, 4, 0}));  // just past "1 0"
  EXPECT_EQ(few.message, "the colour line takes 3 numbers, found 2");
  Diagnostic many = r.diagnostics.items()[1];
  EXPECT_EQ(many.span, (SourceSpan{9, 9, 1}));  // the fifth number
  EXPECT_EQ(r.diagnostics.errorCount(), 2u);
}

TEST(SceneFileReader, RecordNameStandsAlone) {
  ReadResult r = parse(kCameraRecord + "SPHERE 1\n1 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n");
  expectOne(r.diagnostics, DiagnosticCode::TokenCount, 7, 8);
}

TEST(SceneFileReader, SuggestsUpperCaseKeywords) {
  ReadResult r = parse(kCameraRecord + "sphere\n1 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n");
  Diagnostic d = expectOne(r.diagnostics, DiagnosticCode::UnknownKeyword, 7, 1);
  EXPECT_EQ(d.hint, "keywords are upper case: did you mean 'SPHERE'?");
  ASSERT_TRUE(d.fixIt.has_value());
  EXPECT_EQ(d.fixIt->replacement, "SPHERE");
  EXPECT_EQ(d.fixIt->span, (SourceSpan{7, 1, 6}));
}

TEST(SceneFileReader, SuggestsCloseMisspellings) {
  ReadResult r = parse(kCameraRecord + "CYLINDRE\n1 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n");
  Diagnostic d = expectOne(r.diagnostics, DiagnosticCode::UnknownKeyword, 7, 1);
  EXPECT_EQ(d.hint, "did you mean 'CYLINDER'?");
  ReadResult far = parse(kCameraRecord + "TEAPOT\n1 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n");
  EXPECT_EQ(expectOne(far.diagnostics, DiagnosticCode::UnknownKeyword, 7, 1).hint, "");
}

TEST(SceneFileReader, RejectsComments) {
  ReadResult r = parse("# a comment\n" + kCameraRecord + "// another\n" + kLightRecord);
  ASSERT_EQ(testing::withCode(r.diagnostics, DiagnosticCode::CommentNotAllowed).size(), 2u);
  EXPECT_EQ(r.diagnostics.items()[0].span, (SourceSpan{1, 1, 1}));
  EXPECT_EQ(r.diagnostics.items()[1].span, (SourceSpan{8, 1, 2}));
}

TEST(SceneFileReader, ReportsInvalidBytes) {
  std::string text = kCameraRecord + kLightRecord;
  text[kCameraRecord.size() + 2] = '\0';  // "LI\0HT"
  ReadResult r = parse(text);
  Diagnostic d = expectOne(r.diagnostics, DiagnosticCode::InvalidByte, 7, 3);
  EXPECT_EQ(d.message, "line contains a NUL byte");
  ReadResult utf8 =
      parse(kCameraRecord + "SPHERE\n1 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 \xC3\xA9\n");
  expectOne(utf8.diagnostics, DiagnosticCode::InvalidByte, 12, 7);
}

TEST(SceneFileReader, CameraMustComeFirst) {
  ReadResult r = parse(kLightRecord + kCameraRecord);
  Diagnostic d = expectOne(r.diagnostics, DiagnosticCode::CameraNotFirst, 1, 1);
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].span.line, 7u);
}

TEST(SceneFileReader, CameraIsUnique) {
  ReadResult r = parse(kCameraRecord + kLightRecord + kCameraRecord);
  Diagnostic d = expectOne(r.diagnostics, DiagnosticCode::DuplicateCamera, 13, 1);
  EXPECT_EQ(d.notes.at(0).span.line, 1u);
}

TEST(SceneFileReader, EmptyFileAndNoCamera) {
  expectOne(parse("").diagnostics, DiagnosticCode::MissingCamera, 1, 1);
  expectOne(parse("\n\n  \n").diagnostics, DiagnosticCode::MissingCamera, 1, 1);
  expectOne(parse(kLightRecord).diagnostics, DiagnosticCode::MissingCamera, 1, 1);
}

TEST(SceneFileReader, ReportsTruncatedRecordsAndGoesOn) {
  // A SPHERE cut short by the next record, then a CUBE cut short by the end.
  ReadResult r =
      parse(kCameraRecord + "SPHERE\n1 0 0\n1 0 0 0\n" + kLightRecord + "CUBE\n1 1 1\n1 0 0 0\n");
  std::vector<Diagnostic> cut = testing::withCode(r.diagnostics, DiagnosticCode::TruncatedRecord);
  ASSERT_EQ(cut.size(), 2u);
  EXPECT_EQ(cut[0].span.line, 7u);
  EXPECT_EQ(cut[0].message, "SPHERE record has 3 of its 6 lines: the next record starts");
  EXPECT_EQ(cut[1].span.line, 16u);
  EXPECT_EQ(cut[1].message, "CUBE record has 3 of its 6 lines: the file ends");
  EXPECT_EQ(r.scene.lights.size(), 1u);  // the record after the cut was read
}

TEST(SceneFileReader, BlankLineInsideARecord) {
  ReadResult r = parse(kCameraRecord + "SPHERE\n1 0 0\n\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n");
  Diagnostic d = expectOne(r.diagnostics, DiagnosticCode::BlankLineInRecord, 9, 1);
  EXPECT_EQ(d.notes.at(0).span.line, 7u);
  EXPECT_EQ(r.diagnostics.errorCount(), 1u);
}

TEST(SceneFileReader, StrayNumbersAreReportedOnce) {
  ReadResult r = parse(kCameraRecord + "1 2 3\n4 5 6\n" + kLightRecord);
  expectOne(r.diagnostics, DiagnosticCode::ExpectedRecordName, 7, 1);
  EXPECT_EQ(r.scene.lights.size(), 1u);
}

TEST(SceneFileReader, FourthRowMustBe0001) {
  ReadResult r = parse(kCameraRecord + "SPHERE\n1 1 1\n1 0 0 2\n0 1 0 0\n0 0 1 0\n0 0 1 1\n");
  Diagnostic d = expectOne(r.diagnostics, DiagnosticCode::MatrixLastRow, 12, 5);
  EXPECT_EQ(d.hint, "");
}

TEST(SceneFileReader, HintsAtTransposedMatrices) {
  ReadResult r = parse(kCameraRecord + "SPHERE\n1 1 1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n2 3 4 1\n");
  Diagnostic d = expectOne(r.diagnostics, DiagnosticCode::MatrixLastRow, 12, 1);
  EXPECT_NE(d.hint.find("'{0}' repairs such files"), std::string::npos);
  EXPECT_EQ(d.remedies, (std::vector<Remedy>{{Setting::TransposedMatrices, "true"}}));
  // The repair: read the same file column by column (the camera too).
  ReadOptions transposed;
  transposed.sceneFile.transposedMatrices = true;
  ReadResult repaired = parse("CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 5 1\n" + kLightRecord +
                                  "SPHERE\n1 1 1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n2 3 4 1\n",
                              transposed);
  ASSERT_FALSE(repaired.ok());  // the light was written row by row
  ReadResult all = parse(
      "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 5 1\n"
      "SPHERE\n1 1 1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n2 3 4 1\n",
      transposed);
  ASSERT_TRUE(all.ok());
  EXPECT_EQ(glm::dvec3(all.scene.objects[0].matrix[3]), glm::dvec3(2, 3, 4));
  EXPECT_EQ(glm::dvec3(all.scene.camera.matrix[3]), glm::dvec3(0, 0, 5));
}

TEST(SceneFileReader, RejectsSingularAndIllConditionedMatrices) {
  ReadResult singular = parse(kCameraRecord + "CUBE\n1 1 1\n1 0 0 0\n0 0 0 0\n0 0 1 0\n0 0 0 1\n");
  expectOne(singular.diagnostics, DiagnosticCode::MatrixSingular, 7, 1);
  ReadResult rankTwo = parse(kCameraRecord + "CUBE\n1 1 1\n1 2 3 0\n2 4 6 0\n0 0 1 0\n0 0 0 1\n");
  expectOne(rankTwo.diagnostics, DiagnosticCode::MatrixSingular, 7, 1);
  ReadResult thin = parse(kCameraRecord + "CUBE\n1 1 1\n1e-7 0 0 0\n0 1e6 0 0\n0 0 1 0\n0 0 0 1\n");
  expectOne(thin.diagnostics, DiagnosticCode::MatrixIllConditioned, 7, 1);
  ReadResult fine = parse(kCameraRecord + "CUBE\n1 1 1\n1e-6 0 0 0\n0 1e5 0 0\n0 0 1 0\n0 0 0 1\n");
  EXPECT_TRUE(testing::withCode(fine.diagnostics, DiagnosticCode::MatrixIllConditioned).empty());
  ReadResult huge =
      parse(kCameraRecord + "CUBE\n1 1 1\n1e200 0 0 0\n0 1e200 0 0\n0 0 1e200 0\n0 0 0 1\n");
  expectOne(huge.diagnostics, DiagnosticCode::MatrixSingular, 7, 1);
}

TEST(SceneFileReader, AllowsMirrors) {
  ReadResult r =
      parse(kCameraRecord + kLightRecord + "SPHERE\n1 1 1\n-1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n");
  EXPECT_TRUE(r.ok());
  EXPECT_TRUE(r.diagnostics.empty());
}

TEST(SceneFileReader, ChecksColours) {
  ReadResult r = parse(kCameraRecord + kLightRecord +
                       "SPHERE\n1 -0.5 2\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n"
                       "LIGHT\n5 5 5\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n");
  expectOne(r.diagnostics, DiagnosticCode::NegativeColour, 14, 3);
  expectOne(r.diagnostics, DiagnosticCode::ColourAboveOne, 14, 8, Severity::Warning);
  // -0 is black, and a camera's colour is not checked at all.
  ReadResult zero = parse("CAMERA\n-7 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 5\n0 0 0 1\n" + kLightRecord +
                          "CUBE\n-0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n");
  EXPECT_TRUE(zero.diagnostics.empty());
}

TEST(SceneFileReader, PointsAtValuesWhateverTheBlanksAndLiterals) {
  // Tabs, runs of spaces, blanks at both ends, CRLF, and literals that the
  // quick paths of the reader decline (long ones, exponents).
  ReadResult r = parse(kCameraRecord + kLightRecord +
                       "SPHERE\r\n\t1  -0.5\t 2 \r\n1.0000000000000000001 0 0 0\r\n"
                       "0 1e0 0 0\n0 0 +1 0\n0\t0   1.000000000000001e0 1");
  Diagnostic negative = expectOne(r.diagnostics, DiagnosticCode::NegativeColour, 14, 5);
  EXPECT_EQ(negative.span.length, 4u);
  Diagnostic above =
      expectOne(r.diagnostics, DiagnosticCode::ColourAboveOne, 14, 11, Severity::Warning);
  EXPECT_EQ(above.span.length, 1u);
  Diagnostic lastRow = expectOne(r.diagnostics, DiagnosticCode::MatrixLastRow, 18, 7);
  EXPECT_EQ(lastRow.span.length, 19u);
}

TEST(SceneFileReader, ChecksTheCamera) {
  ReadResult parallel = parse("CAMERA\n0 0 0\n1 0 0 0\n0 0 1 0\n0 0 1 0\n0 0 0 1\n");
  expectOne(parallel.diagnostics, DiagnosticCode::CameraDegenerate, 1, 1);
  ReadResult zero = parse("CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 0 0\n0 0 0 1\n");
  expectOne(zero.diagnostics, DiagnosticCode::CameraDegenerate, 1, 1);
  ReadResult scaled = parse("CAMERA\n0 0 0\n2 0 0 0\n0 2 0 0\n0 0 2 0\n0 0 0 1\n" + kLightRecord);
  expectOne(scaled.diagnostics, DiagnosticCode::CameraScaled, 1, 1, Severity::Warning);
  EXPECT_TRUE(scaled.ok());
}

TEST(SceneFileReader, WarnsWhenNothingIsLit) {
  ReadResult r = parse(kCameraRecord + kSphere);
  EXPECT_TRUE(r.ok());
  expectOne(r.diagnostics, DiagnosticCode::NoLight, 1, 1, Severity::Warning);
}

TEST(SceneFileReader, ReportsEveryProblemNotOnlyTheFirst) {
  std::string text = kCameraRecord;
  for (int i = 0; i < 5; ++i) text += "SPHERE\n1 0 x\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
  ReadResult r = parse(text);
  EXPECT_EQ(testing::withCode(r.diagnostics, DiagnosticCode::InvalidNumber).size(), 5u);
}

TEST(SceneFileReader, StopsAfterTheErrorLimit) {
  std::string text;
  for (int i = 0; i < 5000; ++i) text += "1 2 3\nFOO\n";
  ReadOptions options;
  options.errorLimit = 100;
  ReadResult r = parse(text, options);
  EXPECT_EQ(r.diagnostics.errorCount(), 100u);
  EXPECT_EQ(r.diagnostics.items().back().code, DiagnosticCode::TooManyErrors);
}

TEST(SceneFileReader, KeepsALongLineCheap) {
  // Ten million tokens on one line: counted, not stored.
  std::string line;
  line.reserve(20'000'000);
  for (int i = 0; i < 10'000'000; ++i) line += "1 ";
  ReadResult r = parse(kCameraRecord + "SPHERE\n" + line + "\n");
  Diagnostic d = r.diagnostics.items().at(0);
  EXPECT_EQ(d.code, DiagnosticCode::TokenCount);
  EXPECT_EQ(d.message, "the colour line takes 3 numbers, found 10000000");
}

}  // namespace
}  // namespace scene
