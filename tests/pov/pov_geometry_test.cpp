// POV-Ray as the cross-check of our geometry. Each scene is exported with
// --flat (every object unlit in a colour of its own), rendered by POV-Ray at
// one sample per pixel centre, and each pixel's colour mapped back to its
// object; sfrender's renderObjectIds must agree on at least 99.5% of the
// pixels. Where POV-Ray itself is wrong (its fixed tolerances: objects below
// about 1e-5, hits closer than 1e-6, distances beyond 1e7), the test says so
// and judges sfrender against the exact reference caster instead.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <iostream>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "libscene/formats/pov/pov_writer.h"
#include "scenefile/transform.h"
#include "renderer/render.h"
#include "renderer/render_scene.h"
#include "tests/geometry/reference_caster.h"
#include "tests/geometry/scene_builder.h"
#include "tests/pov/povray_runner.h"

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kAgreement = 0.995;

using namespace testscenes;

struct CrossCase {
  std::string name;
  scene::Scene scene;
  double fov = 60.0;
  int width = 200;
  int height = 150;
  // Why POV-Ray cannot be trusted here; empty where it can.
  std::string povRayLimit;
};

// A camera turned by `roll` about its forward axis.
dmat4 rolled(const dvec3& eye, const dvec3& target, double roll) {
  dmat4 m = scene::cameraFromLookAt(eye, target);
  dmat4 turn = rotate(roll, {0, 0, 1});  // about the camera's own z, its -forward
  return m * turn;
}

CrossCase make(std::string name, scene::Scene scene, double fov = 60.0, int width = 200,
               int height = 150, std::string povRayLimit = {}) {
  return {std::move(name), std::move(scene), fov, width, height, std::move(povRayLimit)};
}

