// Direction grids (DirectionGrid) list every box a ray from their apex can
// meet, and the renderer's searches through them (RenderScene::
// anyHitTowardLight, RenderScene::closestHitsFromEye) answer what the BVH
// answers, bit for bit, under seeded random scenes and rays.
#include "renderer/direction_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <set>
#include <vector>

#include "renderer/camera.h"
#include "renderer/default_scene.h"
#include "renderer/render.h"
#include "renderer/render_scene.h"
#include "renderer/test_scenes.h"
#include "renderer/tracer.h"

namespace render {
namespace {

using namespace render::testing;
using scene::ObjectKind;

std::vector<Bounds> randomBoxes(Random& random, int count, double reach, double size) {
  std::vector<Bounds> boxes;
  for (int i = 0; i < count; ++i) {
    glm::dvec3 centre = random.point(reach);
    glm::dvec3 half(random.uniform(0.0, size), random.uniform(0.0, size),
                    random.uniform(0.0, size));
    boxes.push_back(Bounds{centre - half, centre + half});
  }
  return boxes;
}

// Every box that the ray from the apex along `w` meets is in the cell's
// list, unless the grid does not answer there.
void expectListed(const DirectionGrid& grid, std::uint32_t cell, const std::vector<Bounds>& boxes,
                  const glm::dvec3& w, const std::string& where) {
  if (cell == DirectionGrid::kNoCell || grid.full(cell)) return;
  std::span<const std::uint32_t> items = grid.items(cell);
  std::set<std::uint32_t> listed(items.begin(), items.end());
  BoxRay ray{grid.apex(), 1.0 / w};
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    if (hitsBox(boxes[i], ray, 0.0, std::numeric_limits<double>::infinity())) {
      EXPECT_TRUE(listed.count(i)) << where << ": box " << i << " is met but not listed";
    }
  }
}

TEST(DirectionGrid, ACubeListsEveryBoxARayFromItsApexMeets) {
  Random random(71);
  int answered = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Bounds> boxes = randomBoxes(random, 1 + random.below(300), 20.0, 2.0);
    glm::dvec3 apex = random.point(25.0);
    DirectionGrid grid = DirectionGrid::cubeAround(apex, boxes, 16 + random.below(64), {});
    ASSERT_TRUE(grid.built());
    for (int r = 0; r < 400; ++r) {
      // Rays at the boxes, half of them through a corner, where cells are
      // most likely to be cut short.
      const Bounds& target = boxes[random.below(static_cast<int>(boxes.size()))];
      glm::dvec3 at = r % 2 ? target.lo : target.centre();
      glm::dvec3 w = at - apex;
      std::uint32_t cell = grid.cubeCellOf(w);
      EXPECT_EQ(cell, grid.cellOf(DirectionGrid::cubeWindowOf(w), w));
      expectListed(grid, cell, boxes, w, "trial " + std::to_string(trial));
      answered += cell != DirectionGrid::kNoCell && !grid.full(cell);
    }
  }
  EXPECT_GT(answered, 7000);  // of 8,000: the test tests something
}

TEST(DirectionGrid, ACameraWindowListsEveryBoxARayThroughItMeets) {
  Random random(72);
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<Bounds> boxes = randomBoxes(random, 1 + random.below(300), 10.0, 1.5);
    glm::dvec3 eye = random.point(5.0);  // often among the boxes, or in one
    GridWindow window;
    window.forward = random.direction();
    window.uAxis = glm::normalize(glm::cross(window.forward, random.direction()));
    window.vAxis = glm::cross(window.uAxis, window.forward);
    window.uLow = -random.uniform(0.1, 3.0);
    window.uHigh = random.uniform(0.1, 3.0);
    window.vLow = -random.uniform(0.1, 3.0);
    window.vHigh = random.uniform(0.1, 3.0);
    window.columns = 1 + random.below(100);
    window.rows = 1 + random.below(100);
    // No budget: boxes around the eye cover much of the window.
    DirectionGrid grid(
        eye, {window}, boxes,
        {.coverPerBox = 1u << 20, .farLookup = std::numeric_limits<double>::infinity()});
    ASSERT_TRUE(grid.built());
    for (int r = 0; r < 400; ++r) {
      double u = random.uniform(window.uLow, window.uHigh);
      double v = random.uniform(window.vLow, window.vHigh);
      glm::dvec3 w = window.forward + u * window.uAxis + v * window.vAxis;
      std::uint32_t cell = grid.cellOf(0, w);
      EXPECT_NE(cell, DirectionGrid::kNoCell) << "inside the window";
      expectListed(grid, cell, boxes, w, "trial " + std::to_string(trial));
    }
    // Behind the eye or outside the window, the grid does not answer.
    EXPECT_EQ(grid.cellOf(0, -window.forward), DirectionGrid::kNoCell);
    EXPECT_EQ(grid.cellOf(0, window.forward + 2 * window.uLow * window.uAxis),
              DirectionGrid::kNoCell);
  }
}

