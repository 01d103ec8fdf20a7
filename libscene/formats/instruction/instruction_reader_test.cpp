#include "libscene/formats/instruction/instruction_reader.h"

#include <gtest/gtest.h>

#include <string>

#include "libscene/testing/test_support.h"
#include "scenefile/transform.h"

namespace scene {
namespace {

using testing::expectOne;
using testing::withCode;

const std::string kHeader = "OUTPUT_FILE out.ppm\n";
const std::string kCamera = "START CAMERA\n  LOCATION 0 0 5\n  LOOK_AT 0 0 0\nEND CAMERA\n";
const std::string kLight = "START LIGHT\n  LOCATION 3 3 3\n  COLOUR 1 1 1\nEND LIGHT\n";

ReadResult parse(const std::string& text) { return parseInstructionFile(text, "test.txt"); }

TEST(InstructionReader, StopsAtTheFirstObjectOrLightPastMaxObjects) {
  const std::string sphere = "START OBJECT SPHERE\nEND OBJECT\n";
  // Lines 1-5 header and camera, 6-9 the light, 10-11 a sphere, 12 the next.
  std::string text = kHeader + kCamera + kLight + sphere + sphere + "START CAMERA\n";
  ReadOptions options;
  options.maxObjects = 2;
  ReadResult r = parseInstructionFile(text, "test.txt", options);
  Diagnostic d = expectOne(r.diagnostics, DiagnosticCode::TooManyObjects, 12, 1);
  EXPECT_EQ(d.message, "the file has more than 2 objects and lights: reading stops here");
  EXPECT_EQ(r.diagnostics.items().size(), 1u);  // no unclosed block, no second camera
  EXPECT_EQ(r.scene.objects.size(), 1u);
  EXPECT_EQ(r.scene.lights.size(), 1u);

  options.maxObjects = 3;
  EXPECT_TRUE(
      parseInstructionFile(kHeader + kCamera + kLight + sphere + sphere, "test.txt", options).ok());
}

TEST(InstructionReader, ReadsTheManualsExample) {
  ReadResult r = parse(kHeader + kCamera + kLight +
                       "START OBJECT CUBE\n"
                       "  START MATERIAL\n    COLOUR 0.0 0.0 1.0\n    AMBIENT 0.15\n"
                       "    DIFFUSE 0.5\n    SPECULAR 0.8\n    SHININESS 4000.0\n"
                       "    REFLECTIVITY 0.6\n    TRANSPARENCY 0.0\n    RI 1.0\n  END MATERIAL\n"
                       "  START TRANSFORMATION\n    SCALE 0.5 0.5 0.5\n    TRANSLATE 1.0 0.5 1.0\n"
                       "    ROTATE_X 1.57079632679\n    ROTATE_Y 1.57079632679\n"
                       "    ROTATE_Z 1.57079632679\n  END TRANSFORMATION\nEND OBJECT\n");
  ASSERT_TRUE(r.ok()) << r.diagnostics.items().at(0).message;
  EXPECT_TRUE(r.diagnostics.empty());
  EXPECT_EQ(r.scene.outputFile, "out.ppm");
  ASSERT_EQ(r.scene.objects.size(), 1u);
  const Object& cube = r.scene.objects[0];
  EXPECT_EQ(cube.kind, ObjectKind::Cube);
  EXPECT_EQ(cube.material.colour, glm::dvec3(0, 0, 1));
  EXPECT_EQ(cube.material.ambient, 0.15);
  EXPECT_EQ(cube.material.shininess, 4000.0);
  EXPECT_EQ(cube.material.reflectivity, 0.6);
  ASSERT_TRUE(cube.transforms.has_value());
  ASSERT_EQ(cube.transforms->size(), 5u);
  EXPECT_EQ((*cube.transforms)[1].kind, TransformKind::Translate);
  EXPECT_EQ(cube.matrix, composeTransform(*cube.transforms));
  // The eye, forward and up of the camera.
  EXPECT_EQ(glm::dvec3(r.scene.camera.matrix[3]), glm::dvec3(0, 0, 5));
  EXPECT_EQ(glm::dvec3(r.scene.camera.matrix[2]), glm::dvec3(0, 0, 1));
  EXPECT_EQ(r.scene.camera.lookAt, glm::dvec3(0, 0, 0));
}

TEST(InstructionReader, DefaultsAndAnyOrder) {
  ReadResult r = parse("\n\n" + kHeader + kLight + "START OBJECT SPHERE\nEND OBJECT\n" +
                       "START CAMERA\n  LOOK_AT 0 0 0\n  LOCATION 0 0 5\nEND CAMERA\n" +
                       "START OBJECT PLANE\n START TRANSFORMATION\n END TRANSFORMATION\n"
                       " START MATERIAL\n  RI 1.5\n END MATERIAL\nEND OBJECT\n");
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.scene.objects.size(), 2u);
  EXPECT_EQ(r.scene.objects[0].material, Material{});
  EXPECT_EQ(r.scene.objects[0].matrix, glm::dmat4(1.0));
  EXPECT_EQ(r.scene.objects[1].material.ri, 1.5);
  EXPECT_EQ(r.scene.objects[1].material.colour, glm::dvec3(1.0));
}

TEST(InstructionReader, NeedsOutputFileFirst) {
  ReadResult r = parse(kCamera + kLight);
  expectOne(r.diagnostics, DiagnosticCode::MissingOutputFile, 1, 1);
  EXPECT_EQ(r.diagnostics.errorCount(), 1u);  // the blocks are still read
  expectOne(parse("").diagnostics, DiagnosticCode::MissingOutputFile, 1, 1);
}

TEST(InstructionReader, OutputFileTakesOneName) {
  expectOne(parse("OUTPUT_FILE\n" + kCamera).diagnostics, DiagnosticCode::OutputFileName, 1, 12);
  expectOne(parse("OUTPUT_FILE a b\n" + kCamera).diagnostics, DiagnosticCode::OutputFileName, 1,
            15);
  Diagnostic again = expectOne(parse(kHeader + kCamera + "OUTPUT_FILE x\n").diagnostics,
                               DiagnosticCode::UnexpectedLine, 6, 1);
  EXPECT_EQ(again.notes.at(0).span.line, 1u);
}

TEST(InstructionReader, NamesTheOpenBlockAtTheEndOfTheFile) {
  ReadResult r = parse(kHeader + kCamera + "START OBJECT SPHERE\n  START MATERIAL\n  COLOUR 1 0 0\n");
  std::vector<Diagnostic> open = withCode(r.diagnostics, DiagnosticCode::UnclosedBlock);
  ASSERT_EQ(open.size(), 2u);
  EXPECT_EQ(open[0].message, "the file ends inside the MATERIAL block opened at line 7");
  EXPECT_EQ(open[0].notes.at(0).span.line, 7u);
  EXPECT_EQ(open[1].message, "the file ends inside the OBJECT block opened at line 6");
}

TEST(InstructionReader, ClosesABlockThatLacksItsEnd) {
  // The CAMERA lacks END CAMERA; the LIGHT after it is read all the same.
  ReadResult r = parse(kHeader + "START CAMERA\n  LOCATION 0 0 5\n  LOOK_AT 0 0 0\n" + kLight);
  Diagnostic d = expectOne(r.diagnostics, DiagnosticCode::UnclosedBlock, 5, 1);
  EXPECT_EQ(d.message, "the CAMERA block opened at line 2 is not closed before START LIGHT");
  EXPECT_EQ(r.scene.lights.size(), 1u);
}

TEST(InstructionReader, MismatchedAndStrayEnds) {
  ReadResult r = parse(kHeader + "START CAMERA\n  LOCATION 0 0 5\n  LOOK_AT 0 0 0\nEND LIGHT\n"
                                 "END CAMERA\nEND OBJECT\n" + kLight);
  Diagnostic mismatch = expectOne(r.diagnostics, DiagnosticCode::MismatchedEnd, 5, 1);
  EXPECT_EQ(mismatch.notes.at(0).span.line, 2u);
  expectOne(r.diagnostics, DiagnosticCode::UnexpectedEnd, 7, 1);
}

TEST(InstructionReader, DuplicateAndMissingProperties) {
  ReadResult r = parse(kHeader + "START CAMERA\n  LOCATION 0 0 5\n  LOCATION 0 0 6\nEND CAMERA\n" +
                       "START LIGHT\n  COLOUR 1 1 1\nEND LIGHT\n");
  Diagnostic twice = expectOne(r.diagnostics, DiagnosticCode::DuplicateProperty, 4, 3);
  EXPECT_EQ(twice.notes.at(0).span, (SourceSpan{3, 3, 8}));
  std::vector<Diagnostic> missing = withCode(r.diagnostics, DiagnosticCode::MissingProperty);
  ASSERT_EQ(missing.size(), 2u);
  EXPECT_EQ(missing[0].message, "CAMERA block has no LOOK_AT");
  EXPECT_EQ(missing[0].span.line, 2u);
  EXPECT_EQ(missing[1].message, "LIGHT block has no LOCATION");
}

TEST(InstructionReader, CameraMustLookSomewhere) {
  ReadResult r = parse(kHeader + "START CAMERA\n  LOCATION 1 2 3\n  LOOK_AT 1 2 3\nEND CAMERA\n");
  expectOne(r.diagnostics, DiagnosticCode::CameraLookAtLocation, 4, 3);
}

TEST(InstructionReader, CameraLookingStraightDownHasMinusZUp) {
  ReadResult r = parse(kHeader + "START CAMERA\n  LOCATION 0 10 0\n  LOOK_AT 0 0 0\nEND CAMERA\n" +
                       kLight);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(glm::dvec3(r.scene.camera.matrix[1]), glm::dvec3(0, 0, -1));
  EXPECT_EQ(glm::dvec3(r.scene.camera.matrix[0]), glm::dvec3(1, 0, 0));
}

TEST(InstructionReader, OneCameraOnly) {
  ReadResult r = parse(kHeader + kCamera + kCamera);
  expectOne(r.diagnostics, DiagnosticCode::DuplicateCamera, 6, 1);
  expectOne(parse(kHeader + kLight).diagnostics, DiagnosticCode::MissingCamera, 5, 10);
}

TEST(InstructionReader, SectionsAtMostOnce) {
  ReadResult r = parse(kHeader + kCamera +
                       "START OBJECT CUBE\nSTART MATERIAL\nEND MATERIAL\nSTART MATERIAL\n"
                       "END MATERIAL\nEND OBJECT\n");
  expectOne(r.diagnostics, DiagnosticCode::DuplicateSection, 9, 7);
}

TEST(InstructionReader, UnknownKindsAndBlocks) {
  ReadResult kind = parse(kHeader + kCamera + "START OBJECT SPHRE\nEND OBJECT\n");
  Diagnostic d = expectOne(kind.diagnostics, DiagnosticCode::UnknownObjectKind, 6, 14);
  EXPECT_EQ(d.hint, "did you mean 'SPHERE'?");
  ReadResult block = parse(kHeader + kCamera + "START TEAPOT\n  SPOUT 1\nEND TEAPOT\n" + kLight);
  expectOne(block.diagnostics, DiagnosticCode::UnknownKeyword, 6, 7);
  EXPECT_EQ(block.diagnostics.errorCount(), 1u);  // its lines are skipped
  EXPECT_EQ(block.scene.lights.size(), 1u);
}

TEST(InstructionReader, PropertiesBelongToTheirBlocks) {
  ReadResult r = parse(kHeader + "LOCATION 1 2 3\n" +
                       "START CAMERA\n  COLOUR 1 1 1\n  LOCATION 0 0 5\n  LOOK_AT 0 0 0\nEND CAMERA\n" +
                       "START LIGHT\n  LOCATON 1 1 1\nEND LIGHT\n");
  std::vector<Diagnostic> unknown = withCode(r.diagnostics, DiagnosticCode::UnknownKeyword);
  ASSERT_EQ(unknown.size(), 1u);
  EXPECT_EQ(unknown[0].span, (SourceSpan{9, 3, 7}));
  EXPECT_EQ(unknown[0].hint, "did you mean 'LOCATION'?");
  std::vector<Diagnostic> misplaced = withCode(r.diagnostics, DiagnosticCode::UnexpectedLine);
  ASSERT_EQ(misplaced.size(), 2u);
  EXPECT_EQ(misplaced[0].span, (SourceSpan{2, 1, 8}));
  EXPECT_EQ(misplaced[0].message, "LOCATION must stand inside a block");
  EXPECT_EQ(misplaced[1].span, (SourceSpan{4, 3, 6}));
  EXPECT_EQ(misplaced[1].message, "COLOUR does not belong in a CAMERA block");
}

TEST(InstructionReader, MaterialRanges) {
  ReadResult r = parse(kHeader + kCamera + kLight +
                       "START OBJECT SPHERE\n START MATERIAL\n  AMBIENT 1.5\n  DIFFUSE -0.1\n"
                       "  SPECULAR 2\n  REFLECTIVITY 7\n  TRANSPARENCY -1\n  SHININESS 0\n"
                       "  RI 0\n  COLOUR 1 -1 1\n END MATERIAL\nEND OBJECT\n"
                       "START OBJECT SPHERE\n START MATERIAL\n  RI 0.5\n END MATERIAL\nEND OBJECT\n");
  std::vector<Diagnostic> range = withCode(r.diagnostics, DiagnosticCode::ValueOutOfRange);
  ASSERT_EQ(range.size(), 7u);
  EXPECT_EQ(range[0].span, (SourceSpan{12, 11, 3}));
  EXPECT_EQ(range[0].message, "AMBIENT must lie in [0, 1], not 1.5");
  EXPECT_EQ(range[5].message, "SHININESS must be above 0, not 0");
  EXPECT_EQ(range[6].message, "RI must be above 0, not 0");
  expectOne(r.diagnostics, DiagnosticCode::NegativeColour, 19, 12);
  expectOne(r.diagnostics, DiagnosticCode::RiBelowOne, 24, 6, Severity::Warning);
}

TEST(InstructionReader, ZeroScaleAndSingularResults) {
  ReadResult r = parse(kHeader + kCamera +
                       "START OBJECT CUBE\n START TRANSFORMATION\n  SCALE 1 0 -0\n"
                       " END TRANSFORMATION\nEND OBJECT\n"
                       "START OBJECT CUBE\n START TRANSFORMATION\n  SCALE 1e-7 1 1\n"
                       "  SCALE 1 1e6 1\n END TRANSFORMATION\nEND OBJECT\n");
  EXPECT_EQ(withCode(r.diagnostics, DiagnosticCode::ZeroScale).size(), 2u);
  EXPECT_EQ(r.diagnostics.items()[0].span, (SourceSpan{8, 11, 1}));
  expectOne(r.diagnostics, DiagnosticCode::MatrixIllConditioned, 12, 2);
}

TEST(InstructionReader, NegativeScaleIsAMirror) {
  ReadResult r = parse(kHeader + kCamera + kLight +
                       "START OBJECT CUBE\n START TRANSFORMATION\n  SCALE -1 2 3\n"
                       " END TRANSFORMATION\nEND OBJECT\n");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.scene.objects[0].matrix[0][0], -1.0);
}

