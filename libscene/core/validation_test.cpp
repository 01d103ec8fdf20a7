#include "scenefile/validation.h"

#include <gtest/gtest.h>

#include <string>

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

}  // namespace
}  // namespace scene
