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

TEST(RenderMemory, ImageGrowsWithThePixelsAndSceneAndBvhWithTheObjects) {
  RenderMemoryEstimate empty = estimateRenderMemory(0, 0, 1, 1);
  EXPECT_EQ(empty.scene, 0u);
  EXPECT_EQ(empty.bvh, 0u);
  EXPECT_GT(empty.image, 0u);

  RenderMemoryEstimate small = estimateRenderMemory(10, 1, 640, 480);
  RenderMemoryEstimate big = estimateRenderMemory(1'000'000, 1, 640, 480);
  EXPECT_EQ(small.image, big.image);
  EXPECT_EQ(estimateRenderMemory(2000, 0, 1, 1).scene,
            2 * estimateRenderMemory(1000, 0, 1, 1).scene);
  EXPECT_EQ(estimateRenderMemory(2000, 0, 1, 1).bvh, 2 * estimateRenderMemory(1000, 0, 1, 1).bvh);
  // At least the float image, and each object's record (a 3x3 double
  // matrix and a translation), colour and material, more than 200 bytes.
  EXPECT_GE(small.image, 640u * 480 * 12);
  EXPECT_GE(big.scene, 1'000'000u * 200);
  EXPECT_GT(big.bvh, small.bvh);
  EXPECT_EQ(big.total(), big.image + big.scene + big.bvh);

  RenderMemoryEstimate wide = estimateRenderMemory(10, 1, 1280, 960);
  EXPECT_EQ(wide.image, 4 * small.image);
}

// The figures of each part, from the types' sizes: the image three times
// (the floats, the file's copy, the file's bytes).
TEST(RenderMemory, ThePartsAreTheTypesSizes) {
  RenderMemoryEstimate e = estimateRenderMemory(1000, 7, 640, 480);
  EXPECT_EQ(e.image, 640u * 480 * 3 * (3 * sizeof(float)));
  // The records, their colours, a material each (at most), each object's
  // index in the scene and in the plane list, and a plane's normal, counted
  // for any object.
  EXPECT_EQ(e.scene, 1000 * (sizeof(RenderObject) + sizeof(glm::dvec3) + sizeof(scene::Material) +
                             2 * sizeof(std::uint32_t) + sizeof(glm::dvec3)) +
                         7 * sizeof(RenderLight));
  // At least the nodes, the build's copy of each box in float beside its
  // index and bin, the BVH's order (twice: the builder's copy), a byte of
  // marks for the records' moves, and each item's leaf. The threads' lists
  // of the top of the tree and of its subtrees come only with a parallel
  // build, from 16,384 boxes.
  std::uint64_t parts =
      1000 * ((6 * sizeof(float) + 8) + 2 * sizeof(BvhNode) + 3 * sizeof(std::uint32_t) + 1);
  // And 7 lights' grids of at most 8 cells a box on each face: per cell
  // its start, count and full flag, per entry an index (16 a box, plus one
  // a cell, at most), and while two build at once, 6 ranges of cells a box
  // each in a vector that may double.
  std::uint64_t cells = 6 * 8 * 1000 + 1;
  std::uint64_t grids = 7 * (cells * 13 + (16 * 1000 + cells) * 4) + 1000 * (2 * 2 * 6 * 20);
  EXPECT_GE(e.bvh, parts + grids);
  EXPECT_LE(e.bvh, parts + grids + 1000 * 12);
  EXPECT_EQ(estimateRenderMemory(5, 0, 0, -3).image, 0u);  // no pixels
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
  EXPECT_LE(bvh.nodes().capacity(), Bvh::kNodesPerBox * boxes);
  EXPECT_LE(bvh.nodes().size(), 2 * boxes - 1);
  EXPECT_LE(
      bvh.nodes().capacity() * sizeof(BvhNode) + bvh.order().capacity() * sizeof(std::uint32_t),
      Bvh::bytesFor(boxes));

  RenderScene::Bytes bytes = RenderScene::bytesFor(s.objects.size(), s.lights.size());
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
  EXPECT_LE(bvh.nodes().capacity() * sizeof(BvhNode) +
                bvh.order().capacity() * sizeof(std::uint32_t) + grids,
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
  EXPECT_GT(estimateRenderMemory(1, 1, 17, 5, true).image, estimateRenderMemory(1, 1, 17, 5).image);
}

TEST(RenderMemory, HugeCountsSaturateInsteadOfWrapping) {
  RenderMemoryEstimate e = estimateRenderMemory(UINT64_MAX / 2, UINT64_MAX / 2, 32768, 32768);
  EXPECT_EQ(e.scene, UINT64_MAX);
  EXPECT_EQ(e.bvh, UINT64_MAX);
  EXPECT_EQ(e.total(), UINT64_MAX);
  EXPECT_TRUE(renderMemoryRefusal(e, std::uint64_t{1} << 40).has_value());
  EXPECT_EQ(Bvh::bytesFor(UINT64_MAX / 4), UINT64_MAX);
  EXPECT_EQ(Image::bytesFor(32768, 32768), std::uint64_t{32768} * 32768 * 12);
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
  RenderMemoryEstimate e = estimateRenderMemory(1000, 2, 640, 480);
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