TEST(DirectionGrid, ABoxAroundTheApexIsInEveryCell) {
  std::vector<Bounds> boxes{Bounds{glm::dvec3(-1.0), glm::dvec3(1.0)},
                            Bounds{glm::dvec3(5.0), glm::dvec3(6.0)}};
  DirectionGrid grid = DirectionGrid::cubeAround(glm::dvec3(0.25, 0.0, -0.5), boxes, 8, {});
  ASSERT_TRUE(grid.built());
  for (std::uint32_t cell = 0; cell + 1 < grid.cellCount(); ++cell) {
    ASSERT_FALSE(grid.full(cell));
    EXPECT_EQ(grid.items(cell)[0], 0u) << "cell " << cell;
  }
}

TEST(DirectionGrid, CrowdedCellsAreFullAndTooMuchCoverBuildsNothing) {
  // 40 boxes in one direction: a cell of limit 16 that holds them is full.
  std::vector<Bounds> boxes;
  for (int i = 0; i < 40; ++i) {
    boxes.push_back(Bounds{glm::dvec3(-0.1, -0.1, 10.0 + i), glm::dvec3(0.1, 0.1, 10.5 + i)});
  }
  DirectionGrid grid =
      DirectionGrid::cubeAround(glm::dvec3(0.0), boxes, DirectionGrid::FaceCells{}, {});
  std::uint32_t cell = grid.cubeCellOf({0.0, 0.0, 1.0});
  ASSERT_NE(cell, DirectionGrid::kNoCell);
  EXPECT_TRUE(grid.full(cell));
  EXPECT_TRUE(grid.items(cell).empty());
  // Boxes wrapping the apex at a distance cover every cell of every face:
  // far over 16 cells a box at 64 x 64 cells a face, and still at a
  // quarter of that, so no grid.
  std::vector<Bounds> shells(4, Bounds{glm::dvec3(-2.0), glm::dvec3(2.0)});
  DirectionGrid none = DirectionGrid::cubeAround(glm::dvec3(0.0), shells, 64, {});
  EXPECT_FALSE(none.built());
  EXPECT_EQ(none.cubeCellOf({1.0, 0.0, 0.0}), DirectionGrid::kNoCell);
}

TEST(DirectionGrid, FacesNoBoxReachesShareOneEmptyCell) {
  // Boxes below the apex only: the upward face has no cells of its own.
  std::vector<Bounds> boxes{Bounds{glm::dvec3(-1.0, -10.0, -1.0), glm::dvec3(1.0, -9.0, 1.0)}};
  DirectionGrid grid = DirectionGrid::cubeAround(glm::dvec3(0.0), boxes, 32, {});
  std::uint32_t up = grid.cubeCellOf({0.1, 1.0, 0.2});
  ASSERT_NE(up, DirectionGrid::kNoCell);
  EXPECT_TRUE(grid.items(up).empty());
  EXPECT_LT(grid.cellCount(), 6u * 32 * 32);
  std::uint32_t down = grid.cubeCellOf({0.0, -1.0, 0.0});
  ASSERT_EQ(grid.items(down).size(), 1u);
}