std::vector<CrossCase> cases() {
  std::vector<CrossCase> c;
  c.push_back(make("primitives", primitives(1, dvec3(0), {0, 2, 8}, {0, 0, 0})));
  c.push_back(make("shear", shearScene()));
  c.push_back(
      make("mirrors",
           SceneBuilder()
               .camera({0, 2, 9}, {0, 0, 0})
               .add(K::Plane, translate(0, -1.5, 0) * scale(1, -1, 1))
               .add(K::Sphere, translate(-3, 0, 0) * scale(-1, 1.2, 0.8) * rotate(0.5, {0, 0, 1}))
               .add(K::Cube, rotate(0.5, {1, 1, 0}) * scale(1, -0.7, 1))
               .add(K::Cylinder, translate(3, 0, 0) * rotate(0.6, {1, 0, 0}) * scale(-0.8, 1, 0.8))
               .add(K::Cube, translate(0, 2.5, -2) * shear(0, 2, 0.5) * scale(-0.6))
               .build()));
  c.push_back(make(
      "non-uniform scale",
      SceneBuilder()
          .camera({0, 2, 10}, {0, 0, 0})
          .add(K::Plane, translate(0, -2, 0) * scale(50, 1, 0.01))
          .add(K::Sphere, translate(-3, 0, 0) * rotate(0.7, {0, 0, 1}) * scale(2.5, 0.2, 1))
          .add(K::Cube, rotate(0.4, {0, 0, 1}) * scale(0.05, 2, 0.05))
          .add(K::Cylinder, translate(3, 0, 0) * rotate(0.5, {1, 0, 0}) * scale(1.5, 0.02, 1.5))
          .add(K::Sphere, translate(0, 2.5, -1) * rotate(0.7, {0, 1, 0}) * scale(1e-2, 1.2, 1.2))
          .build()));
  c.push_back(make("steep camera down", primitives(1, dvec3(0), {0.5, 12, 1.5}, {0, 0, 0})));
  c.push_back(make("straight down", SceneBuilder()
                                        .camera({0, 10, 0}, {0, 0, 0})
                                        .add(K::Plane, dmat4(1.0))
                                        .add(K::Sphere, translate(-2, 1, 1))
                                        .add(K::Cube, translate(2, 1, -1) * rotate(0.5, {0, 1, 0}))
                                        .add(K::Cylinder, translate(0.3, 1, 2.5))
                                        .build()));
  c.push_back(make("steep camera up",
                   SceneBuilder()
                       .camera({0.5, -1, 3}, {0, 8, 0})
                       .add(K::Plane, translate(0, 12, 0))
                       .add(K::Sphere, translate(0, 8, 0) * scale(2))
                       .add(K::Cube, translate(3, 6, 2))
                       .add(K::Cylinder, translate(-3, 7, -1) * rotate(kPi / 2, {1, 0, 0}))
                       .build()));
  c.push_back(
      make("straight up", SceneBuilder()
                              .camera({0, 0, 0}, {0, 10, 0})
                              .add(K::Plane, translate(0, 12, 0))
                              .add(K::Sphere, translate(0, 8, 0) * scale(2))
                              .add(K::Cube, translate(3, 6, 2))
                              .add(K::Cylinder, translate(-3, 7, -1) * rotate(kPi / 2, {1, 0, 0}))
                              .build()));
  scene::Scene roll = primitives(1, dvec3(0), {0, 2, 8}, {0, 0, 0});
  roll.camera.matrix = rolled({1, 3, 8}, {0, 0, 0}, 0.5);
  c.push_back(make("rolled camera", roll));
  c.push_back(make("wide field of view", primitives(1, dvec3(0), {0, 1, 4}, {0, 0, 0}), 120.0));
  c.push_back(make("narrow field of view", primitives(1, dvec3(0), {0.3, 2, 30}, {0, 0, 0}), 8.0));
  c.push_back(make("2:1 image", primitives(1, dvec3(0), {0, 2, 8}, {0, 0, 0}), 45.0, 240, 120));
  c.push_back(make("camera inside a sphere",
                   SceneBuilder()
                       .camera({1, 0.5, 2}, {0, 0, -5})
                       .add(K::Sphere, scale(10))
                       .add(K::Cube, translate(0, 0, -5) * rotate(0.5, {1, 1, 0}))
                       .add(K::Sphere, translate(-3, 1, -4))
                       .add(K::Cylinder, translate(3, -1, -4) * rotate(0.3, {1, 0, 0}))
                       .build()));
  c.push_back(make("planes every way",
                   SceneBuilder()
                       .camera({0, 0, 6}, {0, 0, 0})
                       .add(K::Plane, translate(0, -2, 0) * rotate(0.2, {0, 0, 1}))
                       .add(K::Plane, translate(0, 3, 0) * rotate(2.9, {1, 0, 0}))
                       .add(K::Plane, translate(-4, 0, 0) * rotate(kPi / 2 + 0.3, {0, 0, 1}))
                       .add(K::Plane, translate(0, 0, -10) * rotate(kPi / 2, {1, 0, 0}))
                       .add(K::Sphere, dmat4(1.0))
                       .build()));
  c.push_back(make("sixty objects with shear and mirrors", randomAffineScene(77)));
  c.push_back(make("size 1 at 1e3", primitives(1, {1e3, 1e3, -1e3}, {0.5, 2, 8}, {0, 0, 0})));

  // POV-Ray's fixed tolerances.
  c.push_back(make("size 1e-6", primitives(1e-6, dvec3(0), {0.5, 2, 8}, {0, 0, 0}), 60.0, 200, 150,
                   "POV-Ray drops intersections nearer than its fixed depth tolerances (about 1e-6 "
                   "along the ray in object space), so objects below about 1e-5 come apart"));
  c.push_back(make("hits closer than 1e-6",
                   SceneBuilder()
                       .camera({0, 0, 4e-7}, {0.2, 0.1, -1})
                       .add(K::Plane, rotate(kPi / 2, {1, 0, 0}))
                       .add(K::Sphere, translate(0, 0, -6) * scale(3))
                       .add(K::Cube, translate(4, 2, -8))
                       .build(),
                   60.0, 200, 150,
                   "POV-Ray ignores hits nearer than its depth tolerance of 1e-6, so it sees "
                   "through the plane 4e-7 in front of the eye"));
  c.push_back(make("size 1e-3 at 1e4", primitives(1e-3, {1e4, -1e4, 1e4}, {0.5, 2, 8}, {0, 0, 0}),
                   60.0, 200, 150,
                   "POV-Ray keeps bounding boxes in single precision, whose step at 1e4 is "
                   "1e-3: it clips objects that small that far out"));
  c.push_back(make("beyond 1e7", primitives(1e6, {0, 0, -3e7}, {0.5, 2, 8}, {0, 0, 0}), 60.0, 200,
                   150,
                   "POV-Ray drops every hit beyond its maximum distance of 1e7, so the far parts "
                   "of the scene vanish"));
  return c;
}

