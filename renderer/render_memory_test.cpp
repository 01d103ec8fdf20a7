#include "renderer/render_memory.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <vector>

#include "renderer/bvh.h"
#include "renderer/render.h"
#include "renderer/render_scene.h"
#include "renderer/test_scenes.h"

namespace render {
namespace {

// The estimate of a render of `objects` objects with `materials` distinct
// materials and `lights` lights in a `width` x `height` image at 1 sample a
// pixel.
RenderMemoryEstimate estimate(std::uint64_t objects, std::uint64_t lights, int width, int height,
                              std::uint64_t materials = 1) {
  return estimateRenderMemory({.objects = objects,
                               .lights = lights,
                               .materials = materials,
                               .width = width,
                               .height = height,
                               .cameraSamples = static_cast<std::uint64_t>(width) * height});
}

TEST(RenderMemory, ImageGrowsWithThePixelsAndSceneAndBvhWithTheObjects) {
  RenderMemoryEstimate empty = estimate(0, 0, 1, 1, 0);
  EXPECT_EQ(empty.scene, 0u);
  EXPECT_EQ(empty.bvh, 0u);
  EXPECT_GT(empty.image, 0u);

  RenderMemoryEstimate small = estimate(10, 1, 640, 480);
  RenderMemoryEstimate big = estimate(1'000'000, 1, 640, 480);
  EXPECT_EQ(small.image, big.image);
  EXPECT_EQ(estimate(2000, 0, 1, 1, 2000).scene, 2 * estimate(1000, 0, 1, 1, 1000).scene);
  EXPECT_EQ(estimate(2000, 0, 1, 1).bvh, 2 * estimate(1000, 0, 1, 1).bvh);
  // At least the float image, and each object's record (a 3x3 double
  // matrix and a translation), colour and index in the scene: 132 bytes.
  EXPECT_GE(small.image, 640u * 480 * 12);
  EXPECT_GE(big.scene, 1'000'000u * 132);
  EXPECT_GT(big.bvh, small.bvh);
  EXPECT_EQ(big.total(), big.image + big.scene + big.bvh);

  RenderMemoryEstimate wide = estimate(10, 1, 1280, 960);
  EXPECT_EQ(wide.image, 4 * small.image);
}

// The figures of each part, from the types' sizes: the image three times
// (the floats, the file's copy, the file's bytes).
TEST(RenderMemory, ThePartsAreTheTypesSizes) {
  RenderMemoryEstimate e = estimate(1000, 7, 64, 46, 3);
  EXPECT_EQ(e.image, 64u * 46 * 3 * (3 * sizeof(float)));
  // The records, their colours and indices in the scene; the materials'
  // table and their numbers by their properties; the lights.
  std::uint64_t material = sizeof(scene::Material) + 7 * 8 + 4 + 4 * sizeof(void*);
  EXPECT_EQ(e.scene, 1000 * (sizeof(RenderObject) + sizeof(glm::dvec3) + sizeof(std::uint32_t)) +
                         3 * material + 7 * sizeof(RenderLight));
  // The BVH's build, then the reorder's byte a record and its stations'
  // records (one in 32); 2,944 samples build no light grids for 1,000
  // objects.
  EXPECT_EQ(e.bvh, Bvh::bytesFor(1000) + 1000 * 6);
  // 3,000 samples do: 7 lights' grids of at most 8 cells a box on each
  // face: per cell its start, count and full flag, per entry an index (16
  // a box, plus one a cell, at most), and while two build at once, 6
  // ranges of cells a box each in a vector that may double; and each
  // item's leaf.
  RenderMemoryEstimate gridded = estimateRenderMemory({.objects = 1000,
                                                       .lights = 7,
                                                       .materials = 3,
                                                       .width = 64,
                                                       .height = 46,
                                                       .cameraSamples = 3000});
  std::uint64_t cells = 6 * 8 * 1000 + 1;
  std::uint64_t grids = 7 * (cells * 13 + (16 * 1000 + cells) * 4) + 1000 * (2 * 2 * 6 * 20 + 4);
  EXPECT_EQ(gridded.bvh, e.bvh + grids);
  EXPECT_EQ(estimate(5, 0, 0, -3).image, 0u);  // no pixels
}

// What the constructors actually hold stays within what bytesFor says: the
// nodes as reserved (never grown past it), the items, the objects, the
// lights.
TEST(RenderMemory, TheEstimateBoundsWhatIsAllocated) {
  scene::Scene s = testing::sceneLookingAt({0, 0, 10}, {0, 0, 0});
  for (int i = 0; i < 300; ++i) {
    s.objects.push_back(
        testing::object(i % 3 == 0 ? scene::ObjectKind::Cube : scene::ObjectKind::Sphere,
                        {testing::scale(0.1), testing::translate(i, i % 7, 0)}));
  }
  s.objects.push_back(testing::object(scene::ObjectKind::Plane));
  for (int i = 0; i < 3; ++i) s.lights.push_back(testing::light({i, 5, 5}));
  RenderScene compiled(s);

  const Bvh& bvh = compiled.bvh();
  std::uint64_t boxes = s.objects.size() - 1;  // the plane is not in the BVH
  EXPECT_LE(bvh.nodes().size(), 2 * boxes - 1);
  EXPECT_LE(bvh.nodes().size_bytes() + bvh.order().capacity() * sizeof(std::uint32_t),
            Bvh::bytesFor(boxes));

  // The constructor builds the lights' grids whatever the samples.
  RenderScene::Bytes bytes =
      RenderScene::bytesFor(s.objects.size(), s.lights.size(), 1, UINT64_MAX);
  EXPECT_LE(compiled.objects().capacity() * sizeof(RenderObject) +
                compiled.lights().capacity() * sizeof(RenderLight),
            bytes.scene);
  EXPECT_GE(bytes.bvh, Bvh::bytesFor(s.objects.size()));
  // The lights' direction grids, which a scene of 300 objects has.
  std::uint64_t grids = 0;
  for (std::size_t l = 0; l < s.lights.size(); ++l) {
    ASSERT_NE(compiled.lightGrid(l), nullptr);
    grids += compiled.lightGrid(l)->bytes();
  }
  EXPECT_LE(bvh.nodes().size_bytes() + bvh.order().capacity() * sizeof(std::uint32_t) + grids,
            bytes.bvh);

  RenderSettings settings;
  settings.width = 17;
  settings.height = 5;
  settings.threads = 1;
  Image image = renderImage(compiled, settings);
  EXPECT_EQ(image.rgb.capacity() * sizeof(float), Image::bytesFor(17, 5));
  settings.coverage = true;
  Image covered = renderImage(compiled, settings);
  EXPECT_EQ((covered.rgb.capacity() + covered.coverage.capacity()) * sizeof(float),
            Image::bytesFor(17, 5, true));
  EXPECT_GT(estimateRenderMemory({.objects = 1, .width = 17, .height = 5, .coverage = true}).image,
            estimate(1, 1, 17, 5).image);
}

TEST(RenderMemory, HugeCountsSaturateInsteadOfWrapping) {
  RenderMemoryEstimate e = estimateRenderMemory({.objects = UINT64_MAX / 2,
                                                 .lights = UINT64_MAX / 2,
                                                 .materials = UINT64_MAX / 2,
                                                 .width = 32768,
                                                 .height = 32768,
                                                 .cameraSamples = UINT64_MAX});
  EXPECT_EQ(e.scene, UINT64_MAX);
  EXPECT_EQ(e.bvh, UINT64_MAX);
  EXPECT_EQ(e.total(), UINT64_MAX);
  EXPECT_TRUE(renderMemoryRefusal(e, std::uint64_t{1} << 40).has_value());
  EXPECT_EQ(Bvh::bytesFor(UINT64_MAX / 4), UINT64_MAX);
  EXPECT_EQ(Image::bytesFor(32768, 32768), std::uint64_t{32768} * 32768 * 12);
}

// The worst cases of what a build holds stay within the estimate: every
// object a plane (normals and a plane list instead of a BVH), every object
// of its own material, and light grids where the samples build them.
TEST(RenderMemory, TheEstimateBoundsAScenesWorstCases) {
  auto held = [](const RenderScene& compiled) {
    RenderSceneMemory m = compiled.memory();
    return m.records + m.bvh + m.grids;
  };
  auto bound = [](std::uint64_t objects, std::uint64_t materials, std::uint64_t samples) {
    RenderScene::Bytes b = RenderScene::bytesFor(objects, 2, materials, samples);
    return b.scene + b.bvh;
  };
  scene::Scene planes = testing::sceneLookingAt({0, 0, 10}, {0, 0, 0});
  for (int i = 0; i < 300; ++i) {
    planes.objects.push_back(
        testing::object(scene::ObjectKind::Plane, {testing::translate(0, -i, 0)}));
  }
  planes.lights = {testing::light({0, 5, 5}), testing::light({5, 5, 5})};
  EXPECT_LE(held(RenderScene(planes)), bound(300, 1, 0));

  scene::Scene own = testing::sceneLookingAt({0, 0, 10}, {0, 0, 0});
  for (int i = 0; i < 300; ++i) {
    own.objects.push_back(testing::object(scene::ObjectKind::Sphere,
                                          {testing::scale(0.1), testing::translate(i, i % 7, 0)}));
    own.objects.back().material.shininess = 1.0 + i;
  }
  own.lights = planes.lights;
  RenderScene ownMaterials(own, 1, false);
  EXPECT_LE(held(ownMaterials), bound(300, 300, 0));
  // The records and the table, made as the objects are added.
  EXPECT_LE(ownMaterials.memory().records, RenderScene::bytesFor(300, 2, 300, 0).scene);
  EXPECT_GT(ownMaterials.memory().records, RenderScene::bytesFor(300, 2, 1, 0).scene);

  // With the grids: 900 samples build them for 300 objects, 899 do not.
  ASSERT_TRUE(RenderScene::lightGridsPay(300, 900));
  ASSERT_FALSE(RenderScene::lightGridsPay(300, 899));
  RenderScene gridded(own, 1, true);
  ASSERT_NE(gridded.lightGrid(0), nullptr);
  EXPECT_LE(held(gridded), bound(300, 300, 900));
  EXPECT_GE(bound(300, 300, 900) - bound(300, 300, 899), gridded.memory().grids);
}

// A scene of 100,000,000 objects of one material, rendered in 1080p at one
// sample a pixel, builds no light grids: it is estimated at its records
// (132 bytes an object), one material, the BVH's build (the compact tree's
// 32 bytes of nodes a box, a 32-byte copy of each box and its 4-byte place
// in the order, and the threads' lists) and the reorder's 6 bytes an
// object: under 21 GB in all, which fits a machine of 24.
TEST(RenderMemory, AHundredMillionObjectsAreEstimatedAtWhatTheBuildHolds) {
  RenderMemoryEstimate e = estimate(100'000'000, 2, 1920, 1080);
  std::uint64_t material = sizeof(scene::Material) + 7 * 8 + 4 + 4 * sizeof(void*);
  EXPECT_EQ(e.scene, std::uint64_t{100'000'000} * 132 + material + 2 * sizeof(RenderLight));
  EXPECT_EQ(e.bvh, Bvh::bytesFor(100'000'000) + 600'000'000);
  EXPECT_GE(Bvh::bytesFor(100'000'000), std::uint64_t{100'000'000} * (32 + 32 + 4));
  EXPECT_LT(Bvh::bytesFor(100'000'000), std::uint64_t{100'000'000} * (32 + 32 + 4 + 1));
  EXPECT_LT(e.total(), std::uint64_t{21'000'000'000});
}

// A scene read whole: its materials bounded by its objects; the region's
// camera samples, which decide the lights' grids; the coverage asked for.
TEST(RenderMemory, ASceneReadWholeIsSizedByItsObjectsAndTheSettings) {
  scene::Scene s = testing::sceneLookingAt({0, 0, 10}, {0, 0, 0});
  for (int i = 0; i < 5; ++i) s.objects.push_back(testing::object(scene::ObjectKind::Sphere));
  for (int i = 0; i < 2; ++i) s.lights.push_back(testing::light({i, 5, 5}));
  RenderSettings settings;
  settings.width = 40;
  settings.height = 30;
  settings.samplesPerPixel = 3;
  settings.coverage = true;
  RenderSize size = renderSizeOf(s, settings);
  EXPECT_EQ(size.objects, 5u);
  EXPECT_EQ(size.lights, 2u);
  EXPECT_EQ(size.materials, 5u);
  EXPECT_EQ(size.width, 40);
  EXPECT_EQ(size.height, 30);
  EXPECT_EQ(size.cameraSamples, 40u * 30u * 3u);
  EXPECT_TRUE(size.coverage);
}

TEST(RenderMemory, ReadsMemAvailableInKibibytes) {
  const char* meminfo =
      "MemTotal:       131072000 kB\n"
      "MemFree:         1000000 kB\n"
      "MemAvailable:    2048000 kB\n"
      "Buffers:           12345 kB\n";
  EXPECT_EQ(parseMemAvailable(meminfo), std::uint64_t{2048000} * 1024);
  EXPECT_EQ(parseMemAvailable("MemTotal: 10 kB\n"), std::nullopt);
  EXPECT_EQ(parseMemAvailable("MemAvailable: lots\n"), std::nullopt);
  EXPECT_EQ(parseMemAvailable("NotMemAvailable: 5 kB\n"), std::nullopt);
}

TEST(RenderMemory, RefusesOnlyWhatDoesNotFitAndSaysBothFigures) {
  RenderMemoryEstimate e = estimate(1000, 2, 640, 480);
  EXPECT_EQ(renderMemoryRefusal(e, e.total()), std::nullopt);
  EXPECT_EQ(renderMemoryRefusal(e, std::nullopt), std::nullopt);  // unknown: not refused
  std::optional<std::string> refusal = renderMemoryRefusal(e, 1000);
  ASSERT_TRUE(refusal.has_value());
  EXPECT_EQ(refusal->rfind("the render needs about ", 0), 0u) << *refusal;
  EXPECT_NE(refusal->find("(image 11 MiB, scene "), std::string::npos) << *refusal;
  EXPECT_NE(refusal->find("only 1000 bytes of memory is available"), std::string::npos) << *refusal;
}

// An address-space limit (RLIMIT_AS) counts what is mapped already.
TEST(RenderMemory, AddressSpaceLeftIsTheLimitLessWhatIsMapped) {
  const char* status = "Name:\tsfrender\nVmPeak:\t  300000 kB\nVmSize:\t  204800 kB\n";
  EXPECT_EQ(parseKibibyteField(status, "VmSize:"), std::uint64_t{204800} * 1024);
  EXPECT_EQ(addressSpaceLeft(std::uint64_t{1} << 30, status),
            (std::uint64_t{1} << 30) - std::uint64_t{204800} * 1024);
  EXPECT_EQ(addressSpaceLeft(std::uint64_t{100} << 20, status), 0u);  // over it already
  EXPECT_EQ(addressSpaceLeft(std::nullopt, status), std::nullopt);    // unlimited
}

TEST(RenderMemory, CgroupLeftIsMaxLessCurrent) {
  EXPECT_EQ(cgroupMemoryLeft("1073741824\n", "73741824\n"), std::uint64_t{1000000000});
  EXPECT_EQ(cgroupMemoryLeft("max\n", "5\n"), std::nullopt);
  EXPECT_EQ(cgroupMemoryLeft("100\n", "200\n"), 0u);
  EXPECT_EQ(cgroupFolder("0::/user.slice/session-2.scope\n"),
            "/sys/fs/cgroup/user.slice/session-2.scope");
  EXPECT_EQ(cgroupFolder("0::/\n"), "/sys/fs/cgroup/");
  EXPECT_EQ(cgroupFolder("12:memory:/docker/abc\n"), std::nullopt);  // cgroup v1 only
}

TEST(RenderMemory, TheLeastKnownLimitCounts) {
  EXPECT_EQ(leastOf({std::uint64_t{5}, std::nullopt, std::uint64_t{3}}), std::uint64_t{3});
  EXPECT_EQ(leastOf({std::nullopt, std::nullopt}), std::nullopt);
  // On this machine: never more than MemAvailable alone.
  std::optional<std::uint64_t> all = readAvailableMemory();
  ASSERT_TRUE(all.has_value());
  std::ifstream in("/proc/meminfo");
  std::stringstream meminfo;
  meminfo << in.rdbuf();
  EXPECT_LE(*all,
            parseMemAvailable(meminfo.str()).value_or(UINT64_MAX) + (std::uint64_t{64} << 20));
}

}  // namespace
}  // namespace render