// A face is cut over the rectangle its boxes reach: finer there than the
// whole face in as many cells, and the rest of the face, which no box
// reaches, answers with the empty cell (a ray there meets nothing).
TEST(DirectionGrid, AFaceIsCutOverTheRectangleItsBoxesReach) {
  Random random(74);
  // A floor of boxes seen from above, as a light sees one.
  std::vector<Bounds> boxes;
  for (int i = 0; i < 400; ++i) {
    glm::dvec3 centre(random.uniform(-10.0, 10.0), 0.0, random.uniform(-10.0, 10.0));
    boxes.push_back(Bounds{centre - glm::dvec3(0.2), centre + glm::dvec3(0.2)});
  }
  glm::dvec3 apex(0.0, 100.0, 0.0);
  DirectionGrid grid = DirectionGrid::cubeAround(apex, boxes, 32, {});
  ASSERT_TRUE(grid.built());
  const GridWindow& down = grid.windows()[3];  // -y
  // At most (10 + 0.2) / (100 - 0.2) each side of the centre, of a face
  // 2 across.
  for (double across : {down.uHigh - down.uLow, down.vHigh - down.vLow}) {
    EXPECT_GT(across, 0.18);
    EXPECT_LT(across, 0.2045);
  }
  EXPECT_EQ(down.columns * down.rows, 32 * 32);
  // Beside the floor, on the same face: nothing, and said so.
  std::uint32_t beside = grid.cubeCellOf({0.5, -1.0, 0.5});
  ASSERT_NE(beside, DirectionGrid::kNoCell);
  EXPECT_TRUE(grid.items(beside).empty());
  EXPECT_FALSE(grid.full(beside));
  // Every direction, on the floor or off it: the shortcut's cell is the
  // general lookup's, and it lists every box the direction meets.
  int listing = 0;
  for (int r = 0; r < 4000; ++r) {
    glm::dvec3 w = r % 2 ? random.direction() : boxes[r % boxes.size()].centre() - apex;
    std::uint32_t cell = grid.cubeCellOf(w);
    ASSERT_EQ(cell, grid.cellOf(DirectionGrid::cubeWindowOf(w), w)) << "ray " << r;
    ASSERT_NE(cell, DirectionGrid::kNoCell) << "ray " << r;
    expectListed(grid, cell, boxes, w, "ray " + std::to_string(r));
    listing += !grid.items(cell).empty();
  }
  EXPECT_GT(listing, 1500);  // of the 2,000 at a box
}

// Boxes listed under labels (a BVH's items, the boxes in its order): each
// cell lists the labels of the boxes the same grid over the boxes in their
// own order lists.
TEST(DirectionGrid, BoxesInAnotherOrderAreListedByTheirLabels) {
  Random random(75);
  std::vector<Bounds> boxes = randomBoxes(random, 300, 20.0, 1.0);
  std::vector<std::uint32_t> labels(boxes.size());
  for (std::uint32_t i = 0; i < labels.size(); ++i) labels[i] = i;
  for (std::size_t i = labels.size() - 1; i > 0; --i) {
    std::swap(labels[i], labels[random.below(static_cast<int>(i + 1))]);
  }
  std::vector<Bounds> shuffled(boxes.size());
  for (std::size_t k = 0; k < boxes.size(); ++k) shuffled[k] = boxes[labels[k]];
  glm::dvec3 apex(3.0, 30.0, -4.0);
  DirectionGrid plain = DirectionGrid::cubeAround(apex, boxes, DirectionGrid::FaceCells{}, {});
  DirectionGrid labelled =
      DirectionGrid::cubeAround(apex, shuffled, DirectionGrid::FaceCells{}, {}, labels);
  ASSERT_TRUE(plain.built());
  ASSERT_EQ(plain.cellCount(), labelled.cellCount());
  for (std::uint32_t cell = 0; cell < plain.cellCount(); ++cell) {
    std::span<const std::uint32_t> a = plain.items(cell);
    std::span<const std::uint32_t> b = labelled.items(cell);
    ASSERT_EQ(std::set<std::uint32_t>(a.begin(), a.end()),
              std::set<std::uint32_t>(b.begin(), b.end()))
        << "cell " << cell;
  }
}

// Cut far too finely for its boxes, a cube is cut a quarter as fine, and
// again, until they fit its budget; it still lists every box a ray meets.
TEST(DirectionGrid, TooMuchCoverCutsTheFacesCoarser) {
  Random random(76);
  std::vector<Bounds> boxes = randomBoxes(random, 60, 20.0, 2.0);
  glm::dvec3 apex(0.0, 40.0, 0.0);
  DirectionGrid::FaceCells fine{1e6, 1e9, 1, std::uint64_t{1} << 20};
  DirectionGrid grid = DirectionGrid::cubeAround(apex, boxes, fine, {});
  ASSERT_TRUE(grid.built());
  // 60 boxes at their first cut: 2^20 cells on the face below.
  EXPECT_LT(grid.cellCount(), std::uint32_t{1} << 20);
  EXPECT_GE(grid.cellCount(), std::uint32_t{1} << 10);
  for (int r = 0; r < 400; ++r) {
    glm::dvec3 w = boxes[r % boxes.size()].centre() - apex;
    expectListed(grid, grid.cubeCellOf(w), boxes, w, "ray " + std::to_string(r));
  }
}