// gtest names a case by its name, not its bytes.
void PrintTo(const CrossCase& c, std::ostream* os) {
  *os << c.name;
}

class PovGeometry : public ::testing::TestWithParam<CrossCase> {};

TEST_P(PovGeometry, PovRayAndSfrenderShowTheSameObjectInEachPixel) {
  if (!povtest::povrayProgram()) GTEST_SKIP() << "povray is not installed";
  const CrossCase& c = GetParam();
  scene::PovWriteOptions options;
  options.verticalFovDegrees = c.fov;
  options.width = c.width;
  options.height = c.height;
  options.flat = true;
  scene::ConversionOptions conversion;
  conversion.pov = options;
  scene::DiagnosticList diagnostics;
  std::optional<std::string> pov = scene::writePovScene(c.scene, conversion, diagnostics);
  ASSERT_TRUE(pov.has_value());
  std::string log;
  std::string fileName = c.name;
  for (char& ch : fileName) {
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '-';
  }
  std::optional<povtest::Image8> image =
      povtest::renderWithPovray(*pov, c.width, c.height, fileName, log);
  ASSERT_TRUE(image.has_value()) << log;
  std::vector<std::int32_t> povIds = povtest::flatObjectIds(*image, c.scene.objects.size());
  EXPECT_EQ(std::count(povIds.begin(), povIds.end(), -2), 0)
      << "every pixel of a flat render is an object's colour or black";

  render::RenderSettings settings;
  settings.width = c.width;
  settings.height = c.height;
  settings.verticalFovDegrees = c.fov;
  std::vector<std::int32_t> ours = render::renderObjectIds(render::RenderScene(c.scene), settings);
  double withPov = povtest::agreement(ours, povIds);

  // The case shows what its name says: every object in some pixel.
  std::set<std::int32_t> shown(ours.begin(), ours.end());
  for (std::size_t i = 0; i < c.scene.objects.size(); ++i) {
    if (c.name != "sixty objects with shear and mirrors" && c.name != "hits closer than 1e-6") {
      EXPECT_TRUE(shown.count(static_cast<std::int32_t>(i))) << "object " << i << " is not seen";
    }
  }

  geomref::Scene reference(c.scene);
  geomref::Camera camera(c.scene.camera, c.width, c.height, c.fov);
  std::vector<std::int32_t> exact = geomref::castObjectIds(reference, camera);
  double withReference = povtest::agreement(ours, exact);
  if (c.povRayLimit.empty()) {
    std::cout << "[ pov ] " << c.name << ": " << 100.0 * withPov
              << "% of pixels agree (the exact reference: " << 100.0 * withReference << "%)\n";
    EXPECT_GE(withPov, kAgreement);
    return;
  }
  std::cout << "[ pov ] " << c.name << ": POV-Ray agrees on " << 100.0 * withPov
            << "% of pixels: " << c.povRayLimit << "; the exact reference agrees on "
            << 100.0 * withReference << "%\n";
  EXPECT_LT(withPov, kAgreement) << "POV-Ray no longer fails here: check it instead";
  EXPECT_GE(withReference, kAgreement);
}

std::string caseName(const ::testing::TestParamInfo<CrossCase>& info) {
  std::string name;
  for (char ch : info.param.name) name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Scenes, PovGeometry, ::testing::ValuesIn(cases()), caseName);

}  // namespace
