// The shading of single points against values computed by hand, one term
// of RENDERING.md at a time.
#include "renderer/tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "renderer/test_scenes.h"

namespace render {
namespace {

using namespace render::testing;
using scene::ObjectKind;

// The colour seen along the ray from (0, 0, 5) toward -z.
glm::dvec3 traceCentre(const scene::Scene& s, int maxDepth = 5, glm::dvec3 origin = {0, 0, 5},
                       glm::dvec3 direction = {0, 0, -1}) {
  RenderScene compiled(s);
  Tracer tracer(compiled, maxDepth);
  MediumStack media;
  TraceContext context;
  return tracer.trace(Ray{origin, direction}, RaySource{}, 0, media, context);
}

void expectColour(const glm::dvec3& got, const glm::dvec3& want, double tolerance = 1e-12) {
  EXPECT_NEAR(got.x, want.x, tolerance);
  EXPECT_NEAR(got.y, want.y, tolerance);
  EXPECT_NEAR(got.z, want.z, tolerance);
}

// A unit sphere at the origin is hit at (0, 0, 1) with normal +z, seen
// from +z: V = (0, 0, 1).
scene::Scene unitSphere(const scene::Material& m, std::vector<scene::Light> lights) {
  scene::Scene s = sceneLookingAt({0, 0, 5}, {0, 0, 0});
  s.objects.push_back(object(ObjectKind::Sphere, {}, m));
  s.lights = std::move(lights);
  return s;
}

TEST(Shading, AmbientIsPerLightAndIgnoresShadowsAndAngles) {
  scene::Material m = flat({0.5, 0.25, 1.0}, 0.2);
  // A light behind the sphere still adds ambient.
  glm::dvec3 one = traceCentre(unitSphere(m, {light({0, 0, -5}, {1, 2, 3})}));
  expectColour(one, glm::dvec3(0.5 * 1 * 0.2, 0.25 * 2 * 0.2, 1.0 * 3 * 0.2));
  glm::dvec3 two =
      traceCentre(unitSphere(m, {light({0, 0, -5}, {1, 2, 3}), light({0, 9, 9}, {1, 1, 1})}));
  expectColour(two, one + glm::dvec3(0.5, 0.25, 1.0) * 0.2);
}

TEST(Shading, DiffuseFollowsTheCosine) {
  scene::Material m = flat({0.5, 0.5, 0.5}, 0.0);
  m.diffuse = 0.8;
  // The light at P + 5 * (0, 0.6, 0.8): cos = 0.8.
  glm::dvec3 c = traceCentre(unitSphere(m, {light({0, 3, 5}, {1, 1, 0.5})}));
  expectColour(c, glm::dvec3(0.5 * 0.8 * 0.8, 0.5 * 0.8 * 0.8, 0.5 * 0.5 * 0.8 * 0.8));
}

TEST(Shading, SpecularIsPhongsHighlightInTheLightsColour) {
  scene::Material m = flat({0.0, 0.0, 0.0}, 0.0);
  m.specular = 0.5;
  m.shininess = 3.0;
  // reflect(-l, N) = (0, -0.6, 0.8), V = (0, 0, 1): cos = 0.8; the object's
  // colour does not tint the highlight.
  glm::dvec3 c = traceCentre(unitSphere(m, {light({0, 3, 5}, {1, 2, 4})}));
  double h = 0.5 * std::pow(0.8, 3.0);
  expectColour(c, glm::dvec3(1, 2, 4) * h);
}

TEST(Shading, NoDiffuseOrSpecularFromBehind) {
  scene::Material m;
  m.colour = {1, 1, 1};
  glm::dvec3 c = traceCentre(unitSphere(m, {light({0, 0, -5})}));
  expectColour(c, glm::dvec3(m.ambient));
}

TEST(Shading, AShadowLeavesOnlyAmbient) {
  scene::Material m;
  m.colour = {1, 0.5, 0.25};
  scene::Scene s = unitSphere(m, {light({0, 3, 5})});
  // A small cube on the segment from P = (0, 0, 1) to the light.
  s.objects.push_back(
      object(ObjectKind::Cube, {scale(0.1), translate(0, 1.5, 3)}, flat({1, 1, 1})));
  expectColour(traceCentre(s), m.colour * m.ambient);
  // Transparent objects cast shadows too.
  s.objects.back().material.transparency = 1.0;
  expectColour(traceCentre(s), m.colour * m.ambient);
}

// shadeSurface works on two lights at a time, side by side in vector lanes;
// here each term is the scalar expression, light by light, and the sums
// must be the same to the bit, whatever the number of lights (odd numbers
// leave a lane over), the exponent (whole, or not, for std::pow) and the
// lights' places (behind the surface, in a shadow).
TEST(Shading, LightsInPairsGiveTheBitsOfOneByOne) {
  auto power = [](double x, double e) {
    auto n = static_cast<unsigned>(e);
    if (!(e >= 0.0 && e <= 1024.0) || static_cast<double>(n) != e) return std::pow(x, e);
    double result = 1.0;
    for (; n > 0; n >>= 1, x *= x) {
      if (n & 1u) result *= x;
    }
    return result;
  };
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double shininess : {200.0, 37.5}) {
    for (std::size_t lights = 1; lights <= 5; ++lights) {
      scene::Material m;
      m.colour = {0.9, 0.5, 0.2};
      m.shininess = shininess;
      scene::Scene s = unitSphere(m, {});
      for (std::size_t i = 0; i < lights; ++i) {
        s.lights.push_back(
            light({4 * u(rng), 4 * u(rng), 3 + 2 * u(rng)}, {0.5 + 0.4 * u(rng), 0.6, 0.7}));
      }
      // A cube that shades part of the sphere from some of the lights.
      s.objects.push_back(object(ObjectKind::Cube, {scale(0.3), translate(0.5, 0.5, 2)}));
      RenderScene compiled(s);
      Tracer tracer(compiled, 0);
      int shaded = 0;
      for (int k = 0; k < 200; ++k) {
        glm::dvec3 from = glm::dvec3(u(rng), u(rng), 5.0);
        glm::dvec3 d = glm::normalize(glm::dvec3(0.6 * u(rng), 0.6 * u(rng), 0) - from);
        std::optional<Hit> hit = compiled.closestHit(Ray{from, d}, RaySource{});
        if (!hit || hit->object != 0) continue;
        ++shaded;
        glm::dvec3 n = glm::dot(hit->normal, d) > 0.0 ? -hit->normal : hit->normal;
        TraceContext context;
        glm::dvec3 got = tracer.shadeSurface(*hit, n, -d, context);
        glm::dvec3 want(0.0);
        for (std::size_t i = 0; i < lights; ++i) {
          const RenderLight& l = compiled.lights()[i];
          want += m.colour * l.colour * m.ambient;
          glm::dvec3 toLight = l.position - hit->point;
          double distance = glm::length(toLight);
          if (!(distance > 0.0)) continue;
          toLight /= distance;
          double cosine = glm::dot(toLight, n);
          TraceContext alone;
          if (cosine <= 0.0 || tracer.shadowed(*hit, i, alone)) continue;
          want += m.colour * l.colour * (m.diffuse * cosine);
          double highlight = std::max(0.0, glm::dot(glm::reflect(-toLight, n), -d));
          if (highlight > 0.0) want += l.colour * (m.specular * power(highlight, shininess));
        }
        EXPECT_EQ(got.x, want.x) << lights << " lights, shininess " << shininess;
        EXPECT_EQ(got.y, want.y);
        EXPECT_EQ(got.z, want.z);
      }
      EXPECT_GT(shaded, 100);
    }
  }
}

TEST(Shading, ReflectionAddsReflectivityTimesWhatTheMirrorSees) {
  // A black mirror plane y = 0 seen from above at 45 degrees; the reflected
  // ray meets a flat-coloured sphere.
  scene::Scene s = sceneLookingAt({0, 1, 1}, {0, 0, 0});
  scene::Material mirror = flat({0, 0, 0});
  mirror.reflectivity = 0.5;
  s.objects.push_back(object(ObjectKind::Plane, {}, mirror));
  s.objects.push_back(
      object(ObjectKind::Sphere, {scale(0.5), translate(0, 5, -5)}, flat({0.2, 0.4, 0.6})));
  s.lights.push_back(light({0, 10, 0}));
  glm::dvec3 c = traceCentre(s, 5, {0, 1, 1}, glm::normalize(glm::dvec3(0, -1, -1)));
  expectColour(c, 0.5 * glm::dvec3(0.2, 0.4, 0.6));
}

scene::Scene glassSphereBeforeBackdrop(double reflectivity, double transparency) {
  scene::Scene s = sceneLookingAt({0, 0, 5}, {0, 0, 0});
  scene::Material glass = flat({0, 0, 0}, 0.0);
  glass.reflectivity = reflectivity;
  glass.transparency = transparency;
  glass.ri = 1.5;
  s.objects.push_back(object(ObjectKind::Sphere, {}, glass));
  // A flat backdrop behind it, the plane z = -3.
  s.objects.push_back(object(ObjectKind::Plane, {rotateX(1.5707963267948966), translate(0, 0, -3)},
                             flat({0.3, 0.6, 0.9})));
  s.lights.push_back(light({0, 0, 10}));
  return s;
}

TEST(Shading, RefractionThroughAGlassSphere) {
  // The central ray passes both surfaces unbent; each passage keeps
  // TRANSPARENCY of the light.
  expectColour(traceCentre(glassSphereBeforeBackdrop(0.0, 0.5)),
               0.5 * 0.5 * glm::dvec3(0.3, 0.6, 0.9));
  // A ray at depth 1 reaches the inner surface but not the backdrop.
  expectColour(traceCentre(glassSphereBeforeBackdrop(0.0, 1.0), 1), glm::dvec3(0.0));
}

TEST(Shading, SchlickWeighsReflectionAgainstRefraction) {
  // Normal incidence, 1 -> 1.5 and back: R = 0.04 at both surfaces. With
  // depth 2, the path through both surfaces to the backdrop is the only
  // one that carries light: (1 - R)^2 of it.
  glm::dvec3 c = traceCentre(glassSphereBeforeBackdrop(1.0, 1.0), 2);
  expectColour(c, 0.96 * 0.96 * glm::dvec3(0.3, 0.6, 0.9), 1e-12);
}

TEST(Schlick, AgainstItsFormula) {
  EXPECT_NEAR(schlickReflectance(1.0, 1.5, 1.0), 0.04, 1e-15);
  EXPECT_NEAR(schlickReflectance(1.0, 1.5, 0.0), 1.0, 1e-15);
  EXPECT_NEAR(schlickReflectance(1.0, 1.5, 0.5), 0.04 + 0.96 * std::pow(0.5, 5), 1e-15);
  // From glass into air, the transmitted angle's cosine is used.
  double cosT = std::sqrt(1.0 - 1.5 * 1.5 * (1.0 - 0.9 * 0.9));
  EXPECT_NEAR(schlickReflectance(1.5, 1.0, 0.9), 0.04 + 0.96 * std::pow(1.0 - cosT, 5), 1e-15);
  // Beyond the critical angle: total reflection.
  EXPECT_EQ(schlickReflectance(1.5, 1.0, 0.5), 1.0);
}

TEST(Refraction, FollowsSnellsLaw) {
  glm::dvec3 n(0, 1, 0);
  for (double angle : {0.0, 0.3, 0.7, 1.2, 1.5}) {
    glm::dvec3 d(std::sin(angle), -std::cos(angle), 0);
    glm::dvec3 t;
    ASSERT_TRUE(refractDirection(d, n, 1.0, 1.33, t));
    double sinT = t.x;
    EXPECT_NEAR(1.0 * std::sin(angle), 1.33 * sinT, 1e-15) << angle;
    EXPECT_NEAR(glm::length(t), 1.0, 1e-15);
    EXPECT_LT(t.y, 0.0);
  }
}

TEST(Refraction, TotalInternalReflection) {
  glm::dvec3 n(0, 1, 0);
  double critical = std::asin(1.0 / 1.5);
  glm::dvec3 t;
  glm::dvec3 below(std::sin(critical - 1e-6), -std::cos(critical - 1e-6), 0);
  glm::dvec3 beyond(std::sin(critical + 1e-6), -std::cos(critical + 1e-6), 0);
  EXPECT_TRUE(refractDirection(below, n, 1.5, 1.0, t));
  EXPECT_FALSE(refractDirection(beyond, n, 1.5, 1.0, t));
}

TEST(Shading, TotalInternalReflectionSendsNothingThrough) {
  // Inside a glass cube, a ray meets its top face at 60 degrees from the
  // normal (beyond the critical 41.8): nothing refracts out, so the white
  // backdrop above stays unseen; straight up, it shows.
  scene::Scene s = sceneLookingAt({0, 0, 0}, {0, 1, 0});
  scene::Material glass = flat({0, 0, 0}, 0.0);
  glass.transparency = 1.0;
  glass.ri = 1.5;
  s.objects.push_back(object(ObjectKind::Cube, {}, glass));
  s.objects.push_back(object(ObjectKind::Plane, {translate(0, 3, 0)}, flat({1, 1, 1})));
  s.lights.push_back(light({0, 10, 0}));
  glm::dvec3 steep(std::sin(1.0472), std::cos(1.0472), 0);
  glm::dvec3 direct = traceCentre(s, 1, {0, 0, 0}, glm::dvec3(0, 1, 0));
  expectColour(direct, glm::dvec3(1.0));  // straight up, it gets through
  // From (-0.9, 0.5) at 60 degrees the ray meets the top face at x = -0.03.
  glm::dvec3 c = traceCentre(s, 1, {-0.9, 0.5, 0}, steep);
  expectColour(c, glm::dvec3(0.0));
}

TEST(Tracing, DepthLimitReturnsBlack) {
  // Two facing mirrors: each bounce takes REFLECTIVITY; the ray that would
  // make bounce depth + 1 returns black, so the sum stops there.
  scene::Scene s = sceneLookingAt({0, 0, 0}, {0, 0, -1});
  scene::Material mirror = flat({1, 1, 1}, 0.1);
  mirror.reflectivity = 0.5;
  s.objects.push_back(
      object(ObjectKind::Plane, {rotateX(1.5707963267948966), translate(0, 0, -1)}, mirror));
  s.objects.push_back(
      object(ObjectKind::Plane, {rotateX(1.5707963267948966), translate(0, 0, 1)}, mirror));
  s.lights.push_back(light({0, 5, 0}));
  for (int depth : {0, 1, 2, 5}) {
    double expected = 0.0;
    for (int bounce = 0; bounce <= depth; ++bounce) expected += 0.1 * std::pow(0.5, bounce);
    expectColour(traceCentre(s, depth, {0, 0, 0}, {0, 0, -1}), glm::dvec3(expected), 1e-15);
  }
}

// Copies carry only the solids on the stack: what a copy answers, and what
// it answers after its own pushes and removals, is what the original would,
// and the original does not change with it.
TEST(MediumStack, ACopyHoldsTheSameSolidsAndGoesItsOwnWay) {
  scene::Scene s = sceneLookingAt({0, 0, 5}, {0, 0, 0});
  for (double ri : {1.1, 1.2, 1.3, 1.4}) {
    scene::Material glass = flat({1, 1, 1}, 0.0);
    glass.transparency = 0.9;
    glass.ri = ri;
    s.objects.push_back(object(ObjectKind::Sphere, {}, glass));
  }
  RenderScene compiled(s);
  // The stack holds objects as the compiled scene numbers them; the spheres
  // here are named by their place in the scene.
  auto sphere = [&](std::uint32_t inScene) {
    std::uint32_t object = 0;
    while (compiled.sceneObject(object) != inScene) ++object;
    return object;
  };
  MediumStack three;
  for (std::uint32_t object : {0u, 1u, 2u}) three.push(sphere(object));

  MediumStack copied(three);
  EXPECT_EQ(copied.size(), 3);
  EXPECT_EQ(copied.refractiveIndex(compiled), 1.3);
  // Assigned over a deeper stack: the deeper one's solids are gone.
  MediumStack assigned;
  for (int k = 0; k < 5; ++k) assigned.push(sphere(3));
  assigned = three;
  EXPECT_EQ(assigned.size(), 3);
  EXPECT_EQ(assigned.refractiveIndex(compiled), 1.3);
  // The order came with them: removing the innermost leaves the one below.
  assigned.remove(sphere(2));
  EXPECT_EQ(assigned.refractiveIndex(compiled), 1.2);
  assigned.remove(sphere(0));
  assigned.remove(sphere(1));
  EXPECT_EQ(assigned.size(), 0);
  EXPECT_EQ(assigned.refractiveIndex(compiled), 1.0);
  // Assigned the empty stack, a stack is empty.
  copied = assigned;
  EXPECT_EQ(copied.size(), 0);
  EXPECT_EQ(copied.refractiveIndex(compiled), 1.0);
  // The original kept its solids through all of it.
  EXPECT_EQ(three.size(), 3);
  EXPECT_EQ(three.refractiveIndex(compiled), 1.3);
}

}  // namespace
}  // namespace render