// A face's cells: per box, less where boxes overlap, within the bounds;
// a setting that is not a number gives the least.
TEST(DirectionGrid, FaceCellsFollowTheBoxesWithinTheirBounds) {
  DirectionGrid::FaceCells cells{8.0, 4.0, 16, 1000};
  EXPECT_EQ(cells.forFace(10, 0.0, 1.0), 80u);
  EXPECT_EQ(cells.forFace(10, 1.0, 1.0), 40u);      // the boxes cover the face once over
  EXPECT_EQ(cells.forFace(1, 0.0, 1.0), 16u);       // at least least
  EXPECT_EQ(cells.forFace(1000, 0.0, 1.0), 1000u);  // at most most
  EXPECT_EQ(cells.bound(1000), 1000u);
  DirectionGrid::FaceCells broken{std::nan(""), 4.0, 16, 1000};
  EXPECT_EQ(broken.forFace(10, 0.0, 1.0), 16u);
}

// Shadow rays toward each light, from points on and among the objects:
// the grid's answer is the BVH's.
TEST(DirectionGrid, ShadowRaysThroughLightGridsAnswerAsTheBvhDoes) {
  Random random(73);
  int blocked = 0, rays = 0;
  for (int trial = 0; trial < 8; ++trial) {
    scene::Scene s = randomScene(random, 70 + random.below(200));
    // Without planes, which would block most of the rays (they are tested
    // before either search, the same way).
    std::erase_if(s.objects, [](const scene::Object& o) { return o.kind == ObjectKind::Plane; });
    // A light among the objects too.
    s.lights.push_back(light(random.point(8.0)));
    RenderScene compiled(s, 1);
    RenderScene plain(s, 1, false);
    for (std::size_t l = 0; l < s.lights.size(); ++l) {
      // The light among the objects may have none (too much of its view
      // covered), and then the BVH answers: the same either way.
      if (l < 2) {
        ASSERT_NE(compiled.lightGrid(l), nullptr) << "trial " << trial << " light " << l;
      }
      ASSERT_EQ(plain.lightGrid(l), nullptr);
      glm::dvec3 target = compiled.lights()[l].position;
      for (int r = 0; r < 600; ++r) {
        glm::dvec3 origin = random.point(r % 3 ? 12.0 : 200.0);
        Ray ray{origin, target - origin};
        std::uint32_t hint = RaySource::kNone;
        bool expected = plain.anyHit(ray, RaySource{}, 1.0);
        EXPECT_EQ(compiled.anyHitTowardLight(l, ray, RaySource{}, 1.0, &hint), expected)
            << "trial " << trial << " light " << l << " ray " << r;
        EXPECT_EQ(hint != RaySource::kNone, expected);
        blocked += expected;
        ++rays;
      }
    }
  }
  EXPECT_GT(blocked, rays / 10);
  EXPECT_LT(blocked, rays * 9 / 10);
}

// Shadow rays from points on the surfaces, as Tracer::shadowed makes them
// (with its shortcut for the floor's points, and the hit point's cell
// used for the ray, RenderScene::shadowCell): the same answers with the grids as without.
TEST(DirectionGrid, ShadowsFromSurfacePointsAreTheSameWithAndWithoutGrids) {
  Random random(77);
  int shortcuts = 0, shadowedCount = 0, total = 0;
  for (int trial = 0; trial < 6; ++trial) {
    scene::Scene s = randomScene(random, 70 + random.below(200));
    std::erase_if(s.objects, [](const scene::Object& o) { return o.kind == ObjectKind::Plane; });
    s.objects.push_back(object(ObjectKind::Plane, {translate(0, -12, 0)}));  // a floor
    s.lights.push_back(light(random.point(8.0)));
    RenderScene compiled(s, 1);
    RenderScene plain(s, 1, false);
    Tracer withGrids(compiled, 5);
    Tracer without(plain, 5);
    TraceContext a, b;
    for (int r = 0; r < 1500; ++r) {
      Ray ray{random.point(15.0) + glm::dvec3(0, 20, 0), random.direction()};
      std::optional<Hit> hit = compiled.closestHit(ray, RaySource{});
      if (!hit) continue;
      for (std::size_t l = 0; l < s.lights.size(); ++l) {
        std::uint32_t cell = compiled.shadowCell(l, hit->point, hit->pointError);
        shortcuts += cell != DirectionGrid::kNoCell && compiled.lightGrid(l)->items(cell).empty() &&
                     compiled.noPlaneBut(hit->object);
        bool expected = without.shadowed(*hit, l, b);
        EXPECT_EQ(withGrids.shadowed(*hit, l, a), expected) << "trial " << trial << " ray " << r;
        shadowedCount += expected;
        ++total;
      }
    }
  }
  EXPECT_GT(shortcuts, total / 10);
  EXPECT_GT(shadowedCount, total / 20);
  EXPECT_LT(shadowedCount, total * 19 / 20);
}

