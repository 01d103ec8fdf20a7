// The builder's logic without a window: key presses and mouse events on a
// BuilderState, saving into a fake file system.
#include "tools/sfbuild/builder_state.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <numbers>
#include <string_view>

#include "libscene/formats/sf/sf_writer.h"
#include "renderer/camera.h"
#include "renderer/render.h"
#include "scenefile/read.h"
#include "scenefile/transform.h"
#include "tools/sfbuild/placement.h"

namespace sfbuild {
namespace {

struct FakeFiles {
  std::map<std::string, std::string> files;
  FileSystem fs() {
    return {[this](const std::string& n) { return files.count(n) != 0; },
            [this](const std::string& n, const std::string& c) -> tools::MaybeFailure {
              files[n] = c;
              return std::nullopt;
            },
            [this](const std::string& n) -> tools::Outcome<std::string> {
              if (files.count(n) == 0) {
                return tools::fileFailure(tools::ExitCode::IoError, n, "no such file");
              }
              return files[n];
            }};
  }
};

void press(BuilderState& state, std::string_view keys, FakeFiles& files) {
  for (char c : keys) {
    int key = c == '\n'     ? static_cast<int>(kKeyEnter)
              : c == '\x1b' ? static_cast<int>(kKeyEscape)
                            : c;
    handleKey(state, key, files.fs());
  }
}

TEST(BuilderState, OpensOnAnEmptySceneWithACamera) {
  BuilderState state = initialState(640, 480);
  EXPECT_TRUE(state.scene.objects.empty());
  EXPECT_TRUE(state.scene.lights.empty());
  EXPECT_FALSE(state.selection);
  EXPECT_EQ(glm::dvec3(state.scene.camera.matrix[3]), glm::dvec3(0, 3, 8));
}

TEST(BuilderState, NumberKeysCreateRedObjectsRestingOnTheGroundSelected) {
  FakeFiles files;
  BuilderState state = initialState(640, 480);
  press(state, "1234", files);
  ASSERT_EQ(state.scene.objects.size(), 4u);
  const scene::ObjectKind kinds[] = {scene::ObjectKind::Plane, scene::ObjectKind::Cube,
                                     scene::ObjectKind::Sphere, scene::ObjectKind::Cylinder};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(state.scene.objects[i].kind, kinds[i]);
    EXPECT_EQ(state.scene.objects[i].material.colour, glm::dvec3(1, 0, 0));
  }
  // The start camera looks at the origin: each object stands there on y = 0,
  // the plane is the ground itself.
  EXPECT_EQ(state.scene.objects[0].matrix, glm::dmat4(1.0));
  glm::dmat4 resting(1.0);
  resting[3] = {0, 1, 0, 1};
  for (std::size_t i = 1; i < 4; ++i) EXPECT_EQ(state.scene.objects[i].matrix, resting);
  EXPECT_EQ(state.selection, (Selection{false, 3}));
  press(state, "L", files);
  ASSERT_EQ(state.scene.lights.size(), 1u);
  EXPECT_EQ(state.selection, (Selection{true, 0}));
}

TEST(BuilderState, TypedAmountsMoveRotateAndScaleAlongTheObjectsOwnAxes) {
  FakeFiles files;
  BuilderState state = initialState(640, 480);
  press(state, "3GX1.5\n", files);
  glm::dmat4 expected(1.0);
  expected[3] = {1.5, 1, 0, 1};
  EXPECT_EQ(state.scene.objects[0].matrix, expected);
  EXPECT_EQ(state.operation, Operation::None);
  // Turned 90 degrees about its own Z, its own X points along world +Y.
  press(state, "RZ90\nGX2\n", files);
  glm::dvec3 position(state.scene.objects[0].matrix[3]);
  EXPECT_NEAR(position.x, 1.5, 1e-12);
  EXPECT_NEAR(position.y, 3.0, 1e-12);
  // Scaling along its own X stretches it along world Y.
  press(state, "SX3\n", files);
  glm::dvec3 column0(state.scene.objects[0].matrix[0]);
  EXPECT_NEAR(column0.y, 3.0, 1e-12);
  EXPECT_NEAR(column0.x, 0.0, 1e-12);
  // S alone scales every axis.
  press(state, "2S0.5\n", files);
  expected = glm::dmat4(1.0);
  for (int k = 0; k < 3; ++k) expected[k][k] = 0.5;
  expected[3] = {0, 1, 0, 1};
  EXPECT_EQ(state.scene.objects[1].matrix, expected);
}

TEST(BuilderState, EscapeAndRightClickCancel) {
  FakeFiles files;
  BuilderState state = initialState(640, 480);
  glm::dmat4 resting(1.0);
  resting[3] = {0, 1, 0, 1};
  press(state, "2GY4\x1b", files);
  EXPECT_EQ(state.scene.objects[0].matrix, resting);
  press(state, "RX30", files);
  EXPECT_NE(state.scene.objects[0].matrix, resting);
  handleMouseButton(state, MouseButton::Right, true, 10, 10);
  EXPECT_EQ(state.scene.objects[0].matrix, resting);
  EXPECT_EQ(state.operation, Operation::None);
  EXPECT_FALSE(state.looking);
  // A scale by 0 cannot be confirmed.
  press(state, "S0\n", files);
  EXPECT_EQ(state.operation, Operation::Scale);
  press(state, "\x1b", files);
  EXPECT_EQ(state.scene.objects[0].matrix, resting);
}

TEST(BuilderState, TheAmountFollowsTheMouseAndALeftClickConfirms) {
  FakeFiles files;
  BuilderState state = initialState(640, 480);
  handleMouseMove(state, 100, 100);
  press(state, "3GX", files);
  handleMouseMove(state, 150, 120);
  EXPECT_NEAR(state.scene.objects[0].matrix[3].x, 0.5, 1e-12);
  EXPECT_EQ(windowTitle(state), "sfbuild | move X 0.5 units | SPHERE 1 | H: keys");
  handleMouseButton(state, MouseButton::Left, true, 200, 120);
  EXPECT_NEAR(state.scene.objects[0].matrix[3].x, 1.0, 1e-12);
  EXPECT_EQ(state.operation, Operation::None);
}

TEST(BuilderState, DeleteAndColour) {
  FakeFiles files;
  BuilderState state = initialState(640, 480);
  press(state, "23", files);
  press(state, "B", files);
  EXPECT_EQ(state.scene.objects[1].material.colour, glm::dvec3(0, 1, 0));
  press(state, "N", files);
  EXPECT_EQ(state.scene.objects[1].material.colour, glm::dvec3(0, 0, 1));
  press(state, "M", files);
  EXPECT_EQ(state.scene.objects[1].material.colour, glm::dvec3(0.5, 0, 0.5));
  press(state, "V", files);
  EXPECT_EQ(state.scene.objects[1].material.colour, glm::dvec3(1, 0, 0));
  press(state, "X", files);
  ASSERT_EQ(state.scene.objects.size(), 1u);
  EXPECT_EQ(state.scene.objects[0].kind, scene::ObjectKind::Cube);
  EXPECT_FALSE(state.selection);
}

TEST(BuilderState, SavesNumberedFilesAndNeverOverwrites) {
  FakeFiles files;
  files.files["Scene2.sf"] = "someone else's";
  BuilderState state = initialState(640, 480);
  press(state, "3L", files);
  press(state, "P", files);
  ASSERT_TRUE(files.files.count("Scene1.sf"));
  press(state, "P", files);
  EXPECT_EQ(files.files["Scene2.sf"], "someone else's");
  ASSERT_TRUE(files.files.count("Scene3.sf"));
  EXPECT_EQ(files.files["Scene1.sf"], files.files["Scene3.sf"]);
  EXPECT_EQ(state.lastSave, "saved Scene3.sf");
  EXPECT_NE(windowTitle(state).find("saved Scene3.sf"), std::string::npos);
  EXPECT_NE(windowTitle(state).find("H: keys"), std::string::npos);
  press(state, "H", files);
  EXPECT_TRUE(state.showHelp);
  EXPECT_EQ(windowTitle(state).find("H: keys"), std::string::npos);

  // The file is the builder's scene, camera included; opened and saved again
  // it is the same, byte for byte.
  scene::ReadResult read = scene::parseScene(files.files["Scene1.sf"], "Scene1.sf");
  ASSERT_TRUE(read.ok());
  EXPECT_EQ(read.scene.camera.matrix, state.scene.camera.matrix);
  EXPECT_EQ(read.scene.lights.size(), 1u);
  EXPECT_EQ(read.scene.objects.size(), 1u);
  FakeFiles again;
  BuilderState reopened = stateForScene(read.scene, 640, 480);
  press(reopened, "P", again);
  EXPECT_EQ(again.files["Scene1.sf"], files.files["Scene1.sf"]);
}

TEST(BuilderState, ClicksPickWithTheRenderersIntersection) {
  FakeFiles files;
  BuilderState state = initialState(640, 480);
  press(state, "3GX-2\nLGX2\nGY-3\n", files);
  state.selection.reset();
  // Project the centres with the builder's matrices, and click there.
  auto pixelOf = [&](const glm::dvec3& p) {
    glm::dvec4 clip = projectionMatrix(state, 0.05, 100) * viewMatrix(state) * glm::dvec4(p, 1);
    glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    return glm::dvec2((ndc.x + 1) / 2 * state.width, (1 - ndc.y) / 2 * state.height);
  };
  glm::dvec2 sphere = pixelOf({-2, 1, 0});
  handleMouseButton(state, MouseButton::Left, true, sphere.x, sphere.y);
  EXPECT_EQ(state.selection, (Selection{false, 0}));
  glm::dvec2 light = pixelOf({0, 1, 0});
  handleMouseButton(state, MouseButton::Left, true, light.x, light.y);
  EXPECT_EQ(state.selection, (Selection{true, 0}));
  handleMouseButton(state, MouseButton::Left, true, 5, 5);
  EXPECT_FALSE(state.selection);
}

TEST(BuilderState, TheProjectionIsTheRenderersPinholeCamera) {
  BuilderState state = initialState(800, 600);
  handleMouseMove(state, 0, 0);
  state.looking = true;
  handleMouseMove(state, 37, -21);  // some turn, so that nothing lines up by chance
  state.looking = false;
  render::RenderSettings settings;
  settings.width = state.width;
  settings.height = state.height;
  settings.verticalFovDegrees = kVerticalFovDegrees;
  render::PinholeCamera camera(state.scene.camera, settings);
  glm::dmat4 vp = projectionMatrix(state, 0.05, 100) * viewMatrix(state);
  for (double x : {0.5, 100.5, 399.5, 799.5}) {
    for (double y : {0.5, 300.5, 599.5}) {
      render::Ray ray = camera.rayThrough(x, y);
      glm::dvec4 clip = vp * glm::dvec4(ray.origin + 7.0 * ray.direction, 1.0);
      glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
      EXPECT_NEAR((ndc.x + 1) / 2 * state.width, x, 1e-9);
      EXPECT_NEAR((1 - ndc.y) / 2 * state.height, y, 1e-9);
    }
  }
}

TEST(BuilderState, CameraMovesWithTheMouseAndWheel) {
  BuilderState state = initialState(640, 480);
  glm::dmat4 before = state.scene.camera.matrix;
  handleScroll(state, 2);
  glm::dvec3 moved = glm::dvec3(state.scene.camera.matrix[3]) - glm::dvec3(before[3]);
  EXPECT_NEAR(glm::length(moved), 1.0, 1e-12);
  EXPECT_GT(glm::dot(moved, -glm::dvec3(before[2])), 0.99);
  handleMouseButton(state, MouseButton::Middle, true, 10, 10);
  handleMouseMove(state, 30, 10);
  handleMouseButton(state, MouseButton::Middle, false, 30, 10);
  EXPECT_NEAR(state.scene.camera.matrix[3].x, -0.2, 1e-12);
  handleMouseButton(state, MouseButton::Right, true, 30, 10);
  handleMouseMove(state, 80, 10);
  EXPECT_GT(-state.scene.camera.matrix[2].x, 0.1);  // the mouse went right: so did the view
}

TEST(Placement, TheLowestPointOfEachShapeIsExact) {
  // A sphere scaled by 2 on y and 3 on x, turned 30 degrees about z: its
  // lowest point is -|row 1 of the linear part| below its centre.
  glm::dmat4 m = glm::rotate(glm::dmat4(1.0), std::numbers::pi / 6, glm::dvec3(0, 0, 1)) *
                 glm::scale(glm::dmat4(1.0), glm::dvec3(3, 2, 1));
  m[3] = {0, 10, 0, 1};
  double a = 3 * std::sin(std::numbers::pi / 6), b = 2 * std::cos(std::numbers::pi / 6);
  EXPECT_NEAR(lowestY(scene::ObjectKind::Sphere, m), 10 - std::sqrt(a * a + b * b), 1e-12);
  EXPECT_NEAR(lowestY(scene::ObjectKind::Cube, m), 10 - a - b, 1e-12);
  EXPECT_NEAR(lowestY(scene::ObjectKind::Cylinder, m), 10 - b - a, 1e-12);
  // Against brute force over the shapes' surfaces, for a tilted cylinder.
  glm::dmat4 t = glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1, 0.3, 0.5))) *
                 glm::scale(glm::dmat4(1.0), glm::dvec3(0.5, 2, 1.5));
  double lowest = 1e300;
  for (int i = 0; i <= 720; ++i) {
    double angle = i * std::numbers::pi / 360;
    for (double y : {-1.0, 1.0}) {
      glm::dvec4 p = t * glm::dvec4(std::cos(angle), y, std::sin(angle), 1);
      lowest = std::min(lowest, p.y);
    }
  }
  EXPECT_NEAR(lowestY(scene::ObjectKind::Cylinder, t), lowest, 1e-4);
  EXPECT_LE(lowestY(scene::ObjectKind::Cylinder, t), lowest);
}

