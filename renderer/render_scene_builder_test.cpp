// A scene built batch by batch is the scene built whole: the same records,
// hierarchy, hits and images, however the objects were split.
#include "renderer/render_scene_builder.h"

#include <gtest/gtest.h>

#include <cstring>

#include "renderer/render.h"
#include "renderer/test_scenes.h"

namespace render {
namespace {

using namespace render::testing;

// The scene built from `s`'s objects added in `batches` batches of nearly
// equal sizes.
RenderScene builtInBatches(const scene::Scene& s, int batches, int threads) {
  RenderSceneBuilder builder(threads);
  const std::size_t count = s.objects.size();
  for (int b = 0; b < batches; ++b) {
    std::size_t begin = count * b / batches;
    std::size_t end = count * (b + 1) / batches;
    builder.add(std::span<const scene::Object>(s.objects).subspan(begin, end - begin));
  }
  return std::move(builder).finish(s);
}

void expectSameRecords(const RenderScene& a, const RenderScene& b) {
  ASSERT_EQ(a.objects().size(), b.objects().size());
  for (std::uint32_t r = 0; r < a.objects().size(); ++r) {
    ASSERT_EQ(a.sceneObject(r), b.sceneObject(r)) << "object " << r;
    ASSERT_EQ(a.objects()[r].toLocal, b.objects()[r].toLocal) << "object " << r;
    ASSERT_EQ(a.objects()[r].translation, b.objects()[r].translation) << "object " << r;
    ASSERT_EQ(a.objects()[r].kind, b.objects()[r].kind) << "object " << r;
    ASSERT_EQ(a.material(r), b.material(r)) << "object " << r;
    ASSERT_EQ(a.linearToWorld(r), b.linearToWorld(r)) << "object " << r;
  }
  ASSERT_EQ(a.bvh().nodes().size(), b.bvh().nodes().size());
  // Node by node: an empty scene's nodes have no storage to compare.
  for (std::size_t n = 0; n < a.bvh().nodes().size(); ++n) {
    ASSERT_EQ(0, std::memcmp(&a.bvh().nodes()[n], &b.bvh().nodes()[n], sizeof(BvhNode)))
        << "node " << n;
  }
  ASSERT_EQ(a.bvh().itemCount(), b.bvh().itemCount());
  EXPECT_EQ(a.hasTransparency(), b.hasTransparency());
}

TEST(RenderSceneBuilder, BatchesMakeTheSceneBuiltWhole) {
  Random random(11);
  // Past the sizes at which records and the BVH are built in parts.
  for (int count : {0, 1, 7, 300, 20000}) {
    scene::Scene s = randomScene(random, count);
    RenderScene whole(s, 2);
    for (int batches : {1, 2, 7}) {
      SCOPED_TRACE(::testing::Message() << count << " objects, " << batches << " batches");
      RenderScene built = builtInBatches(s, batches, 2);
      expectSameRecords(whole, built);
      for (int k = 0; k < 200; ++k) {
        Ray ray{random.point(25.0), random.direction()};
        expectSameHit(built.closestHit(ray, RaySource{}), whole.closestHit(ray, RaySource{}),
                      "ray " + std::to_string(k));
      }
    }
  }
}

TEST(RenderSceneBuilder, BatchesRenderTheSameImage) {
  Random random(7);
  scene::Scene s = randomScene(random, 400);
  RenderSettings settings;
  settings.width = 48;
  settings.height = 36;
  Image whole = renderImage(RenderScene(s), settings);
  for (int batches : {2, 7}) {
    Image built = renderImage(builtInBatches(s, batches, 2), settings);
    EXPECT_EQ(built.rgb, whole.rgb) << batches << " batches";
  }
}

// The whole image's samples choose the tree's kind (Bvh::nodeCostFor): for
// a grid of kMinCompactBoxes small objects, one sample fewer than
// kFullTreeSamplesPerBox a box builds the compact tree (leaves of two or
// more, fewer nodes than objects), and exactly that many the full one, as
// no count at all does. No two objects of the
// grid meet a ray at one distance, so each ray's hit is the same object,
// and each image the same, bit for bit.
TEST(RenderSceneBuilder, FewSamplesAnObjectBuildACompactTreeOfTheSameHits) {
  Random random(5);
  scene::Scene s = sceneLookingAt({0, 0, 200}, {0, 0, 0});
  constexpr scene::ObjectKind kKinds[] = {scene::ObjectKind::Sphere, scene::ObjectKind::Cube,
                                          scene::ObjectKind::Cylinder};
  for (int i = 0; i < 256; ++i) {
    for (int j = 0; j < 256; ++j) {
      s.objects.push_back(
          object(kKinds[random.below(3)],
                 {scale(random.uniform(0.2, 0.4)), rotateX(random.uniform(-3, 3)),
                  rotateZ(random.uniform(-3, 3)), translate(i - 128.0, j - 128.0, 0)},
                 scene::Material{}));
    }
  }
  s.lights.push_back(light({50, 80, 300}));
  const std::uint64_t boxes = s.objects.size();
  ASSERT_EQ(boxes, Bvh::kMinCompactBoxes);
  const std::uint64_t fewest = Bvh::kFullTreeSamplesPerBox * boxes;
  RenderScene compact(s, 2, false, fewest - 1);
  RenderScene full(s, 2, false, fewest);
  RenderScene uncounted(s, 2, false);
  EXPECT_LT(compact.bvh().nodes().size(), boxes);
  EXPECT_EQ(full.bvh().nodes().size(), uncounted.bvh().nodes().size());
  EXPECT_GT(full.bvh().nodes().size(), boxes);
  EXPECT_LT(compact.memory().bvh, full.memory().bvh);
  for (int k = 0; k < 2000; ++k) {
    glm::dvec3 target(random.uniform(-130, 130), random.uniform(-130, 130), 0);
    Ray ray{random.point(100.0) + glm::dvec3(0, 0, 150), {}};
    ray.direction = glm::normalize(target - ray.origin);
    std::optional<Hit> a = compact.closestHit(ray, RaySource{});
    std::optional<Hit> b = full.closestHit(ray, RaySource{});
    ASSERT_EQ(a.has_value(), b.has_value()) << "ray " << k;
    if (!a) continue;
    EXPECT_EQ(a->t, b->t) << "ray " << k;
    EXPECT_EQ(compact.sceneObject(a->object), full.sceneObject(b->object)) << "ray " << k;
    EXPECT_EQ(a->normal, b->normal) << "ray " << k;
  }
  RenderSettings settings;
  settings.width = 64;
  settings.height = 48;
  EXPECT_EQ(renderImage(compact, settings).rgb, renderImage(full, settings).rgb);
}

// Materials are numbered by their first use in the order added, whatever
// the batches and threads: here in batches past the size made in parts,
// most of whose objects share the last material found, a few of which
// bring a new one (and one batch starts with one).
TEST(RenderSceneBuilder, MaterialsAreNumberedByFirstUse) {
  Random random(5);
  scene::Scene s = randomScene(random, 60000);
  for (scene::Object& o : s.objects) o.material = scene::Material{};
  std::vector<std::uint32_t> expected(s.objects.size(), 0);
  scene::Material glass;
  glass.transparency = 0.5;
  scene::Material matte;
  matte.specular = 0.0;
  scene::Material shiny;
  shiny.reflectivity = 0.75;
  auto use = [&](std::size_t i, const scene::Material& m, std::uint32_t number) {
    s.objects[i].material = m;
    expected[i] = number;
  };
  use(30001, glass, 1);
  for (std::size_t i = 40000; i < 41000; ++i) use(i, matte, 2);
  use(45000, shiny, 3);
  use(59999, glass, 1);
  for (int batches : {1, 3}) {
    SCOPED_TRACE(::testing::Message() << batches << " batches");
    RenderScene built = builtInBatches(s, batches, 2);
    for (std::uint32_t r = 0; r < built.objects().size(); ++r) {
      ASSERT_EQ(built.objects()[r].material, expected[built.sceneObject(r)]) << "object " << r;
    }
  }
}

// memory() counts each array as the layout says: per object its record,
// colour and file index; per plane its normal and place in the plane list;
// the table of distinct materials; the lights; the nodes (2n - 1 over n
// boxes, one a leaf) and an item a box; each item's leaf and the lights'
// grids.
TEST(RenderSceneBuilder, MemoryIsTheLayoutsSizes) {
  Random random(3);
  scene::Scene s = randomScene(random, 1000);
  scene::Material shiny;
  shiny.specular = 0.25;
  for (int i = 0; i < 10; ++i) s.objects[i * 7].material = shiny;
  RenderScene built(s, 2);
  std::uint64_t objects = s.objects.size();
  std::uint64_t planes = built.planeObjects().size();
  std::uint64_t bounded = objects - planes;
  ASSERT_GT(planes, 0u);
  // randomScene's materials differ in reflectivity and transparency alone;
  // and the shiny one.
  std::uint64_t materials = 5;
  RenderSceneMemory memory = built.memory();
  EXPECT_EQ(memory.records,
            objects * (sizeof(RenderObject) + sizeof(glm::dvec3) + sizeof(std::uint32_t)) +
                planes * (sizeof(glm::dvec3) + sizeof(std::uint32_t)) +
                materials * sizeof(scene::Material) + s.lights.size() * sizeof(RenderLight));
  EXPECT_EQ(memory.bvh, built.bvh().nodes().size() * sizeof(BvhNode));
  EXPECT_LE(built.bvh().nodes().size(), 2 * bounded - 1);
  std::uint64_t grids = bounded * sizeof(std::uint32_t);
  for (std::size_t l = 0; l < s.lights.size(); ++l) grids += built.lightGrid(l)->bytes();
  EXPECT_EQ(memory.grids, grids);
  RenderScene::Bytes most = RenderScene::bytesFor(objects, s.lights.size(), materials, UINT64_MAX);
  // The planes' normals and list are made with the BVH, after the records.
  EXPECT_LE(memory.records - planes * (sizeof(glm::dvec3) + sizeof(std::uint32_t)), most.scene);
  EXPECT_LE(memory.records + memory.bvh + memory.grids, most.scene + most.bvh);
}

TEST(RenderSceneBuilder, NothingAddedIsAnEmptyScene) {
  scene::Scene s = sceneLookingAt({0, 0, 1}, {0, 0, 0});
  s.lights.push_back(light({1, 1, 1}));
  RenderScene built = RenderSceneBuilder(1).finish(s);
  EXPECT_TRUE(built.objects().empty());
  EXPECT_TRUE(built.bvh().empty());
  EXPECT_EQ(built.lights().size(), 1u);
  EXPECT_FALSE(built.closestHit(Ray{}, RaySource{}).has_value());
}

}  // namespace
}  // namespace render