// Camera rays through the eye's grid find the BVH's hit, bit for bit, ties
// included: two objects with one matrix tie everywhere, and the BVH's order
// decides between them.
TEST(DirectionGrid, CameraRaysThroughTheEyeGridFindTheBvhsHit) {
  Random random(74);
  for (int trial = 0; trial < 8; ++trial) {
    scene::Scene s = randomScene(random, 70 + random.below(200));
    for (int twin = 0; twin < 10; ++twin) s.objects.push_back(s.objects[twin]);
    if (trial % 2) s.camera.matrix[3] = glm::dvec4(random.point(6.0), 1.0);  // among them
    RenderScene compiled(s, 1);
    RenderSettings settings;
    settings.width = 64;
    settings.height = 48;
    PinholeCamera camera(compiled.camera(), settings);
    EyeGrid eye = compiled.eyeGrid(camera.eye(), camera.imageWindow(16, 12));
    ASSERT_TRUE(eye.grid.built());
    std::vector<Ray> rays;
    for (int j = 0; j < settings.height; ++j) {
      for (int i = 0; i < settings.width; ++i) {
        rays.push_back(camera.rayThrough(i + random.uniform(0, 1), j + random.uniform(0, 1)));
      }
    }
    // And a ray from elsewhere, which the grid must leave to the BVH.
    rays.push_back(Ray{camera.eye() + glm::dvec3(0.5), camera.forward()});
    std::vector<std::optional<Hit>> found(rays.size());
    compiled.closestHitsFromEye(eye, rays.data(), static_cast<int>(rays.size()), found.data());
    for (std::size_t k = 0; k < rays.size(); ++k) {
      expectSameHit(found[k], compiled.closestHit(rays[k], RaySource{}),
                    "trial " + std::to_string(trial) + " ray " + std::to_string(k));
    }
  }
}

// Ties: each object five times, with one matrix, so that the five meet
// every ray at the same distance and the BVH's order picks one (more than a
// leaf holds, so split in two, whose order follows the ray); the groups all
// around the eye, so that rays cross each split in both directions, whose
// orders differ.
TEST(DirectionGrid, TiesFallAsTheBvhBreaksThem) {
  Random random(76);
  scene::Scene s = sceneLookingAt({0, 0, 0}, {0, 0, -1});
  for (int i = 0; i < 60; ++i) {
    glm::dvec3 at = random.direction() * random.uniform(4.0, 9.0);
    constexpr ObjectKind kKinds[] = {ObjectKind::Sphere, ObjectKind::Cube, ObjectKind::Cylinder};
    scene::Object o =
        object(kKinds[i % 3], {scale(random.uniform(0.5, 1.5)), rotateY(random.uniform(-3, 3)),
                               translate(at.x, at.y, at.z)});
    for (int copy = 0; copy < 5; ++copy) s.objects.push_back(o);
  }
  RenderScene compiled(s, 1);
  int twinsDecided = 0;
  for (glm::dvec3 forward : {glm::dvec3(0, 0, -1), glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0),
                             glm::dvec3(-1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0)}) {
    GridWindow window;
    window.forward = forward;
    window.uAxis = glm::dvec3(forward.y, forward.z, forward.x);
    window.vAxis = glm::cross(window.uAxis, forward);
    window.uLow = window.vLow = -3.0;
    window.uHigh = window.vHigh = 3.0;
    window.columns = window.rows = 24;
    EyeGrid eye = compiled.eyeGrid(glm::dvec3(0.0), window);
    ASSERT_TRUE(eye.grid.built());
    std::vector<Ray> rays;
    for (int r = 0; r < 4000; ++r) {
      glm::dvec3 d =
          forward + random.uniform(-3, 3) * window.uAxis + random.uniform(-3, 3) * window.vAxis;
      rays.push_back(Ray{glm::dvec3(0.0), d});
    }
    std::vector<std::optional<Hit>> found(rays.size());
    compiled.closestHitsFromEye(eye, rays.data(), static_cast<int>(rays.size()), found.data());
    for (std::size_t k = 0; k < rays.size(); ++k) {
      std::optional<Hit> alone = compiled.closestHit(rays[k], RaySource{});
      expectSameHit(found[k], alone, "ray " + std::to_string(k));
      // A later one of the five (in the renderer's numbering, the BVH's
      // order) wins where the BVH visits the second half first.
      twinsDecided += alone && alone->object % 5 != 0;
    }
  }
  EXPECT_GT(twinsDecided, 500);
}