TEST(InstructionReader, NumbersOnPropertyLines) {
  ReadResult r = parse(kHeader + "START CAMERA\n  LOCATION 0 0\n  LOOK_AT 0 0 0 0\nEND CAMERA\n" +
                       "START LIGHT\n  LOCATION 1,5 0 0\n  COLOUR 1 1 1\nEND LIGHT\n");
  expectOne(r.diagnostics, DiagnosticCode::InvalidNumber, 7, 12);
  std::vector<Diagnostic> counts = withCode(r.diagnostics, DiagnosticCode::TokenCount);
  ASSERT_EQ(counts.size(), 2u);
  EXPECT_EQ(counts[0].span, (SourceSpan{3, 15, 0}));
  EXPECT_EQ(counts[0].message, "LOCATION takes 3 numbers, found 2");
  EXPECT_EQ(counts[1].span, (SourceSpan{4, 17, 1}));
}

TEST(InstructionReader, CrlfAndBom) {
  std::string text = "\xEF\xBB\xBFOUTPUT_FILE a.ppm\r\nSTART CAMERA\r\nLOCATION 0 0 5\r\n"
                     "LOOK_AT 0 0 0\r\nEND CAMERA\r\n" + kLight;
  ReadResult r = parse(text);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.scene.outputFile, "a.ppm");
}

TEST(InstructionReader, ManyUnterminatedBlocksCostNoDepth) {
  std::string text = kHeader;
  for (int i = 0; i < 100000; ++i) text += "START OBJECT SPHERE\n START MATERIAL\n";
  ReadResult r = parse(text);
  EXPECT_TRUE(r.diagnostics.full());
  EXPECT_EQ(r.diagnostics.items().back().code, DiagnosticCode::TooManyErrors);
}

}  // namespace
}  // namespace scene
