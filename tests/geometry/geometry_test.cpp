// docs/ACCURACY.md, "Geometry": at one sample per pixel,
// the object each pixel shows agrees with an exact ray cast through the
// pixel centres on all pixels but those whose centre ray passes within 1e-6
// (relative to the scene's size) of a silhouette edge.
//
// Each scene below is drawn by render::renderObjectIds and by the long
// double reference caster; at least 99.5% of the pixels must agree, and
// every pixel that does not must lie within 1e-6 rad of a silhouette.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>
#include <ostream>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "renderer/render.h"
#include "renderer/render_scene.h"
#include "scenefile/transform.h"
#include "tests/geometry/reference_caster.h"
#include "tests/geometry/scene_builder.h"

namespace {

constexpr double kPi = std::numbers::pi;

struct GeometryCase {
  std::string name;
  scene::Scene scene;
  int width = 160;
  int height = 120;
  // Whether each object must cover some pixel: proves that the case shows
  // what its name says.
  bool everyObjectVisible = true;
};

using namespace testscenes;

std::vector<GeometryCase> geometryCases() {
  std::vector<GeometryCase> cases;
  cases.push_back({"primitives", primitives(1, dvec3(0), {0, 2, 8}, {0, 0, 0})});

  cases.push_back({"shear", shearScene()});

  // Negative determinants: mirrors about one axis and about all three.
  cases.push_back(
      {"mirror",
       SceneBuilder()
           .camera({0, 2, 9}, {0, 0, 0})
           .add(K::Plane, translate(0, -1.5, 0) * scale(1, -1, 1))
           .add(K::Sphere, translate(-3, 0, 0) * scale(-1, 1.2, 0.8) * rotate(0.5, {0, 0, 1}))
           .add(K::Cube, translate(0, 0, 0) * rotate(0.5, {1, 1, 0}) * scale(1, -0.7, 1))
           .add(K::Cylinder, translate(3, 0, 0) * rotate(0.6, {1, 0, 0}) * scale(-0.8, 1, 0.8))
           .add(K::Cube, translate(0, 2.5, -2) * shear(0, 2, 0.5) * scale(-0.6))
           .build()});

  cases.push_back(
      {"non-uniform scale",
       SceneBuilder()
           .camera({0, 2, 10}, {0, 0, 0})
           .add(K::Plane, translate(0, -2, 0) * scale(50, 1, 0.01))
           .add(K::Sphere, translate(-3, 0, 0) * rotate(0.7, {0, 0, 1}) * scale(2.5, 0.2, 1))
           .add(K::Cube, translate(0, 0, 0) * rotate(0.4, {0, 0, 1}) * scale(0.05, 2, 0.05))
           .add(K::Cylinder, translate(3, 0, 0) * rotate(0.5, {1, 0, 0}) * scale(1.5, 0.02, 1.5))
           // A disc 1e-4 thick, seen at an angle: condition number 1.5e4.
           .add(K::Sphere, translate(0, 2.5, -1) * rotate(0.7, {0, 1, 0}) * scale(1e-4, 1.2, 1.2))
           .add(K::Cylinder,
                translate(-1.5, 1.5, 0) * rotate(1.2, {0, 0, 1}) * scale(0.01, 3, 0.01))
           .build()});

  // cameraFromLookAt's straight-up and straight-down cameras take their up
  // vector from +Z / -Z.
  cases.push_back({"looking straight up",
                   SceneBuilder()
                       .camera({0, 0, 0}, {0, 10, 0})
                       .add(K::Plane, translate(0, 12, 0))
                       .add(K::Sphere, translate(0, 8, 0) * scale(2))
                       .add(K::Cube, translate(3, 6, 2))
                       .add(K::Cylinder, translate(-3, 7, -1) * rotate(kPi / 2, {1, 0, 0}))
                       .build()});
  cases.push_back(
      {"looking straight down", SceneBuilder()
                                    .camera({0, 10, 0}, {0, 0, 0})
                                    .add(K::Plane, dmat4(1.0))
                                    .add(K::Sphere, translate(-2, 1, 1))
                                    .add(K::Cube, translate(2, 1, -1) * rotate(0.5, {0, 1, 0}))
                                    .add(K::Cylinder, translate(0.3, 1, 2.5))
                                    .build()});

  // Objects of size 1e-4 some 1e5 from the origin on every axis.
  cases.push_back({"size 1e-4 at 1e5", primitives(1e-4, {1e5, 1e5, -1e5}, {0.5, 2, 8}, {0, 0, 0})});

  // A sphere of radius 1e4 with one of radius 1e-3 (and a cube of 1e-3)
  // beside it: the big one is the ground, with its horizon in view.
  cases.push_back(
      {"radius 1e4 beside 1e-3", SceneBuilder()
                                     .camera({2e-3, 4e-3, 8e-3}, {0, 1e-3, 0})
                                     .add(K::Sphere, translate(0, -1e4, 0) * scale(1e4))
                                     .add(K::Sphere, translate(0, 1.5e-3, 0) * scale(1e-3))
                                     .add(K::Cube, translate(2.5e-3, 1e-3, -2e-3) * scale(1e-3))
                                     .build()});
  // The same pair seen side by side: the big sphere is a wall.
  cases.push_back({"radius 1e-3 at the side of 1e4",
                   SceneBuilder()
                       .camera({1e4 + 1e-3, -1e4 + 1e-3, 8e-3}, {1e4 + 1e-3, -1e4, 0})
                       .add(K::Sphere, translate(0, -1e4, 0) * scale(1e4))
                       .add(K::Sphere, translate(1e4 + 2e-3, -1e4, 0) * scale(1e-3))
                       .build()});

  cases.push_back({"camera inside a sphere",
                   SceneBuilder()
                       .camera({1, 0.5, 2}, {0, 0, -5})
                       .add(K::Sphere, scale(10))
                       .add(K::Cube, translate(0, 0, -5) * rotate(0.5, {1, 1, 0}))
                       .add(K::Sphere, translate(-3, 1, -4))
                       .add(K::Cylinder, translate(3, -1, -4) * rotate(0.3, {1, 0, 0}))
                       .build()});
  cases.push_back(
      {"camera inside a cube", SceneBuilder()
                                   .camera({0, 0, 8}, {-4, -2, 0})
                                   .add(K::Cube, scale(10, 5, 10))
                                   .add(K::Sphere, translate(-3, -2, -2))
                                   .add(K::Cylinder, translate(2, -3, -3))
                                   .add(K::Cube, translate(-5, 1, 2) * rotate(0.7, {0, 1, 1}))
                                   .build()});
  cases.push_back({"camera inside a cube, at a corner", SceneBuilder()
                                                            .camera({5, 1, 5}, {10, 5, 10})
                                                            .add(K::Cube, scale(10, 5, 10))
                                                            .add(K::Sphere, translate(8, 3, 9))
                                                            .build()});

  // Inside a sheared, mirrored cylinder: the tube and a cap around the eye.
  cases.push_back(
      {"camera inside a cylinder", SceneBuilder()
                                       .camera({0.5, -1, 1}, {-1, 2.5, -2})
                                       .add(K::Cylinder, shear(0, 1, 0.3) * scale(-4, 3, 4))
                                       .add(K::Sphere, translate(-1, 1.5, -1.5) * scale(0.7))
                                       .build()});

  // Rays that meet surfaces at grazing angles: from 0.01 above the top of a
  // long box and a long cylinder lying on the plane, and 0.1 beside the
  // box's flank, looking along them.
  cases.push_back(
      {"grazing",
       SceneBuilder()
           .camera({0.2, 2.01, 3}, {0.2, 1.8, -20})
           .add(K::Plane, dmat4(1.0))
           .add(K::Cylinder, translate(-1.2, 1, -8) * rotate(kPi / 2, {1, 0, 0}) * scale(1, 10, 1))
           .add(K::Cube, translate(1.3, 1, -8) * scale(1, 1, 10))
           .add(K::Sphere, translate(0, 2, -40) * scale(2))
           .build()});

  // Odd sizes put the middle column's and row's rays exactly in the planes
  // x = 1 and y = 1 of the cube: parallel to its faces, along them.
  cases.push_back({"rays along cube faces",
                   SceneBuilder()
                       .camera({1, 1, 6}, {1, 1, 0})
                       .add(K::Cube, dmat4(1.0))
                       .add(K::Cube, translate(-3, 0, 0))
                       .add(K::Cylinder, translate(3, 0, -2))
                       .add(K::Plane, translate(0, -1, 0))
                       .build(),
                   161, 121});
  // Looking straight down the axis of a cylinder and along cube faces.
  cases.push_back({"rays along a cylinder's axis",
                   SceneBuilder()
                       .camera({0, 10, 0}, {0, 0, 0})
                       .add(K::Cylinder, dmat4(1.0))
                       .add(K::Cube, translate(3, 0, 0))
                       .add(K::Cube, translate(-3, 0, 3))
                       .add(K::Plane, translate(0, -1, 0))
                       .build(),
                   161, 121});

  // The plane seen from below, tilted, crossing a second plane and objects.
  cases.push_back({"planes from below",
                   SceneBuilder()
                       .camera({0, -4, 8}, {0, 0, 0})
                       .add(K::Plane, rotate(0.3, {1, 0, 0.2}))
                       .add(K::Plane, translate(0, 0, -6) * rotate(kPi / 2 - 0.2, {1, 0, 0}))
                       .add(K::Sphere, translate(-2, 0.3, 0))
                       .add(K::Cube, translate(2, -1, 1) * rotate(0.4, {0, 1, 0}))
                       .build()});

  // A camera matrix with scale, shear and roll: only its eye, forward and
  // orthonormalised up count.
  {
    dvec3 eye(1, 2, 8);
    dvec3 forward = glm::normalize(dvec3(0, 0, 0) - eye);
    dvec3 up = glm::normalize(dvec3(0.3, 1, 0));
    dvec3 right = glm::normalize(glm::cross(forward, up));
    dmat4 m(1.0);
    m[0] = glm::dvec4(3.0 * right, 0);
    m[1] = glm::dvec4(0.5 * up + 0.4 * forward, 0);
    m[2] = glm::dvec4(-2.0 * forward, 0);
    m[3] = glm::dvec4(eye, 1);
    scene::Scene s = primitives(1, dvec3(0), {0, 0, 1}, {0, 0, 0});
    s.camera.matrix = m;
    cases.push_back({"skewed, rolled camera matrix", s});
  }

  cases.push_back({"60 random affine objects", randomAffineScene(20260523), 160, 120, false});
  return cases;
}

// Names the case in gtest's messages.
void PrintTo(const GeometryCase& c, std::ostream* out) {
  *out << c.name;
}

class Geometry : public testing::TestWithParam<GeometryCase> {};

void checkObjectIds(const GeometryCase& c, render::RenderDevice device) {
  render::RenderSettings settings;
  settings.device = device;
  settings.width = c.width;
  settings.height = c.height;
  settings.samplesPerPixel = 1;
  render::RenderScene renderScene(c.scene);
  std::vector<std::int32_t> rendered = render::renderObjectIds(renderScene, settings);

  geomref::Scene reference(c.scene);
  geomref::Camera camera(c.scene.camera, c.width, c.height, settings.verticalFovDegrees);
  std::vector<std::int32_t> exact = geomref::castObjectIds(reference, camera);
  ASSERT_EQ(rendered.size(), exact.size());

  if (c.everyObjectVisible) {
    std::set<std::int32_t> shown(exact.begin(), exact.end());
    for (std::int32_t i = 0; i < static_cast<std::int32_t>(c.scene.objects.size()); ++i) {
      EXPECT_TRUE(shown.count(i)) << "object " << i << " is not in view";
    }
  }

  int disagree = 0;
  int offEdge = 0;
  geomref::Real worst = 0;
  std::vector<std::string> report;  // the first few differences
  for (int j = 0; j < c.height; ++j) {
    for (int i = 0; i < c.width; ++i) {
      std::size_t k = static_cast<std::size_t>(j) * c.width + i;
      if (rendered[k] == exact[k]) continue;
      ++disagree;
      geomref::Real distance = geomref::silhouetteDistance(reference, camera, i, j);
      worst = std::max(worst, distance);
      if (report.size() < 5) {
        char line[160];
        std::snprintf(line, sizeof line,
                      "pixel (%d, %d): renderer %d, exact %d, silhouette within %g rad", i, j,
                      rendered[k], exact[k], static_cast<double>(distance));
        report.push_back(line);
      }
      if (distance > 1e-6L) {
        ++offEdge;
        ADD_FAILURE() << "pixel (" << i << ", " << j << "): renderer " << rendered[k] << ", exact "
                      << exact[k] << ", nearest silhouette about " << static_cast<double>(distance)
                      << " rad away";
      }
    }
  }
  double agreement = 1.0 - static_cast<double>(disagree) / static_cast<double>(exact.size());
  std::printf("[ geometry ] %-36s %3dx%-3d agreement %8.4f%%", c.name.c_str(), c.width, c.height,
              100.0 * agreement);
  if (disagree == 0) {
    std::printf("\n");
  } else {
    std::printf("  (%d differ, %s within %g rad of a silhouette)\n", disagree,
                offEdge ? "NOT all" : "all", static_cast<double>(worst));
  }
  for (const std::string& line : report) std::printf("[ geometry ]   %s\n", line.c_str());
  EXPECT_GE(agreement, 0.995);
  EXPECT_EQ(offEdge, 0);
}

TEST_P(Geometry, ObjectIdsAgreeWithExactCastAwayFromSilhouettes) {
  checkObjectIds(GetParam(), render::RenderDevice::Cpu);
}

// The GPU path's camera rays (lavapipe where no GPU is present).
TEST_P(Geometry, GpuObjectIdsAgreeWithExactCastAwayFromSilhouettes) {
  render::GpuProbe probe = render::probeGpu();
  if (!probe.available) GTEST_SKIP() << "no Vulkan device: " << probe.reason;
  checkObjectIds(GetParam(), render::RenderDevice::Gpu);
}

std::string caseName(const testing::TestParamInfo<GeometryCase>& info) {
  std::string name;
  for (char ch : info.param.name) {
    name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Scenes, Geometry, testing::ValuesIn(geometryCases()), caseName);

}  // namespace
