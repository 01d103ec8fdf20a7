#include "scenefile/validation.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <utility>

#include "libscene/testing/test_support.h"
#include "scenefile/convert.h"
#include "scenefile/format.h"
#include "scenefile/read.h"

namespace scene {
namespace {

Scene litScene() {
  Scene s;
  s.lights.emplace_back();
  return s;
}

TEST(Validation, AnOutputFileSetInMemoryMustBeANameAnInstructionFileHolds) {
  // A reader gives only names it could read; a scene built in memory (the
  // Python module's) may hold anything, which the writer would write as it is.
  Scene s = litScene();
  s.outputFile = "image-1.ppm";
  EXPECT_TRUE(validateScene(s).empty());
  for (std::string bad : {"", "a b.ppm", "tab\t.ppm", "x\nSTART CAMERA", "caf\xC3\xA9.ppm"}) {
    SCOPED_TRACE(bad);
    s.outputFile = bad;
    DiagnosticList out = validateScene(s);
    ASSERT_EQ(out.errorCount(), 1u);
    EXPECT_EQ(out.items()[0].code, DiagnosticCode::OutputFileName);
  }
  s.outputFile.reset();
  EXPECT_TRUE(validateScene(s).empty());
}

// The OUTPUT_FILE an instruction file gets from its own name reads back,
// whatever the name; the writer writes none that would not.
TEST(Validation, AnOutputFileNamedAfterItsFileIsOneTheReaderTakes) {
  const std::pair<std::string, std::string> cases[] = {
      {"out.txt", "out.ppm"},          {"dir/my scene.txt", "my_scene.ppm"},
      {"tab\t.txt", "tab_.ppm"},       {"line\nSTART CAMERA.txt", "line_START_CAMERA.ppm"},
      {"caf\xC3\xA9.txt", "caf_.ppm"}, {"\xE2\x82\xAC\x7F\xFF.txt", "___.ppm"},
      {"{stem}.txt", "{stem}.ppm"},
  };
  Scene s = litScene();
  for (const auto& [path, name] : cases) {
    SCOPED_TRACE(path);
    EXPECT_EQ(outputFileNameFor(path), name);
    ConversionOptions options;
    options.instructions.outputFile = outputFileNameFor(path);
    DiagnosticList out;
    std::optional<std::string> text = convertScene(s, Format::InstructionFile, options, out);
    ASSERT_TRUE(text);
    ReadResult back = parseSceneAs(Format::InstructionFile, *text, "back.txt");
    EXPECT_TRUE(back.ok());
    EXPECT_EQ(back.scene.outputFile, name);
  }
  for (std::string bad : {"", "a b.ppm", "tab\t.ppm", "x\nSTART CAMERA", "caf\xC3\xA9.ppm"}) {
    SCOPED_TRACE(bad);
    ConversionOptions options;
    options.instructions.outputFile = bad;
    DiagnosticList out;
    EXPECT_FALSE(convertScene(s, Format::InstructionFile, options, out));
    EXPECT_EQ(out.errorCount(), 1u);
    Scene named = s;
    named.outputFile = bad;
    DiagnosticList refused;
    EXPECT_FALSE(convertScene(named, Format::InstructionFile, {}, refused));
  }
}

// A glTF or POV-Ray file carries the OUTPUT_FILE of the instruction file it
// was written from: only a name an instruction file holds is taken back.
TEST(Validation, EveryReaderTakesOnlyAnOutputFileAnInstructionFileHolds) {
  Scene s = litScene();
  s.outputFile = "image-1.ppm";
  for (Format format : {Format::Gltf, Format::Pov}) {
    SCOPED_TRACE(formatInfo(format).name);
    DiagnosticList out;
    std::optional<std::string> text = convertScene(s, format, {}, out);
    ASSERT_TRUE(text);
    std::size_t at = text->find("image-1.ppm");
    ASSERT_NE(at, std::string::npos);
    ReadResult good = parseSceneAs(format, *text, "good");
    EXPECT_EQ(good.scene.outputFile, "image-1.ppm");
    text->replace(at, 11, "caf\xC3\xA9.ppm");
    ReadResult back = parseSceneAs(format, *text, "bad");
    if (format == Format::Gltf) {
      EXPECT_EQ(testing::withCode(back.diagnostics, DiagnosticCode::OutputFileName).size(), 1u);
    } else {
      EXPECT_TRUE(back.ok());
      EXPECT_FALSE(back.scene.outputFile);
      int told = 0;
      for (const Diagnostic& d : testing::withCode(back.diagnostics, DiagnosticCode::PovIgnored)) {
        told += d.message.find("output_file") != std::string::npos;
      }
      EXPECT_EQ(told, 1);
    }
  }
}

}  // namespace
}  // namespace scene
