// Properties of the compiled scene's ray queries under seeded random
// transforms, after pbrt-v4's shape tests.
#include "renderer/render_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <glm/matrix.hpp>
#include <random>

#include "libscene/testing/random_cases.h"
#include "renderer/float_error.h"
#include "renderer/test_scenes.h"
#include "renderer/tracer.h"

namespace render {
namespace {

using namespace render::testing;
using scene::ObjectKind;

class RandomTransforms {
 public:
  explicit RandomTransforms(std::uint64_t seed) : rng_(seed) {}
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  // Scales from 1e-4 to 1e4 (ratios within 1e8, so that the condition
  // number stays far below the format's 1e12) and origins up to 1e8.
  std::vector<scene::TransformOp> transform() {
    double base = uniform(-4, 4);
    auto factor = [&] { return std::pow(10.0, std::clamp(base + uniform(-1, 1), -4.0, 4.0)); };
    double reach = std::pow(10.0, uniform(0, 8));
    return {scale(factor(), factor(), factor()), rotateX(uniform(-3.2, 3.2)),
            rotateY(uniform(-3.2, 3.2)), rotateZ(uniform(-3.2, 3.2)),
            translate(uniform(-reach, reach), uniform(-reach, reach), uniform(-reach, reach))};
  }
  glm::dvec3 direction() {
    for (;;) {
      glm::dvec3 d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      double l = glm::length(d);
      if (l > 0.1 && l <= 1.0) return d / l;
    }
  }