TEST(Placement, NewObjectsRestOnTheGroundWhereTheCameraLooks) {
  FakeFiles files;
  BuilderState state = initialState(640, 480);
  state.scene.camera.matrix = scene::cameraFromLookAt({4, 6, 4}, {2, 0, -1});
  press(state, "3", files);
  glm::dvec3 centre(state.scene.objects[0].matrix[3]);
  EXPECT_NEAR(centre.x, 2, 1e-12);
  EXPECT_NEAR(centre.z, -1, 1e-12);
  EXPECT_NEAR(lowestY(scene::ObjectKind::Sphere, state.scene.objects[0].matrix), 0, 1e-12);
  // Looking over the horizon: kPlacementDistance ahead, still on the ground.
  state.scene.camera.matrix = scene::cameraFromLookAt({0, 1, 0}, {0, 2, -10});
  press(state, "4", files);
  glm::dmat4 m = state.scene.objects[1].matrix;
  glm::dvec3 ahead = placementPoint(state.scene.camera);
  EXPECT_NEAR(ahead.z, -kPlacementDistance * 10 / std::sqrt(101.0), kPlacementStep / 2);
  EXPECT_EQ(m[3].x, ahead.x);
  EXPECT_EQ(m[3].z, ahead.z);
  EXPECT_EQ(lowestY(scene::ObjectKind::Cylinder, m), 0.0);
}