// Objects of every scale from 1e-6 to 1e6 placed out to 1e8, lights among
// them and inside them: shadow rays near the light (where the grid lists
// every box close by) and far from it (where lookups go to the BVH), and
// the images, the same with and without grids.
TEST(DirectionGrid, ObjectsOfEveryScaleAnswerAsTheBvhDoes) {
  Random random(78);
  int grids = 0;
  for (int trial = 0; trial < 4; ++trial) {
    scene::Scene s = sceneLookingAt({0, 0, 50}, {0, 0, 0});
    for (int i = 0; i < 150; ++i) {
      double size = std::pow(10.0, random.uniform(-6, 6));
      glm::dvec3 at = random.direction() * std::pow(10.0, random.uniform(-3, 8));
      constexpr ObjectKind kKinds[] = {ObjectKind::Sphere, ObjectKind::Cube, ObjectKind::Cylinder};
      s.objects.push_back(
          object(kKinds[i % 3], {scale(size, size * random.uniform(0.1, 10), size),
                                 rotateX(random.uniform(-3, 3)), translate(at.x, at.y, at.z)}));
    }
    // One light inside an object, one beside a tiny one, one far away.
    s.lights.push_back(light(glm::dvec3(s.objects[0].matrix[3])));
    s.lights.push_back(light(glm::dvec3(s.objects[1].matrix[3]) + glm::dvec3(1e-5)));
    s.lights.push_back(light({3e7, 2e7, -1e7}));
    RenderScene compiled(s, 1);
    RenderScene plain(s, 1, false);
    for (std::size_t l = 0; l < s.lights.size(); ++l) grids += compiled.lightGrid(l) != nullptr;
    Tracer withGrids(compiled, 5);
    Tracer without(plain, 5);
    TraceContext a, b;
    for (int r = 0; r < 2000; ++r) {
      const scene::Object& target = s.objects[random.below(static_cast<int>(s.objects.size()))];
      glm::dvec3 origin = random.direction() * std::pow(10.0, random.uniform(-2, 9));
      Ray ray{origin, glm::dvec3(target.matrix[3]) - origin};
      std::optional<Hit> hit = compiled.closestHit(ray, RaySource{});
      if (!hit) continue;
      for (std::size_t l = 0; l < s.lights.size(); ++l) {
        EXPECT_EQ(withGrids.shadowed(*hit, l, a), without.shadowed(*hit, l, b))
            << "trial " << trial << " ray " << r << " light " << l;
      }
    }
    RenderSettings settings;
    settings.width = 64;
    settings.height = 48;
    settings.threads = 1;
    settings.samplesPerPixel = 16;  // 4 samples an object or more: the eye's grid too
    Image with = renderImage(compiled, settings);
    settings.eyeGrid = false;
    Image alone = renderImage(plain, settings);
    EXPECT_EQ(with.rgb, alone.rgb) << "trial " << trial;
  }
  // Of 12: the far light of each trial has a grid; the lights among the
  // huge objects mostly have none (their boxes would cover too many cells),
  // and walk the BVH.
  EXPECT_GE(grids, 4);
}

// Whole images: with both grids and without either, every float the same.
TEST(DirectionGrid, ImagesAreTheSameWithAndWithoutGrids) {
  Random random(75);
  std::vector<scene::Scene> scenes{defaultScene()};
  for (int k = 0; k < 3; ++k) scenes.push_back(randomScene(random, 80 + random.below(150)));
  for (const scene::Scene& s : scenes) {
    RenderSettings settings;
    settings.width = 96;
    settings.height = 54;
    settings.coverage = true;
    settings.threads = 2;
    settings.samplesPerPixel = 2;
    Image with = renderImage(RenderScene(s), settings);
    settings.eyeGrid = false;
    Image without = renderImage(RenderScene(s, 0, false), settings);
    EXPECT_EQ(with.rgb, without.rgb);
    EXPECT_EQ(with.coverage, without.coverage);
  }
}

}  // namespace
}  // namespace render