 private:
  std::mt19937_64 rng_;
};

TEST(ReIntersection, ASpawnedRayNeverMeetsItsSurfaceAgain) {
  RandomTransforms random(1234);
  int hits = 0;
  int attempts = 0;
  while (hits < 1000 && attempts < 100000) {
    ++attempts;
    ObjectKind kind =
        std::array{ObjectKind::Sphere, ObjectKind::Cube, ObjectKind::Cylinder}[attempts % 3];
    scene::Scene s = sceneLookingAt({0, 0, 1}, {0, 0, 0});
    s.objects.push_back(object(kind, random.transform()));
    RenderScene compiled(s);
    // Aim at a random point inside the object from outside it.
    const glm::dmat4& m = s.objects[0].matrix;
    glm::dvec3 target(m * glm::dvec4(random.uniform(-0.5, 0.5), random.uniform(-0.5, 0.5),
                                     random.uniform(-0.5, 0.5), 1.0));
    double size = glm::length(glm::dvec3(m[0])) + glm::length(glm::dvec3(m[1])) +
                  glm::length(glm::dvec3(m[2]));
    glm::dvec3 from = target + random.direction() * (4.0 * size);
    std::optional<Hit> hit = compiled.closestHit(Ray{from, target - from}, RaySource{});
    if (!hit) continue;
    ++hits;
    // Re-cast from the hit in random directions, with no help from knowing
    // which object the ray left: outward finds nothing, inward finds the
    // solid from inside.
    for (int k = 0; k < 8; ++k) {
      glm::dvec3 w = random.direction();
      if (std::abs(glm::dot(w, hit->normal)) < 1e-6) continue;
      Ray spawned{offsetRayOrigin(hit->point, hit->pointError, hit->normal, w), w};
      std::optional<Hit> again = compiled.closestHit(spawned, RaySource{});
      if (glm::dot(w, hit->normal) > 0.0) {
        ASSERT_FALSE(again.has_value())
            << "outward ray met its surface again at t = " << again->t << ", hit " << hits;
      } else {
        ASSERT_TRUE(again.has_value()) << "inward ray left the solid, hit " << hits;
        ASSERT_TRUE(again->fromInside) << "inward ray started outside, hit " << hits;
      }
    }
  }
  EXPECT_EQ(hits, 1000);
}

TEST(Bvh, AnyHitAgreesWithBruteForceWhateverItsHint) {
  // Segments of random length among 1,000 objects: anyHit through the
  // hierarchy answers as the brute-force search does, with no hint, with
  // the hint it keeps, and with a wrong one; the hint it leaves names a
  // blocking object, or none when nothing blocks.
  RandomTransforms random(7);
  scene::Scene s = sceneLookingAt({0, 0, 1}, {0, 0, 0});
  double spread = 40.0;
  for (int i = 0; i < 1000; ++i) {
    ObjectKind kind = i == 0 ? ObjectKind::Plane : static_cast<ObjectKind>(1 + i % 3);
    s.objects.push_back(
        object(kind, {scale(random.uniform(0.2, 2), random.uniform(0.2, 2), random.uniform(0.2, 2)),
                      rotateY(random.uniform(0, 3)), rotateX(random.uniform(0, 3)),
                      translate(random.uniform(-spread, spread), random.uniform(-spread, spread),
                                random.uniform(-spread, spread))}));
  }
  RenderScene compiled(s);
  std::uint32_t kept = RaySource::kNone;
  int blocked = 0;
  for (int r = 0; r < 20000; ++r) {
    glm::dvec3 origin(random.uniform(-1.5, 1.5) * spread, random.uniform(-1.5, 1.5) * spread,
                      random.uniform(-1.5, 1.5) * spread);
    glm::dvec3 d = random.direction();
    if (r % 7 == 0) d = glm::dvec3(r % 2 ? 1.0 : -0.0, 0.0, -0.0);  // axis-parallel, signed zeros
    Ray ray{origin, d};
    double tMax = random.uniform(0.0, 3.0 * spread);
    bool expected = compiled.closestHitBruteForce(ray, RaySource{}, tMax).has_value();
    blocked += expected;
    ASSERT_EQ(compiled.anyHit(ray, RaySource{}, tMax), expected) << "ray " << r;
    ASSERT_EQ(compiled.anyHit(ray, RaySource{}, tMax, &kept), expected) << "ray " << r;
    if (expected) {
      ASSERT_NE(kept, RaySource::kNone) << "ray " << r;
      // The object it names blocks this segment on its own.
      scene::Scene one = sceneLookingAt({0, 0, 1}, {0, 0, 0});
      one.objects.push_back(s.objects[compiled.sceneObject(kept)]);
      ASSERT_TRUE(RenderScene(one).closestHitBruteForce(ray, RaySource{}, tMax).has_value())
          << "ray " << r;
    } else {
      ASSERT_EQ(kept, RaySource::kNone) << "ray " << r;
    }
    std::uint32_t wrong = static_cast<std::uint32_t>(r % 1000);
    ASSERT_EQ(compiled.anyHit(ray, RaySource{}, tMax, &wrong), expected) << "ray " << r;
  }
  // Both answers occur often enough to matter.
  EXPECT_GT(blocked, 2000);
  EXPECT_LT(blocked, 18000);
}

TEST(Bvh, HitsAreIdenticalToBruteForce) {
  // A million rays in all, spread so that brute force stays affordable:
  // fewer rays for the larger scenes.
  RandomTransforms random(99);
  struct Size {
    int objects;
    int rays;
  };
  long long total = 0;
  for (Size size : {Size{1, 500000}, Size{10, 300000}, Size{100, 100000}, Size{1000, 89900},
                    Size{10000, 9000}, Size{100000, 1000}, Size{1000000, 100}}) {
    scene::Scene s = sceneLookingAt({0, 0, 1}, {0, 0, 0});
    double spread = std::cbrt(static_cast<double>(size.objects)) * 4.0;
    for (int i = 0; i < size.objects; ++i) {
      ObjectKind kind = static_cast<ObjectKind>(i % 4);
      if (kind == ObjectKind::Plane && i % 1000 != 0) kind = ObjectKind::Sphere;  // a few planes
      s.objects.push_back(object(
          kind, {scale(random.uniform(0.2, 1), random.uniform(0.2, 1), random.uniform(0.2, 1)),
                 rotateY(random.uniform(0, 3)), rotateX(random.uniform(0, 3)),
                 translate(random.uniform(-spread, spread), random.uniform(-spread, spread),
                           random.uniform(-spread, spread))}));
    }
    RenderScene compiled(s);
    for (int r = 0; r < scene::testing::randomCases(size.rays); ++r) {
      glm::dvec3 origin(random.uniform(-2, 2) * spread, random.uniform(-2, 2) * spread,
                        random.uniform(-2, 2) * spread);
      glm::dvec3 d = random.direction();
      if (r % 7 == 0) d = glm::dvec3(r % 2 ? 1.0 : -0.0, 0.0, -0.0);  // axis-parallel, signed zeros
      Ray ray{origin, d};
      std::optional<Hit> fast = compiled.closestHit(ray, RaySource{});
      std::optional<Hit> slow =
          compiled.closestHitBruteForce(ray, RaySource{}, std::numeric_limits<double>::infinity());
      ASSERT_EQ(fast.has_value(), slow.has_value()) << size.objects << " objects, ray " << r;
      if (fast) {
        ASSERT_EQ(fast->t, slow->t) << size.objects << " objects, ray " << r;
      }
      ++total;
    }
  }
  EXPECT_EQ(total, scene::testing::randomCases(1000000));
}

// A tracer that finds the closest object by its own search finishes with
// hitsOnObjects: the very hits closestHit makes, entering or leaving, each
// twice in a row (the second from the first's toWorldLinear).
TEST(RenderScene, HitsOnObjectsAreClosestHitsHitsBitForBit) {
  RandomTransforms random(7);
  scene::Scene s = sceneLookingAt({0, 0, 1}, {0, 0, 0});
  for (int i = 0; i < 300; ++i) {
    s.objects.push_back(object(
        static_cast<ObjectKind>(i % 4),
        {scale(random.uniform(0.5, 3), random.uniform(0.5, 3), 1.0), rotateY(random.uniform(0, 3)),
         translate(random.uniform(-20, 20), random.uniform(-20, 20), random.uniform(-20, 20))}));
  }
  RenderScene compiled(s);
  auto sameBits = [](const Hit& a, const Hit& b) {
    const double x[] = {a.t,
                        a.point.x,
                        a.point.y,
                        a.point.z,
                        a.pointError.x,
                        a.pointError.y,
                        a.pointError.z,
                        a.normal.x,
                        a.normal.y,
                        a.normal.z};
    const double y[] = {b.t,
                        b.point.x,
                        b.point.y,
                        b.point.z,
                        b.pointError.x,
                        b.pointError.y,
                        b.pointError.z,
                        b.normal.x,
                        b.normal.y,
                        b.normal.z};
    return std::memcmp(x, y, sizeof x) == 0 && a.object == b.object && a.fromInside == b.fromInside;
  };
  // Every ray twice in a row, in one batch, and a ray with no object.
  const double infinity = std::numeric_limits<double>::infinity();
  std::vector<std::optional<Hit>> expected;
  std::vector<std::uint32_t> objects;
  std::vector<Ray> rays;
  std::vector<double> tMaxes;
  for (int r = 0; r < 20000; ++r) {
    Ray ray{{random.uniform(-25, 25), random.uniform(-25, 25), random.uniform(-25, 25)},
            random.direction()};
    std::optional<Hit> hit = compiled.closestHit(ray, RaySource{});
    for (int k = 0; k < 2; ++k) {
      expected.push_back(hit);
      objects.push_back(hit ? hit->object : RaySource::kNone);
      rays.push_back(ray);
      tMaxes.push_back(hit ? std::nextafter(hit->t, infinity) : infinity);
    }
  }
  std::vector<std::optional<Hit>> found(rays.size());
  compiled.hitsOnObjects(objects.data(), rays.data(), tMaxes.data(), static_cast<int>(rays.size()),
                         found.data());
  int hits = 0, fromInside = 0;
  for (std::size_t k = 0; k < found.size(); ++k) {
    ASSERT_EQ(found[k].has_value(), expected[k].has_value()) << "ray " << k;
    if (!expected[k]) continue;
    ASSERT_TRUE(sameBits(*found[k], *expected[k])) << "ray " << k;
    ++hits;
    fromInside += expected[k]->fromInside;
  }
  EXPECT_GT(hits, 1000);
  EXPECT_GT(fromInside, 0);
}

// The compiled scene numbers its objects the planes first, in the scene's
// order, then the bounded objects in the BVH's order, whose items are then
// numbered by their place; sceneObject names each one's place in the scene,
// and every record is that object's. The layout is the BVH's, so the same
// for any thread count.
TEST(RecordOrder, PlanesFirstThenTheBvhsOrderEachRecordItsSceneObjects) {
  RandomTransforms random(5);
  scene::Scene s = sceneLookingAt({0, 0, 1}, {0, 0, 0});
  const int count = 20000;  // past the size at which records and BVH are built in parts
  double spread = std::cbrt(static_cast<double>(count)) * 4.0;
  for (int i = 0; i < count; ++i) {
    ObjectKind kind = i % 997 == 3 ? ObjectKind::Plane : static_cast<ObjectKind>(1 + i % 3);
    scene::Material m;
    m.colour = glm::dvec3(i, 0.5, 0.25);
    m.transparency = i == count - 1 ? 0.5 : 0.0;
    s.objects.push_back(
        object(kind,
               {scale(random.uniform(0.2, 1), random.uniform(0.2, 1), random.uniform(0.2, 1)),
                rotateY(random.uniform(0, 3)),
                translate(random.uniform(-spread, spread), random.uniform(-spread, spread),
                          random.uniform(-spread, spread))},
               m));
  }
  RenderScene one(s, 1);
  RenderScene four(s, 4);
  EXPECT_TRUE(one.hasTransparency());
  std::vector<int> seen(count, 0);
  std::uint32_t planes = 0;
  for (std::uint32_t r = 0; r < static_cast<std::uint32_t>(count); ++r) {
    std::uint32_t inScene = one.sceneObject(r);
    ASSERT_LT(inScene, static_cast<std::uint32_t>(count));
    ++seen[inScene];
    ASSERT_EQ(four.sceneObject(r), inScene) << "object " << r;
    const scene::Object& o = s.objects[inScene];
    ASSERT_EQ(one.objects()[r].kind, o.kind) << "object " << r;
    ASSERT_EQ(one.objects()[r].translation, glm::dvec3(o.matrix[3])) << "object " << r;
    ASSERT_EQ(one.objects()[r].toLocal, renderObject(o.kind, o.matrix).toLocal) << "object " << r;
    ASSERT_EQ(one.material(r), o.material) << "object " << r;
    if (o.kind == ObjectKind::Plane) {
      // The planes come first, in the scene's order.
      ASSERT_EQ(r, planes++);
      if (r > 0) {
        ASSERT_GT(inScene, one.sceneObject(r - 1));
      }
    }
  }
  for (int i = 0; i < count; ++i) ASSERT_EQ(seen[i], 1) << "scene object " << i;
  EXPECT_EQ(one.planeObjects().size(), planes);
  ASSERT_EQ(one.boundedObjects().size(), count - planes);
  EXPECT_TRUE(one.bvh().order().empty());
  ASSERT_EQ(one.bvh().itemCount(), count - planes);
  for (std::uint32_t k = 0; k < one.bvh().itemCount(); ++k) {
    ASSERT_EQ(one.boundedObjects()[k], planes + k);
  }
  // Each leaf holds the boxes of the objects its items name.
  for (const BvhNode& node : one.bvh().nodes()) {
    for (std::uint32_t i = 0; i < node.count; ++i) {
      std::uint32_t object = one.boundedObjects()[node.offset + i];
      Bounds box = *worldBounds(one.objects()[object]);
      for (int a = 0; a < 3; ++a) {
        ASSERT_LE(node.planes[a], box.lo[a]) << "object " << object;
        ASSERT_GE(node.planes[3 + a], box.hi[a]) << "object " << object;
      }
    }
  }
}

TEST(RestingOnAPlane, NoLightGapAtTheContact) {
  // A unit sphere and a cube resting on the floor y = 0, the light up and
  // to the right: floor points just left of each contact lie in shadow.
  for (ObjectKind kind : {ObjectKind::Sphere, ObjectKind::Cube}) {
    scene::Scene s = sceneLookingAt({0, 5, 5}, {0, 0, 0});
    s.objects.push_back(object(ObjectKind::Plane));
    s.objects.push_back(object(kind, {translate(0, 1, 0)}));
    s.lights.push_back(light({10, 10, 0}));
    RenderScene compiled(s);
    double edge = kind == ObjectKind::Cube ? -1.0 : 0.0;
    for (double gap : {1e-3, 1e-6, 1e-9, 1e-12}) {
      // The floor seen from below (planes are two-sided): the shadow ray
      // still leaves on the light's side.
      glm::dvec3 onFloor(edge - gap, 0, 0);
      std::optional<Hit> hit =
          compiled.closestHit(Ray{onFloor - glm::dvec3(0, 1, 0), {0, 1, 0}}, RaySource{});
      ASSERT_TRUE(hit.has_value());
      ASSERT_EQ(hit->object, 0u);
      Tracer tracer(compiled, 0);
      TraceContext context;
      EXPECT_TRUE(tracer.shadowed(*hit, 0, context)) << objectKindName(kind) << " gap " << gap;
    }
  }
}

TEST(ThinGlassSlab, ExitPointAndDirectionFollowSnellsLaw) {
  // A slab 1e-3 thick (y from -5e-4 to 5e-4) of index 1.5, a ray at 40
  // degrees: it leaves parallel to how it came, shifted by
  // h * sin(i - t) / cos(t).
  double h = 1e-3;
  scene::Scene s = sceneLookingAt({0, 1, 0}, {0, 0, 0});
  scene::Material glass;
  glass.transparency = 1.0;
  glass.ri = 1.5;
  s.objects.push_back(object(ObjectKind::Cube, {scale(10, h / 2, 10)}, glass));
  RenderScene compiled(s);
  double i = 40.0 * 3.141592653589793 / 180.0;
  glm::dvec3 d(std::sin(i), -std::cos(i), 0.0);
  glm::dvec3 entry(0.0, h / 2, 0.0);
  std::optional<Hit> in = compiled.closestHit(Ray{entry - d, d}, RaySource{});
  ASSERT_TRUE(in.has_value());
  glm::dvec3 inside;
  ASSERT_TRUE(refractDirection(d, in->normal, 1.0, 1.5, inside));
  Ray through{offsetRayOrigin(in->point, in->pointError, in->normal, inside), inside};
  std::optional<Hit> out = compiled.closestHit(through, RaySource{in->object, true});
  ASSERT_TRUE(out.has_value());
  ASSERT_TRUE(out->fromInside);
  glm::dvec3 leaving;
  ASSERT_TRUE(refractDirection(inside, -out->normal, 1.5, 1.0, leaving));

  double t = std::asin(std::sin(i) / 1.5);
  glm::dvec3 exactExit(h * std::tan(t), -h / 2, 0.0);
  EXPECT_LT(glm::length(out->point - exactExit), 1e-6 * h);
  EXPECT_LT(glm::length(leaving - d), 1e-6);
  // The lateral shift against the unbent line.
  double shift = h * std::sin(i - t) / std::cos(t);
  glm::dvec3 unbent = entry + d * (h / std::cos(i));
  EXPECT_NEAR(glm::length(glm::cross(out->point - unbent, d)), shift, 1e-6 * h);
}

TEST(ParallelMirrors, FiftyBouncesLandWhereTheyShould) {
  // Mirrors z = -1 and z = +1; from the origin along (a, 0, -1) the k-th
  // bounce is at x = a (2k + 1), z = -+1 alternately.
  scene::Scene s = sceneLookingAt({0, 0, 0}, {0, 0, -1});
  scene::Material mirror;
  mirror.reflectivity = 1.0;
  s.objects.push_back(
      object(ObjectKind::Plane, {rotateX(1.5707963267948966), translate(0, 0, -1)}, mirror));
  s.objects.push_back(
      object(ObjectKind::Plane, {rotateX(1.5707963267948966), translate(0, 0, 1)}, mirror));
  RenderScene compiled(s);
  double a = 0.37;
  Ray ray{{0, 0, 0}, glm::normalize(glm::dvec3(a, 0, -1))};
  RaySource source;
  for (int k = 0; k < 50; ++k) {
    std::optional<Hit> hit = compiled.closestHit(ray, source);
    ASSERT_TRUE(hit.has_value()) << k;
    double x = a * (2 * k + 1);
    EXPECT_NEAR(hit->point.x, x, 1e-13 * (2 * k + 1)) << k;
    EXPECT_EQ(hit->point.z, k % 2 == 0 ? -1.0 : 1.0) << k;
    glm::dvec3 r = glm::reflect(ray.direction, hit->normal);
    ray = Ray{offsetRayOrigin(hit->point, hit->pointError, hit->normal, r), r};
    source = RaySource{hit->object, glm::dot(r, hit->normal) < 0.0};
  }
}

TEST(LightOnASurface, TheSurfaceItLiesOnCastsNoShadow) {
  // The light lies on the floor under a sphere, and on a cube's top face
  // under another: the undersides facing them are lit.
  for (bool onCube : {false, true}) {
    scene::Scene s = sceneLookingAt({0, 0, 5}, {0, 0, 0});
    if (onCube) {
      s.objects.push_back(object(ObjectKind::Cube, {translate(0, -1, 0)}));  // top face y = 0
    } else {
      s.objects.push_back(object(ObjectKind::Plane));
    }
    s.objects.push_back(object(ObjectKind::Sphere, {translate(0, 2, 0)}));
    s.lights.push_back(light({0, 0, 0}));
    RenderScene compiled(s);
    std::optional<Hit> bottom = compiled.closestHit(Ray{{0, 1.5, 0}, {0, 1, 0}}, RaySource{});
    ASSERT_TRUE(bottom.has_value());
    ASSERT_TRUE(bottom->fromInside);  // from inside the sphere, up
    std::optional<Hit> under = compiled.closestHit(Ray{{0.0, 0.5, 0.0}, {0, 1, 0}}, RaySource{});
    ASSERT_TRUE(under.has_value());
    Tracer tracer(compiled, 0);
    TraceContext context;
    EXPECT_FALSE(tracer.shadowed(*under, 0, context)) << onCube;
  }
}

// The searches test planes from the y row of their transforms alone
// (RenderScene::intersectPlane); brute force tests them as any object. Rays
// leaving a plane, rays stopped short, rays in a plane's own directions and
// packets of them all end at brute force's hit, bit for bit.
TEST(PlaneHits, TheSearchesMeetPlanesAsBruteForceDoes) {
  RandomTransforms random(2026);
  scene::Scene s = sceneLookingAt({0, 0, 5}, {0, 0, 0});
  for (int i = 0; i < 12; ++i) {
    ObjectKind kind = i % 4 == 0 ? ObjectKind::Cube : ObjectKind::Plane;
    s.objects.push_back(object(
        kind,
        {scale(random.uniform(0.2, 3), random.uniform(1e-3, 3), random.uniform(0.2, 3)),
         rotateX(random.uniform(-3.2, 3.2)), rotateZ(random.uniform(-3.2, 3.2)),
         translate(random.uniform(-1e3, 1e3), random.uniform(-5, 5), random.uniform(-5, 5))}));
  }
  RenderScene compiled(s);
  const std::uint32_t planes = static_cast<std::uint32_t>(compiled.planeObjects().size());
  ASSERT_EQ(planes, 9u);
  constexpr int kPacket = Bvh::kPacketSize;
  Ray rays[kPacket];
  RaySource sources[kPacket];
  std::optional<Hit> expected[kPacket];
  int met = 0;
  for (int r = 0; r < scene::testing::randomCases(200000); ++r) {
    int lane = r % kPacket;
    glm::dvec3 origin(random.uniform(-1e3, 1e3), random.uniform(-8, 8), random.uniform(-8, 8));
    glm::dvec3 d = random.direction();
    RaySource source{};
    if (r % 3 == 0) {
      // Leaving a plane, from a point on it, or along it.
      std::uint32_t plane = static_cast<std::uint32_t>(r / 3) % planes;
      glm::dmat3 linear = compiled.linearToWorld(plane);
      glm::dvec3 translation(s.objects[compiled.sceneObject(plane)].matrix[3]);
      origin = translation + linear * glm::dvec3(random.uniform(-9, 9), 0, random.uniform(-9, 9));
      if (r % 2 == 0) d = linear * glm::dvec3(random.uniform(-1, 1), 0, random.uniform(-1, 1));
      source = RaySource{plane, false};
    }
    double tMax = r % 5 == 0 ? random.uniform(0, 20) : std::numeric_limits<double>::infinity();
    rays[lane] = Ray{origin, d};
    sources[lane] = source;
    expected[lane] = compiled.closestHitBruteForce(rays[lane], source, tMax);
    std::optional<Hit> found = compiled.closestHit(rays[lane], source, tMax);
    ASSERT_EQ(found.has_value(), expected[lane].has_value()) << "ray " << r;
    if (found) {
      met += found->object < planes;
      ASSERT_EQ(found->object, expected[lane]->object) << "ray " << r;
      ASSERT_EQ(found->t, expected[lane]->t) << "ray " << r;
      ASSERT_EQ(found->point, expected[lane]->point) << "ray " << r;
    }
    ASSERT_EQ(compiled.anyHit(rays[lane], source, tMax), expected[lane].has_value()) << "ray " << r;
    if (lane == kPacket - 1) {
      std::optional<Hit> packet[kPacket];
      compiled.closestHits(rays, sources, kPacket, packet);
      for (int k = 0; k < kPacket; ++k) {
        std::optional<Hit> alone = compiled.closestHitBruteForce(
            rays[k], sources[k], std::numeric_limits<double>::infinity());
        ASSERT_EQ(packet[k].has_value(), alone.has_value()) << "ray " << r - lane + k;
        if (alone) {
          ASSERT_EQ(packet[k]->t, alone->t) << "ray " << r - lane + k;
        }
      }
    }
  }
  EXPECT_GT(met, scene::testing::randomCases(200000) / 10);
}

// A plane's normal is made once, per plane (RenderScene::hitOn): with
// several planes between other objects, each hit carries the normal of the
// plane it met, the inverse transpose's image of +y.
TEST(PlaneHits, EachCarriesTheNormalOfItsOwnPlane) {
  RandomTransforms random(77);
  scene::Scene s = sceneLookingAt({0, 0, 5}, {0, 0, 0});
  for (int i = 0; i < 12; ++i) {
    ObjectKind kind = i % 3 == 0 ? ObjectKind::Sphere : ObjectKind::Plane;
    s.objects.push_back(object(
        kind, {scale(random.uniform(0.5, 2), random.uniform(0.5, 2), 1),
               rotateX(random.uniform(-3.2, 3.2)), rotateZ(random.uniform(-3.2, 3.2)),
               translate(random.uniform(-5, 5), random.uniform(-5, 5), random.uniform(-5, 5))}));
  }
  RenderScene compiled(s);
  std::vector<int> planeHits(s.objects.size(), 0);
  for (int i = 0; i < 4000; ++i) {
    glm::dvec3 origin(random.uniform(-8, 8), random.uniform(-8, 8), random.uniform(-8, 8));
    std::optional<Hit> hit = compiled.closestHit(Ray{origin, random.direction()}, RaySource{});
    if (!hit) continue;
    std::uint32_t inScene = compiled.sceneObject(hit->object);
    if (s.objects[inScene].kind != ObjectKind::Plane) continue;
    ++planeHits[inScene];
    glm::dmat3 linear(s.objects[inScene].matrix);
    glm::dvec3 expected =
        glm::normalize(glm::transpose(glm::inverse(linear)) * glm::dvec3(0, 1, 0));
    EXPECT_NEAR(glm::length(hit->normal - expected), 0.0, 1e-12) << inScene;
    EXPECT_NEAR(glm::dot(hit->normal, linear[0]), 0.0, 1e-12 * glm::length(linear[0]));
  }
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    if (s.objects[i].kind == ObjectKind::Plane) {
      EXPECT_GT(planeHits[i], 0) << i;
    }
  }
}

TEST(CameraInside, EachSolidIsSeenFromWithinWithFiniteNormals) {
  for (ObjectKind kind : {ObjectKind::Sphere, ObjectKind::Cube, ObjectKind::Cylinder}) {
    scene::Scene s = sceneLookingAt({0, 0, 0}, {0.3, -0.2, -1});
    s.objects.push_back(object(kind, {scale(2, 3, 4), rotateY(0.4)}));
    RenderScene compiled(s);
    RandomTransforms random(5);
    for (int i = 0; i < 2000; ++i) {
      std::optional<Hit> hit = compiled.closestHit(Ray{{0, 0, 0}, random.direction()}, RaySource{});
      ASSERT_TRUE(hit.has_value()) << objectKindName(kind);
      ASSERT_TRUE(hit->fromInside);
      ASSERT_TRUE(std::isfinite(hit->normal.x + hit->normal.y + hit->normal.z));
    }
  }
  // On a plane, the camera sees nothing of it (nothing closer than the eye).
  scene::Scene s = sceneLookingAt({0, 0, 0}, {1, 0, 0});
  s.objects.push_back(object(ObjectKind::Plane));
  RenderScene compiled(s);
  EXPECT_FALSE(compiled.closestHit(Ray{{0, 0, 0}, {1, -1, 0}}, RaySource{}).has_value());
}

}  // namespace
}  // namespace render