TEST(Placement, NewLightsGoAboveTheObjects) {
  FakeFiles files;
  BuilderState state = initialState(640, 480);
  press(state, "3GX-2\n2GX2\nSY3\n1", files);  // a plane counts for nothing
  press(state, "L", files);
  // The cube reaches y = 1 + 3 = ... its centre is at 1, scaled 3 on y: top 4.
  glm::dvec3 light = state.scene.lights[0].position();
  EXPECT_EQ(light, glm::dvec3(0, 4 + kLightHeightAboveScene, 0));
}

TEST(History, UndoAndRedoEveryChange) {
  FakeFiles files;
  BuilderState state = initialState(640, 480);
  scene::Scene empty = state.scene;
  press(state, "3", files);
  scene::Scene oneSphere = state.scene;
  press(state, "GX2\n", files);
  scene::Scene moved = state.scene;
  press(state, "B", files);
  scene::Scene green = state.scene;
  handleKey(state, kKeyUndo, files.fs());
  EXPECT_EQ(state.scene, moved);
  handleKey(state, kKeyUndo, files.fs());
  EXPECT_EQ(state.scene, oneSphere);
  handleKey(state, kKeyRedo, files.fs());
  EXPECT_EQ(state.scene, moved);
  handleKey(state, kKeyUndo, files.fs());
  handleKey(state, kKeyUndo, files.fs());
  EXPECT_EQ(state.scene, empty);
  EXPECT_FALSE(state.selection);           // the sphere it named is gone
  handleKey(state, kKeyUndo, files.fs());  // nothing more to undo
  EXPECT_EQ(state.scene, empty);
  for (int i = 0; i < 3; ++i) handleKey(state, kKeyRedo, files.fs());
  EXPECT_EQ(state.scene, green);
  // A new change forgets what could be redone.
  handleKey(state, kKeyUndo, files.fs());
  state.selection = Selection{false, 0};
  press(state, "X", files);
  handleKey(state, kKeyRedo, files.fs());
  EXPECT_TRUE(state.scene.objects.empty());
  // A transform in progress is cancelled, not recorded.
  press(state, "2GY5", files);
  handleKey(state, kKeyUndo, files.fs());
  EXPECT_TRUE(state.scene.objects.empty());
  EXPECT_EQ(state.operation, Operation::None);
}

