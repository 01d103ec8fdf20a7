// Packets of rays (Bvh::traversePacket, RenderScene::closestHits) find what
// each ray finds alone, bit for bit, and images do not change with them.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <random>
#include <span>
#include <vector>

#include "renderer/bvh_packet.h"
#include "renderer/default_scene.h"
#include "renderer/render.h"
#include "renderer/render_scene.h"
#include "renderer/test_scenes.h"

namespace render {
namespace {

using namespace render::testing;
using scene::ObjectKind;

// closestHits against closestHit, ray by ray.
int expectSameHits(const RenderScene& compiled, const std::vector<Ray>& rays,
                   const std::vector<RaySource>& sources, const std::string& where) {
  std::vector<std::optional<Hit>> packet(rays.size());
  compiled.closestHits(rays.data(), sources.data(), static_cast<int>(rays.size()), packet.data());
  int hits = 0;
  for (std::size_t k = 0; k < rays.size(); ++k) {
    std::optional<Hit> alone = compiled.closestHit(rays[k], sources[k]);
    expectSameHit(packet[k], alone, where + " ray " + std::to_string(k));
    hits += alone ? 1 : 0;
  }
  return hits;
}

TEST(Packets, CoherentRaysFindTheirOwnClosestHits) {
  Random random(41);
  int hits = 0;
  int total = 0;
  for (int trial = 0; trial < 40; ++trial) {
    RenderScene compiled(randomScene(random, 1 + random.below(300)));
    for (int packet = 0; packet < 50; ++packet) {
      // A camera-like fan: one origin, directions a little apart, in
      // packets of every size from 1 to 11 (lanes left empty in the last).
      glm::dvec3 origin = random.point(15.0);
      glm::dvec3 towards = random.direction();
      double spread = std::pow(10.0, random.uniform(-6, -1));
      int count = 1 + random.below(11);
      std::vector<Ray> rays;
      for (int k = 0; k < count; ++k) {
        rays.push_back(Ray{origin, glm::normalize(towards + spread * random.direction())});
      }
      std::vector<RaySource> sources(rays.size());
      hits += expectSameHits(compiled, rays, sources, "trial " + std::to_string(trial));
      total += count;
    }
  }
  // The rays meet objects, most of them, so that hits are compared.
  EXPECT_GT(hits, total / 4);
}

TEST(Packets, RaysAtObjectsOfEveryScaleFindTheirOwnClosestHits) {
  Random random(47);
  int hits = 0;
  int total = 0;
  for (int trial = 0; trial < 30; ++trial) {
    // Scales from 1e-4 to 1e4 and origins up to 1e8 (as the single-ray
    // tests of render_scene_test.cpp), a packet aimed at each object.
    scene::Scene s = sceneLookingAt({0, 0, 1}, {0, 0, 0});
    int count = 1 + random.below(60);
    double base = random.uniform(-4, 4);
    for (int i = 0; i < count; ++i) {
      auto factor = [&] {
        return std::pow(10.0, std::clamp(base + random.uniform(-1, 1), -4.0, 4.0));
      };
      glm::dvec3 at = random.point(std::pow(10.0, random.uniform(0, 8)));
      ObjectKind kind = std::array{ObjectKind::Sphere, ObjectKind::Cube, ObjectKind::Cylinder,
                                   ObjectKind::Plane}[random.below(4)];
      s.objects.push_back(
          object(kind, {scale(factor(), factor(), factor()), rotateX(random.uniform(-3.2, 3.2)),
                        rotateY(random.uniform(-3.2, 3.2)), rotateZ(random.uniform(-3.2, 3.2)),
                        translate(at.x, at.y, at.z)}));
    }
    RenderScene compiled(s);
    for (const scene::Object& target : s.objects) {
      glm::dvec3 centre(target.matrix[3]);
      double size = glm::length(glm::dvec3(target.matrix[0]));
      glm::dvec3 origin = centre - size * 10.0 * random.direction();
      std::vector<Ray> rays;
      for (int k = 0; k < 4; ++k) {
        glm::dvec3 aim = centre + size * random.uniform(0, 1.5) * random.direction();
        rays.push_back(Ray{origin, aim - origin});
      }
      std::vector<RaySource> sources(rays.size());
      hits += expectSameHits(compiled, rays, sources, "trial " + std::to_string(trial));
      total += 4;
    }
  }
  EXPECT_GT(hits, total / 4);
}

TEST(Packets, RaysOfMixedSignsAndEveryOriginFindTheirOwnClosestHits) {
  Random random(42);
  for (int trial = 0; trial < 40; ++trial) {
    RenderScene compiled(randomScene(random, 1 + random.below(200)));
    for (int packet = 0; packet < 50; ++packet) {
      std::vector<Ray> rays;
      int count = 1 + random.below(8);
      for (int k = 0; k < count; ++k) rays.push_back(Ray{random.point(15.0), random.direction()});
      std::vector<RaySource> sources(rays.size());
      expectSameHits(compiled, rays, sources, "trial " + std::to_string(trial));
    }
  }
}

TEST(Packets, RaysInBoxPlanesAndAlongAxesFindTheirOwnClosestHits) {
  Random random(43);
  for (int trial = 0; trial < 30; ++trial) {
    RenderScene compiled(randomScene(random, 2 + random.below(100)));
    std::span<const BvhNode> nodes = compiled.bvh().nodes();
    ASSERT_FALSE(nodes.empty());
    for (int packet = 0; packet < 50; ++packet) {
      // Origins on a node's face planes, directions with components of +0
      // and -0 (a ray lying in the plane), of the same sign in the packet
      // or not.
      const BvhNode& node = nodes[random.below(static_cast<int>(nodes.size()))];
      int axis = random.below(3);
      std::vector<Ray> rays;
      int count = 1 + random.below(4);
      double zero = random.below(2) == 0 ? 0.0 : -0.0;
      for (int k = 0; k < count; ++k) {
        glm::dvec3 origin = random.point(15.0);
        origin[axis] = node.planes[axis + 3 * random.below(2)];
        glm::dvec3 d = random.direction();
        d[axis] = random.below(4) == 0 ? -zero : zero;
        if (random.below(3) == 0) d[(axis + 1) % 3] = 0.0;
        if (d == glm::dvec3(0.0)) d[(axis + 2) % 3] = 1.0;
        rays.push_back(Ray{origin, d});
      }
      std::vector<RaySource> sources(rays.size());
      expectSameHits(compiled, rays, sources, "trial " + std::to_string(trial));
    }
  }
}

TEST(Packets, RaysLeavingSurfacesFindTheirOwnClosestHits) {
  Random random(44);
  int compared = 0;
  for (int trial = 0; trial < 30; ++trial) {
    RenderScene compiled(randomScene(random, 10 + random.below(200)));
    for (int packet = 0; packet < 40; ++packet) {
      // Rays spawned from hits, inward and outward, as reflected and
      // refracted rays are: each leaves its own source.
      std::vector<Ray> rays;
      std::vector<RaySource> sources;
      glm::dvec3 origin = random.point(15.0);
      glm::dvec3 towards = random.direction();
      for (int k = 0; k < 4; ++k) {
        Ray camera{origin, glm::normalize(towards + 0.01 * random.direction())};
        std::optional<Hit> hit = compiled.closestHit(camera, RaySource{});
        if (!hit) continue;
        glm::dvec3 d = glm::normalize(towards + 0.05 * random.direction());
        if (random.below(2) == 0) d = -d;
        rays.push_back(Ray{hit->point, d});
        sources.push_back(RaySource{hit->object, glm::dot(d, hit->normal) < 0.0});
      }
      if (rays.empty()) continue;
      compared += static_cast<int>(rays.size());
      expectSameHits(compiled, rays, sources, "trial " + std::to_string(trial));
    }
  }
  EXPECT_GT(compared, 1000);
}

// The leaves each lane visits, and the tMax it has before each, are those of
// Bvh::traverse for its ray alone, whatever the visitor returns: a made-up
// tMax that shrinks at some items, and stops a ray at others; with leaves
// of one box and of several (odd trials: Bvh::kCompactNodeCost), where the
// tMax changes between the items of a leaf.
TEST(Packets, EachLaneVisitsTheItemsOfItsOwnTraversalInOrder) {
  Random random(45);
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<Bounds> boxes;
    int count = 1 + random.below(500);
    for (int i = 0; i < count; ++i) {
      glm::dvec3 centre = random.point(10.0);
      glm::dvec3 half(random.uniform(0.01, 2), random.uniform(0.01, 2), random.uniform(0.01, 2));
      boxes.push_back(Bounds{centre - half, centre + half});
    }
    Bvh bvh(boxes, 1, trial % 2 ? Bvh::kCompactNodeCost : Bvh::kNodeCost);
    // A tMax per item from its index: some items end the ray.
    auto tMaxAt = [&](std::uint32_t item, double tMax) {
      if (item % 17 == 3) return -1.0;
      double t = 5.0 + static_cast<double>((item * 7919u) % 40u);
      return t < tMax ? t : tMax;
    };
    for (int packet = 0; packet < 40; ++packet) {
      BoxRay rays[Bvh::kPacketSize];
      double tMax[Bvh::kPacketSize];
      int lanes = 1 + random.below(Bvh::kPacketSize);
      glm::dvec3 origin = random.point(15.0);
      glm::dvec3 towards = random.direction();
      bool mixed = random.below(4) == 0;
      for (int k = 0; k < lanes; ++k) {
        glm::dvec3 d = mixed ? random.direction() : towards + 0.2 * random.direction();
        rays[k] = BoxRay{origin, 1.0 / d};
        tMax[k] = random.below(3) == 0 ? 20.0 : std::numeric_limits<double>::infinity();
      }
      std::vector<std::vector<std::pair<std::uint32_t, double>>> alone(lanes), together(lanes);
      for (int k = 0; k < lanes; ++k) {
        double current = tMax[k];
        bvh.traverse(rays[k], tMax[k], [&](std::uint32_t item) {
          alone[k].emplace_back(item, current);
          current = tMaxAt(item, current);
          return current;
        });
      }
      double current[Bvh::kPacketSize];
      for (int k = 0; k < lanes; ++k) current[k] = tMax[k];
      bvh.traversePacket(rays, lanes, tMax, [&](int lane, std::uint32_t item) {
        EXPECT_LT(lane, lanes);
        together[lane].emplace_back(item, current[lane]);
        current[lane] = tMaxAt(item, current[lane]);
        return current[lane];
      });
      for (int k = 0; k < lanes; ++k) EXPECT_EQ(together[k], alone[k]) << "lane " << k;
    }
  }
}

// Shadow rays toward one light from points near each other, in packets of
// every size (RenderScene::anyHits), against anyHit ray by ray, with and
// without a hint.
TEST(Packets, ShadowRaysAnswerAsEachAlone) {
  Random random(47);
  int blocked = 0;
  int total = 0;
  for (int trial = 0; trial < 40; ++trial) {
    scene::Scene s = randomScene(random, 1 + random.below(300));
    RenderScene compiled(s, 0, false);
    glm::dvec3 light = random.point(20.0);
    for (int packet = 0; packet < 50; ++packet) {
      glm::dvec3 centre = random.point(15.0);
      double spread = std::pow(10.0, random.uniform(-4, 0.5));
      int count = 1 + random.below(11);
      std::vector<Ray> rays;
      std::vector<double> tMaxes;
      for (int k = 0; k < count; ++k) {
        glm::dvec3 origin = centre + spread * random.direction();
        rays.push_back(Ray{origin, light - origin});
        tMaxes.push_back(random.below(4) == 0 ? random.uniform(0.1, 1.0) : 1.0);
      }
      std::vector<RaySource> sources(rays.size());
      std::uint32_t hint = random.below(2) == 0 ? RaySource::kNone
                                                : static_cast<std::uint32_t>(random.below(
                                                      static_cast<int>(compiled.objects().size())));
      bool packed[11] = {};
      compiled.anyHits(rays.data(), sources.data(), tMaxes.data(), count, packed, &hint);
      for (int k = 0; k < count; ++k) {
        bool alone = compiled.anyHit(rays[k], sources[k], tMaxes[k]);
        EXPECT_EQ(packed[k], alone) << "trial " << trial << " ray " << k;
        blocked += alone ? 1 : 0;
      }
      total += count;
    }
  }
  // Some rays are blocked and some are not, so that both answers are
  // compared.
  EXPECT_GT(blocked, total / 10);
  EXPECT_LT(blocked, total - total / 10);
}

// Whole images with and without packets: every channel, the coverage and
// the ray counts the same; with the lights' direction grids or without
// them, when the camera rays' shadow rays go as packets too.
void expectSameRender(const scene::Scene& s, RenderSettings settings, bool lightGrids) {
  RenderScene compiled(s, 0, lightGrids);
  RenderStatistics withStats;
  RenderStatistics withoutStats;
  settings.packets = true;
  Image with = renderImage(compiled, settings, &withStats);
  settings.packets = false;
  Image without = renderImage(compiled, settings, &withoutStats);
  EXPECT_EQ(with.rgb, without.rgb);
  EXPECT_EQ(with.coverage, without.coverage);
  EXPECT_EQ(withStats.rays.primary, withoutStats.rays.primary);
  EXPECT_EQ(withStats.rays.secondary, withoutStats.rays.secondary);
  EXPECT_EQ(withStats.rays.shadow, withoutStats.rays.shadow);
  EXPECT_EQ(withStats.rays.pruned, withoutStats.rays.pruned);
  EXPECT_EQ(withStats.rays.cut, withoutStats.rays.cut);
  EXPECT_EQ(withStats.retracedPixels, withoutStats.retracedPixels);
}

TEST(Packets, TheDefaultSceneIsTheSameImageWithAndWithoutPackets) {
  RenderSettings settings;
  settings.width = 131;  // rows of tiles that end short of a packet
  settings.height = 67;
  settings.coverage = true;
  settings.threads = 2;
  for (int spp : {1, 3}) {
    settings.samplesPerPixel = spp;
    settings.seed = 5;
    for (bool grids : {true, false}) expectSameRender(defaultScene(), settings, grids);
  }
}

TEST(Packets, RandomScenesAreTheSameImageWithAndWithoutPackets) {
  Random random(46);
  for (int trial = 0; trial < 6; ++trial) {
    scene::Scene s = randomScene(random, 1 + random.below(150));
    RenderSettings settings;
    settings.width = 70;
    settings.height = 45;
    settings.coverage = true;
    settings.threads = 1;
    settings.samplesPerPixel = 1 + random.below(3);
    settings.seed = static_cast<std::uint64_t>(trial);
    for (bool grids : {true, false}) expectSameRender(s, settings, grids);
  }
}

}  // namespace
}  // namespace render
