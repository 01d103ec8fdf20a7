#include "tools/sfrender/render_hint.h"

#include <gtest/gtest.h>

#include <string>

#include "tools/common/diagnostic_printer.h"
#include "tools/tool_test_support.h"

namespace tools {
namespace {

scene::Diagnostic cameraNote() {
  scene::Diagnostic d;
  d.severity = scene::Severity::Note;
  d.code = scene::DiagnosticCode::CameraFov;
  d.hint = "render with {0} {1} {2}";
  d.remedies = {{scene::Setting::FieldOfView, "53.13010235415598"},
                {scene::Setting::Width, "640"},
                {scene::Setting::Height, "480"}};
  return d;
}

TEST(RenderHint, LeavesOutWhatTheRenderUsesAlready) {
  render::RenderSettings settings;
  settings.verticalFovDegrees = 53.13010235415598;
  settings.width = 640;
  settings.height = 480;
  EXPECT_EQ(renderHintText(cameraNote(), settings), "");
  settings.height = 300;
  EXPECT_EQ(renderHintText(cameraNote(), settings), "render with sfrender --height 480");
  settings.verticalFovDegrees = 60;
  settings.width = 320;
  EXPECT_EQ(renderHintText(cameraNote(), settings), hintText(cameraNote()));
  EXPECT_EQ(hintText(cameraNote()),
            "render with sfrender --fov 53.13010235415598 --width 640 "
            "--height 480");
}

TEST(RenderHint, KeepsEveryOtherHint) {
  scene::Diagnostic d;
  d.hint = "raise the limit with {0} if the file is meant to be this large";
  d.remedies = {{scene::Setting::MaxFileSize, ""}};
  EXPECT_EQ(renderHintText(d, render::RenderSettings{}), hintText(d));
  d.hint = "keywords are upper case";
  d.remedies.clear();
  EXPECT_EQ(renderHintText(d, render::RenderSettings{}), "keywords are upper case");
}

// End to end: a POV-Ray camera's view is what sfrender renders, so its note
// (with -v) gives no hint to pass it; another --fov is told the camera's.
class RenderHintRun : public ToolTest {};

TEST_F(RenderHintRun, SfrenderIsNotToldToPassTheViewItUses) {
  std::string pov = write("wide.pov",
                          "camera { location <0, 2, -6> look_at <0, 0.5, 0> angle 80 right x*2 }\n"
                          "light_source { <4, 8, -6> color rgb 1 }\n"
                          "sphere { <0, 1, 0>, 1 pigment { color rgb <1, 0.3, 0.2> } }\n");
  ASSERT_EQ(run(sfrender, {"sfrender", "-v", pov, "-o", path("a.png"), "--spp", "1"}), 0)
      << err_.str();
  EXPECT_NE(err_.str().find("[camera-fov]"), std::string::npos) << err_.str();
  EXPECT_EQ(err_.str().find("hint: render with"), std::string::npos) << err_.str();
  ASSERT_EQ(
      run(sfrender, {"sfrender", "-v", pov, "-o", path("b.png"), "--spp", "1", "--fov", "30"}), 0)
      << err_.str();
  EXPECT_NE(err_.str().find("hint: render with sfrender --fov 45.52"), std::string::npos)
      << err_.str();
  EXPECT_EQ(err_.str().find("--width 640"), std::string::npos) << err_.str();
}

}  // namespace
}  // namespace tools