TEST(History, PanelEditsAreStepsToo) {
  FakeFiles files;
  BuilderState state = initialState(640, 480);
  press(state, "2L", files);
  scene::Scene before = state.scene;
  setObjectTransform(state, 0, {1, 2, 3}, {90, 0, 0}, {2, 2, 2});
  glm::dmat4 m = state.scene.objects[0].matrix;
  EXPECT_EQ(glm::dvec3(m[3]), glm::dvec3(1, 2, 3));
  EXPECT_NEAR(m[1][2], 2.0, 1e-12);  // local +Y turned onto world +Z, doubled
  scene::Material shiny;
  shiny.shininess = 20;
  setObjectMaterial(state, 0, shiny);
  setLight(state, 0, {0, 9, 0}, {0.5, 0.5, 0.5});
  setCameraView(state, {10, 1, 0}, {0, 1, 0});
  EXPECT_EQ(state.scene.lights[0].position(), glm::dvec3(0, 9, 0));
  for (int i = 0; i < 4; ++i) handleKey(state, kKeyUndo, files.fs());
  EXPECT_EQ(state.scene, before);
}

TEST(History, AViewDragIsOneStepAndTheLengthIsBounded) {
  FakeFiles files;
  BuilderState state = initialState(640, 480);
  press(state, "3", files);
  scene::Scene before = state.scene;
  handleMouseButton(state, MouseButton::Middle, true, 10, 10);
  for (int x = 11; x < 40; ++x) handleMouseMove(state, x, 10);
  handleMouseButton(state, MouseButton::Middle, false, 40, 10);
  handleScroll(state, 1);
  handleScroll(state, 1);
  EXPECT_NE(state.scene, before);
  handleKey(state, kKeyUndo, files.fs());
  EXPECT_EQ(state.scene, before);
  for (std::size_t i = 0; i < kHistoryLength + 20; ++i) press(state, i % 2 ? "B" : "N", files);
  std::size_t undone = 0;
  for (; undone < 2 * kHistoryLength; ++undone) {
    scene::Scene now = state.scene;
    handleKey(state, kKeyUndo, files.fs());
    if (state.scene == now) break;
  }
  EXPECT_EQ(undone, kHistoryLength);
}

TEST(BuilderState, IdColoursRoundTrip) {
  for (std::size_t i : {0u, 1u, 254u, 255u, 1000u}) {
    glm::ivec3 c = idColour(i);
    EXPECT_EQ(idFromColour(c.r, c.g, c.b), static_cast<int>(i));
  }
  EXPECT_EQ(idFromColour(0, 0, 0), -1);
}

}  // namespace
}  // namespace sfbuild
