#include "renderer/adaptive_sampling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "renderer/camera.h"
#include "renderer/default_scene.h"
#include "renderer/render.h"
#include "renderer/test_scenes.h"

namespace render {
namespace {

using namespace render::testing;
using scene::ObjectKind;

TEST(AdaptiveSampling, SamplesDifferByColourOrByObject) {
  SampleLook grey = lookOf(glm::dvec3(0.5), 3);
  EXPECT_FALSE(looksDiffer(grey, lookOf({0.5, 0.5, 0.55}, 3), 0.1));
  EXPECT_TRUE(looksDiffer(grey, lookOf({0.5, 0.5, 0.65}, 3), 0.1));
  // Another object of the same colour: an edge that colours alone miss.
  EXPECT_TRUE(looksDiffer(grey, lookOf(glm::dvec3(0.5), 4), 0.1));
  EXPECT_TRUE(looksDiffer(grey, lookOf(glm::dvec3(0.5), RaySource::kNone), 0.1));
  // In the image's units: anything above 1 shows as 1.
  EXPECT_FALSE(looksDiffer(lookOf(glm::dvec3(2.0), 1), lookOf(glm::dvec3(7.0), 1), 0.01));
}

TEST(AdaptiveSampling, ASpreadExceedsWhereAnyTwoSamplesDiffer) {
  SampleSpread spread;
  spread.add(lookOf({0.2, 0.5, 0.5}, 1));
  spread.add(lookOf({0.25, 0.5, 0.5}, 1));
  EXPECT_FALSE(spread.exceeds(0.1));
  spread.add(lookOf({0.35, 0.5, 0.5}, 1));
  EXPECT_TRUE(spread.exceeds(0.1));  // 0.2 and 0.35
  SampleSpread objects;
  objects.add(lookOf(glm::dvec3(0.5), 1));
  objects.add(lookOf(glm::dvec3(0.5), 2));
  EXPECT_TRUE(objects.exceeds(0.9));
  EXPECT_FALSE(objects.coloursDiffer(0.0));
  EXPECT_TRUE(spread.coloursDiffer(0.1));
}

TEST(AdaptiveSampling, DepthIsTheMostCutsThatKeepSquaresWithinTheSamples) {
  EXPECT_EQ(subdivisionDepth(1), 0);
  EXPECT_EQ(subdivisionDepth(3), 0);
  EXPECT_EQ(subdivisionDepth(4), 1);
  EXPECT_EQ(subdivisionDepth(15), 1);
  EXPECT_EQ(subdivisionDepth(16), 2);
  EXPECT_EQ(subdivisionDepth(64), 3);
  EXPECT_EQ(subdivisionDepth(255), 3);
  EXPECT_EQ(subdivisionDepth(256), 4);
  EXPECT_EQ(subdivisionDepth(1 << 30), kMaxSubdivisionDepth);
}

// A pixel seen through a lattice: `left` left of the line x + 0.37 y = 0.55
// (x, y in [0, 1] across the pixel), `right` right of it; by default object
// 1 and object 2, each of its own grey. The part of the pixel left of the
// line is 0.55 - 0.37 / 2.
struct EdgedPixel {
  int side;
  SampleLook left = lookOf(glm::dvec3(0.2), 1);
  SampleLook right = lookOf(glm::dvec3(0.7), 2);
  SampleLook at(int point) const {
    double x = static_cast<double>(point % side) / (side - 1);
    double y = static_cast<double>(point / side) / (side - 1);
    return x + 0.37 * y < 0.55 ? left : right;
  }
  // Subdivides `lattice` as this pixel, at `threshold`: the cuts it made.
  int subdivide(PixelLattice& lattice, double threshold) const {
    const int last = side - 1;
    const SampleLook corners[4] = {at(0), at(last), at(last * side), at(last * side + last)};
    lattice.start(corners);
    return lattice.subdivide(threshold,
                             [&](const std::vector<int>& points, std::vector<SampleLook>& looks) {
                               for (std::size_t k = 0; k < points.size(); ++k) {
                                 looks[k] = at(points[k]);
                               }
                             });
  }
  static constexpr double kLeftShare = 0.55 - 0.37 / 2.0;
};

TEST(AdaptiveSampling, FinerSquaresAreCutOnlyWhereTheirCornersDifferByMore) {
  // One object, two greys `gap` apart: the pixel is cut where the gap
  // passes the threshold, a square `level` cuts down where it passes
  // threshold * 2^level. A gap of 1.5 * threshold * 2^k is cut k + 1 times.
  const double threshold = 0.02;
  PixelLattice lattice(5);
  for (int k = 0; k < 4; ++k) {
    double gap = 1.5 * threshold * std::ldexp(1.0, k);
    EdgedPixel pixel{lattice.side(), lookOf(glm::dvec3(0.2), 1), lookOf(glm::dvec3(0.2 + gap), 1)};
    EXPECT_EQ(pixel.subdivide(lattice, threshold), k + 1) << "gap " << gap;
  }
  EdgedPixel below{lattice.side(), lookOf(glm::dvec3(0.2), 1), lookOf(glm::dvec3(0.21), 1)};
  EXPECT_EQ(below.subdivide(lattice, threshold), 0);
}

TEST(AdaptiveSampling, TwoObjectsOfOneColourCutThePixelOnly) {
  // An edge that colours miss: the pixel is cut once, its squares are not.
  PixelLattice lattice(3);
  const glm::dvec3 grey(0.5);
  EdgedPixel pixel{lattice.side(), lookOf(grey, 1), lookOf(grey, 2)};
  EXPECT_EQ(pixel.subdivide(lattice, 0.01), 1);
  // The first cut's five points and the corners, each square a quarter.
  EXPECT_EQ(lattice.points().size(), 9u);
  // With the colours apart, the same edge is cut to the finest squares.
  EdgedPixel coloured{lattice.side(), lookOf(grey, 1), lookOf(glm::dvec3(0.6), 2)};
  EXPECT_EQ(coloured.subdivide(lattice, 0.01), 3);
}

TEST(AdaptiveSampling, ALatticeCutsAlongAnEdgeAndWeighsItsSquares) {
  for (int depth = 1; depth <= kMaxSubdivisionDepth; ++depth) {
    PixelLattice lattice(depth);
    EdgedPixel pixel{lattice.side()};
    const int last = lattice.side() - 1;
    const SampleLook corners[4] = {pixel.at(0), pixel.at(last), pixel.at(last * lattice.side()),
                                   pixel.at(last * lattice.side() + last)};
    std::vector<int> tracedAt(static_cast<std::size_t>(lattice.side()) * lattice.side(), 0);
    lattice.start(corners);
    int cuts = lattice.subdivide(
        0.01, [&](const std::vector<int>& points, std::vector<SampleLook>& looks) {
          ASSERT_EQ(points.size(), looks.size());
          for (std::size_t k = 0; k < points.size(); ++k) {
            ++tracedAt[points[k]];
            looks[k] = pixel.at(points[k]);
          }
        });
    EXPECT_EQ(cuts, depth);
    // No point twice, and no corner: those the pixel started with.
    for (int p = 0; p < static_cast<int>(tracedAt.size()); ++p) ASSERT_LE(tracedAt[p], 1) << p;
    EXPECT_EQ(tracedAt[0] + tracedAt[last] + tracedAt.back(), 0);
    // Only along the edge: a number of points that grows with the side, not
    // with its square (at depth 6, 129 x 129 points).
    int traced = 0;
    for (int n : tracedAt) traced += n;
    EXPECT_LE(traced, 8 * last) << "depth " << depth;
    // The weights: in lattice order, multiples of a lattice step's square's
    // quarter, summing to 1 exactly; the share of object 1 within the
    // finest squares' error of the true share.
    const double quantum = 0.25 / static_cast<double>(last * last);
    double sum = 0.0, left = 0.0;
    ASSERT_EQ(lattice.points().size(), lattice.weights().size());
    for (std::size_t k = 0; k < lattice.points().size(); ++k) {
      if (k > 0) {
        ASSERT_LT(lattice.points()[k - 1], lattice.points()[k]);
      }
      double w = lattice.weights()[k];
      ASSERT_EQ(std::fmod(w, quantum), 0.0);
      sum += w;
      if (pixel.at(lattice.points()[k]).object == 1) left += w;
    }
    EXPECT_EQ(sum, 1.0);
    EXPECT_NEAR(left, EdgedPixel::kLeftShare, 1.0 / last) << "depth " << depth;
  }
}

TEST(AdaptiveSampling, ASquareLeftWholeWhoseCornersHalfDifferTakesItsCentre) {
  // One object, two greys 1.5 x threshold apart, at depth 1: the pixel is
  // cut once; its quarters differ by less than their threshold (2 x) but
  // more than its half, so each quarter the edge crosses takes its centre,
  // and only those.
  const double threshold = 0.02;
  PixelLattice lattice(1);
  const int side = lattice.side();
  ASSERT_EQ(side, 5);
  EdgedPixel pixel{side, lookOf(glm::dvec3(0.2), 1), lookOf(glm::dvec3(0.2 + 1.5 * threshold), 1)};
  std::vector<int> centres;
  const int last = side - 1;
  const SampleLook corners[4] = {pixel.at(0), pixel.at(last), pixel.at(last * side),
                                 pixel.at(last * side + last)};
  lattice.start(corners);
  int cuts = lattice.subdivide(threshold,
                               [&](const std::vector<int>& points, std::vector<SampleLook>& looks) {
                                 for (std::size_t k = 0; k < points.size(); ++k) {
                                   int a = points[k] % side, b = points[k] / side;
                                   if (a % 2 == 1) centres.push_back(points[k]);
                                   EXPECT_EQ(a % 2, b % 2) << "not a quarter's centre or corner";
                                   looks[k] = pixel.at(points[k]);
                                 }
                               });
  EXPECT_EQ(cuts, 1);
  std::vector<int> crossed;
  for (int q : {0, 2, 2 * side, 2 * side + 2}) {
    const int quarter[4] = {q, q + 2, q + 2 * side, q + 2 * side + 2};
    bool left = false, right = false;
    for (int c : quarter) (pixel.at(c).colour.x < 0.21f ? left : right) = true;
    if (left && right) crossed.push_back(q + side + 1);
  }
  ASSERT_FALSE(crossed.empty());
  std::sort(centres.begin(), centres.end());
  EXPECT_EQ(centres, crossed);
  // Each centre half its quarter: weight 1/8; the weights sum to 1.
  double sum = 0.0;
  for (std::size_t k = 0; k < lattice.points().size(); ++k) {
    int p = lattice.points()[k];
    if (std::find(crossed.begin(), crossed.end(), p) != crossed.end()) {
      EXPECT_EQ(lattice.weights()[k], 0.125);
    }
    sum += lattice.weights()[k];
  }
  EXPECT_EQ(sum, 1.0);
  // Two objects of one colour: the pixel is cut, and its quarters take no
  // centre, as their colours agree.
  EdgedPixel grey{side, lookOf(glm::dvec3(0.5), 1), lookOf(glm::dvec3(0.5), 2)};
  const SampleLook greyCorners[4] = {grey.at(0), grey.at(last), grey.at(last * side),
                                     grey.at(last * side + last)};
  lattice.start(greyCorners);
  int traced = 0;
  EXPECT_EQ(lattice.subdivide(threshold,
                              [&](const std::vector<int>& points, std::vector<SampleLook>& looks) {
                                traced += static_cast<int>(points.size());
                                for (std::size_t k = 0; k < points.size(); ++k) {
                                  looks[k] = grey.at(points[k]);
                                }
                              }),
            1);
  EXPECT_EQ(traced, 5);
}

TEST(AdaptiveSampling, ALatticeTracesNothingWhereCornersAgreeOrPointsAreLent) {
  PixelLattice lattice(3);
  const int side = lattice.side(), last = side - 1;
  const SampleLook grey = lookOf(glm::dvec3(0.5), 1);
  const SampleLook same[4] = {grey, grey, grey, grey};
  int traced = 0;
  auto count = [&](const std::vector<int>& points, std::vector<SampleLook>& looks) {
    traced += static_cast<int>(points.size());
    for (SampleLook& look : looks) look = grey;
  };
  lattice.start(same);
  EXPECT_EQ(lattice.subdivide(0.01, count), 0);
  EXPECT_EQ(traced, 0);
  EXPECT_EQ(lattice.points(), (std::vector<int>{0, last, last * side, last * side + last}));
  EXPECT_EQ(lattice.weights(), std::vector<double>(4, 0.25));

  // The same pixel with its left side lent by a neighbour: those points are
  // not traced again, and the pixel is the same.
  EdgedPixel pixel{side};
  const SampleLook corners[4] = {pixel.at(0), pixel.at(last), pixel.at(last * side),
                                 pixel.at(last * side + last)};
  auto trace = [&](const std::vector<int>& points, std::vector<SampleLook>& looks) {
    for (std::size_t k = 0; k < points.size(); ++k) {
      ASSERT_NE(points[k] % side, 0) << "a lent point traced";
      looks[k] = pixel.at(points[k]);
      ++traced;
    }
  };
  lattice.start(corners);
  lattice.subdivide(0.01, [&](const std::vector<int>& points, std::vector<SampleLook>& looks) {
    for (std::size_t k = 0; k < points.size(); ++k) looks[k] = pixel.at(points[k]);
  });
  const std::vector<int> points = lattice.points();
  const std::vector<double> weights = lattice.weights();
  lattice.start(corners);
  for (int b = 1; b < last; ++b) lattice.preset(b * side, pixel.at(b * side));
  traced = 0;
  lattice.subdivide(0.01, trace);
  EXPECT_GT(traced, 0);
  EXPECT_EQ(lattice.points(), points);
  EXPECT_EQ(lattice.weights(), weights);
}

RenderSettings adaptiveSettings(int spp, double threshold) {
  RenderSettings settings;
  settings.width = 64;
  settings.height = 48;
  settings.samplesPerPixel = spp;
  settings.adaptiveThreshold = threshold;
  settings.coverage = true;
  return settings;
}

TEST(AdaptiveSampling, TheSameImageAtAnyThreadCount) {
  RenderScene compiled(defaultScene());
  RenderSettings settings = adaptiveSettings(16, 0.02);
  settings.seed = 3;
  settings.threads = 1;
  Image one = renderImage(compiled, settings);
  for (int threads : {2, 3}) {
    settings.threads = threads;
    Image many = renderImage(compiled, settings);
    ASSERT_EQ(one.rgb, many.rgb) << threads << " threads";
    ASSERT_EQ(one.coverage, many.coverage) << threads << " threads";
  }
}

// The runs of TileEdgeCorners hold every corner on a tile's edge once, and
// no other, each in a place of its own.
TEST(AdaptiveSampling, TileEdgeRunsCoverEveryEdgeCornerOnce) {
  struct Case {
    int x0, y0, width, height, tile;
  };
  for (Case c : {Case{0, 0, 64, 48, 32}, Case{5, 7, 65, 33, 32}, Case{0, 0, 1, 40, 32},
                 Case{3, 0, 97, 1, 32}, Case{0, 0, 31, 32, 32}, Case{2, 9, 10, 11, 3},
                 Case{0, 0, 7, 5, 1}}) {
    TileEdgeCorners edges(c.x0, c.y0, c.width, c.height, c.tile);
    const int x1 = c.x0 + c.width, y1 = c.y0 + c.height;
    auto edgeColumn = [&](int x) { return (x - c.x0) % c.tile == 0 || x == x1; };
    auto edgeRow = [&](int y) { return (y - c.y0) % c.tile == 0 || y == y1; };
    std::vector<int> seen(static_cast<std::size_t>(c.width + 1) * (c.height + 1), 0);
    std::vector<const SampleColour*> places;
    for (std::size_t r = 0; r < edges.runCount(); ++r) {
      const TileEdgeCorners::Run& run = edges.run(r);
      SampleColour* samples = edges.samples(run);
      for (int k = 0; k < run.count; ++k) {
        int x = run.x + (run.down ? 0 : k), y = run.y + (run.down ? k : 0);
        ASSERT_TRUE(x >= c.x0 && x <= x1 && y >= c.y0 && y <= y1) << x << "," << y;
        ASSERT_TRUE(edgeRow(y) || edgeColumn(x)) << x << "," << y;
        ++seen[static_cast<std::size_t>(y - c.y0) * (c.width + 1) + (x - c.x0)];
        samples[k].slack = x * 1000.0 + y;
        ASSERT_EQ(edges.onEdgeRow(y), edgeRow(y)) << y;
        places.push_back(&edges.sample(x, y));
        ASSERT_EQ(places.back(), samples + k);
      }
    }
    for (int y = c.y0; y <= y1; ++y) {
      for (int x = c.x0; x <= x1; ++x) {
        int expected = edgeRow(y) || edgeColumn(x) ? 1 : 0;
        ASSERT_EQ(seen[static_cast<std::size_t>(y - c.y0) * (c.width + 1) + (x - c.x0)], expected)
            << x << "," << y << " of " << c.width << "x" << c.height;
        if (expected) {
          ASSERT_EQ(edges.sample(x, y).slack, x * 1000.0 + y);
        }
      }
    }
    std::sort(places.begin(), places.end());
    ASSERT_EQ(std::adjacent_find(places.begin(), places.end()), places.end());
    ASSERT_LE(
        edges.runCount() * sizeof(TileEdgeCorners::Run) + places.size() * sizeof(SampleColour),
        TileEdgeCorners::bytesFor(c.width, c.height, c.tile));
  }
}

// Pass 1's edge corners and each tile's own: every pixel corner of the
// region traced once, whatever the threads and the region's size.
TEST(AdaptiveSampling, EveryPixelCornerIsTracedOnce) {
  RenderScene compiled(defaultScene());
  for (auto [width, height] :
       {std::pair{64, 48}, std::pair{33, 1}, std::pair{1, 65}, std::pair{70, 31}}) {
    for (int threads : {1, 3}) {
      RenderSettings settings = adaptiveSettings(2, 0.02);  // depth 0: corners alone
      settings.width = width;
      settings.height = height;
      settings.threads = threads;
      RenderStatistics statistics;
      renderImage(compiled, settings, &statistics);
      EXPECT_EQ(statistics.samples, static_cast<std::uint64_t>(width + 1) * (height + 1))
          << width << "x" << height << ", " << threads << " threads";
    }
  }
}

// The RMSE of `image` against `reference`, each value clamped to [0, 1] as
// a picture shows it.
double clampedRmse(const Image& image, const Image& reference) {
  double sum = 0.0;
  for (std::size_t k = 0; k < image.rgb.size(); ++k) {
    double d = std::clamp(image.rgb[k], 0.0f, 1.0f) - std::clamp(reference.rgb[k], 0.0f, 1.0f);
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(image.rgb.size()));
}

// Against a 256-spp reference, adaptive sampling at 16 is closer than
// uniform 4 with fewer samples, and at 64 closer than uniform 16 (and than
// adaptive at 16) with fewer samples. On the default scene at 160x120 the
// RMSEs are 0.0023 (3.4 samples a pixel) against 0.0082, and 0.0010 (6.5)
// against 0.0027.
TEST(AdaptiveSampling, ErrorFallsWithDepthAtAFractionOfTheSamples) {
  RenderScene compiled(defaultScene());
  RenderSettings settings = adaptiveSettings(256, 0.0);
  settings.width = 160;
  settings.height = 120;
  settings.seed = 11;
  Image reference = renderImage(compiled, settings);
  auto rmse = [&](const Image& image) { return clampedRmse(image, reference); };
  auto render = [&](int spp, double threshold, RenderStatistics* statistics) {
    RenderSettings s = settings;
    s.samplesPerPixel = spp;
    s.adaptiveThreshold = threshold;
    return renderImage(compiled, s, statistics);
  };
  RenderStatistics at16, at64;
  double adaptive16 = rmse(render(16, 0.01, &at16)), adaptive64 = rmse(render(64, 0.01, &at64));
  double uniform4 = rmse(render(4, 0.0, nullptr)), uniform16 = rmse(render(16, 0.0, nullptr));
  EXPECT_LT(adaptive16, uniform4);
  EXPECT_LT(adaptive64, adaptive16);
  EXPECT_LT(adaptive64, uniform16);
  std::uint64_t pixels = at64.pixels;
  EXPECT_LT(at64.samples, 16 * pixels);
  EXPECT_LT(at16.samples, 4 * pixels);
  // The corners, (160 + 1) x (120 + 1), and the refined pixels' points.
  EXPECT_GT(at16.samples, 161u * 121u);
  EXPECT_GT(at16.refinedPixels, 0u);
  EXPECT_LT(at16.refinedPixels, pixels / 2);
  EXPECT_GE(at16.refinedPixels, at16.fullySampledPixels);
  EXPECT_EQ(at16.refinedPixels, at64.refinedPixels);  // decided at the corners
}

// A pixel that is not cut but whose corners differ by more than half the
// threshold takes its centre too: an eighth of each corner and half the
// centre. Here one wall fills the view, so no pixel shows two objects, and
// at a threshold of 1 no colours differ enough to cut one; the shadow of a
// cube behind the camera crosses the wall, its edge 0.7 deep. The corners'
// mean is the `--spp 2` image (no cut at depth 0) and the centre the
// uniform `--spp 1` image, so every pixel is the first or the mean of the
// two, and the pixels on the shadow's edge are the mean.
TEST(AdaptiveSampling, CornersThatDifferByHalfTheThresholdAddTheCentre) {
  scene::Scene s = sceneLookingAt({0, 0, 0}, {0, 0, -1});
  scene::Material wall = flat({0.8, 0.8, 0.8}, 0.1);
  wall.diffuse = 0.9;
  s.objects.push_back(object(ObjectKind::Cube, {scale(20, 20, 1), translate(0, 0, -5)}, wall));
  s.objects.push_back(object(ObjectKind::Cube, {scale(0.5, 0.5, 0.5), translate(0.2, 0.1, 2)}));
  s.lights.push_back(light({0, 0, 5}));
  RenderScene compiled(s);
  RenderSettings settings = adaptiveSettings(16, 1.0);
  settings.width = 160;
  settings.height = 120;
  settings.coverage = false;
  // Every corner traced, as the `--spp 2` image's are.
  settings.interpolatesCorners = false;
  RenderStatistics statistics;
  Image adaptive = renderImage(compiled, settings, &statistics);
  RenderSettings cornersOnly = settings;
  cornersOnly.samplesPerPixel = 2;
  Image corners = renderImage(compiled, cornersOnly);
  RenderSettings centresOnly = settings;
  centresOnly.samplesPerPixel = 1;
  centresOnly.adaptiveThreshold = 0.0;
  Image centres = renderImage(compiled, centresOnly);
  std::uint64_t centred = 0;
  for (int j = 0; j < settings.height; ++j) {
    for (int i = 0; i < settings.width; ++i) {
      glm::vec3 a = adaptive.pixel(i, j), c = corners.pixel(i, j), m = centres.pixel(i, j);
      if (a == c) continue;
      ++centred;
      ASSERT_NEAR(a.x, 0.5f * c.x + 0.5f * m.x, 1e-6f) << i << "," << j;
      ASSERT_NEAR(a.y, 0.5f * c.y + 0.5f * m.y, 1e-6f) << i << "," << j;
      ASSERT_NEAR(a.z, 0.5f * c.z + 0.5f * m.z, 1e-6f) << i << "," << j;
    }
  }
  EXPECT_EQ(statistics.refinedPixels, 0u);
  EXPECT_EQ(statistics.retracedPixels, 0u);
  // The shadow's edge, about 4 x 50 pixels long, gives some 200.
  EXPECT_GT(centred, 100u);
  EXPECT_LE(centred, statistics.centredPixels);
  EXPECT_EQ(statistics.samples, 161u * 121u + statistics.centredPixels);

  // At depth 0 (`--spp` 2 or 3) no pixel takes its centre.
  RenderStatistics shallow;
  renderImage(compiled, cornersOnly, &shallow);
  EXPECT_EQ(shallow.centredPixels, 0u);
  EXPECT_EQ(shallow.samples, 161u * 121u);
}

TEST(AdaptiveSampling, ACornerBetweenAnchorsIsTheirMeanWhereTheyAgree) {
  CornerInterpolation rule{0.1, 5, 4};
  int anchors[4][2];
  EXPECT_EQ(rule.anchorsOf(2, 2, anchors), 0);  // an anchor: traced
  ASSERT_EQ(rule.anchorsOf(3, 2, anchors), 2);
  EXPECT_EQ((std::vector<int>{anchors[0][0], anchors[0][1], anchors[1][0], anchors[1][1]}),
            (std::vector<int>{2, 2, 4, 2}));
  ASSERT_EQ(rule.anchorsOf(2, 1, anchors), 2);
  EXPECT_EQ((std::vector<int>{anchors[0][0], anchors[0][1], anchors[1][0], anchors[1][1]}),
            (std::vector<int>{2, 0, 2, 2}));
  EXPECT_EQ(rule.anchorsOf(1, 3, anchors), 4);
  // Corner 5 of an image 5 pixels wide has no anchor to its right.
  EXPECT_EQ(rule.anchorsOf(5, 2, anchors), 0);
  EXPECT_EQ(rule.anchorsOf(3, 4, anchors), 2);
  EXPECT_EQ(CornerInterpolation{}.anchorsOf(3, 2, anchors), 0);  // off

  SampleLook near[2] = {lookOf({0.5, 0.5, 0.5}, 1), lookOf({0.55, 0.5, 0.5}, 1)};
  EXPECT_TRUE(rule.agree(3, 2, near, 2));
  SampleLook far[2] = {lookOf({0.5, 0.5, 0.5}, 1), lookOf({0.65, 0.5, 0.5}, 1)};
  EXPECT_FALSE(rule.agree(3, 2, far, 2));
  SampleLook objects[2] = {lookOf({0.5, 0.5, 0.5}, 1), lookOf({0.5, 0.5, 0.5}, 2)};
  EXPECT_FALSE(rule.agree(3, 2, objects, 2));

  SampleColour a{{0.25, 0.5, 0.75}, 0.125, 3}, b{{0.75, 0.5, 0.25}, 0.375, 3};
  const SampleColour* pair[2] = {&a, &b};
  SampleColour mean = meanOf(pair, 2);
  EXPECT_EQ(mean.colour, glm::dvec3(0.5));
  EXPECT_EQ(mean.slack, 0.25);
  EXPECT_EQ(mean.object, 3u);
}

// With coarse anchors on, an anchor (both coordinates even) off the
// multiples of 4 lies between coarse anchors two corners away, is known
// before the corners between anchors, and agrees at its own tolerance.
TEST(AdaptiveSampling, AnAnchorBetweenCoarseAnchorsIsTheirMeanWhereTheyAgree) {
  CornerInterpolation rule{0.1, 10, 6, nullptr, 0.05};
  ASSERT_TRUE(rule.coarse());
  int anchors[4][2];
  auto listed = [&](int count) {
    std::vector<int> v;
    for (int a = 0; a < count; ++a) v.insert(v.end(), {anchors[a][0], anchors[a][1]});
    return v;
  };
  EXPECT_EQ(rule.stageOf(4, 4), 0);
  EXPECT_EQ(rule.anchorsOf(4, 4, anchors), 0);  // a coarse anchor: traced
  EXPECT_EQ(rule.stageOf(2, 0), 1);
  EXPECT_EQ(listed(rule.anchorsOf(2, 0, anchors)), (std::vector<int>{0, 0, 4, 0}));
  EXPECT_EQ(listed(rule.anchorsOf(4, 2, anchors)), (std::vector<int>{4, 0, 4, 4}));
  EXPECT_EQ(listed(rule.anchorsOf(2, 2, anchors)), (std::vector<int>{0, 0, 4, 0, 0, 4, 4, 4}));
  // Corner 10 of an image 10 pixels wide has no coarse anchor to its right.
  EXPECT_EQ(rule.anchorsOf(10, 0, anchors), 0);
  EXPECT_EQ(rule.stageOf(3, 2), 2);
  EXPECT_EQ(listed(rule.anchorsOf(3, 2, anchors)), (std::vector<int>{2, 2, 4, 2}));
  // Without coarse anchors every even corner is an anchor, traced.
  CornerInterpolation fine{0.1, 10, 6};
  EXPECT_EQ(fine.stageOf(2, 0), 0);
  EXPECT_EQ(fine.anchorsOf(2, 0, anchors), 0);

  SampleLook near[2] = {lookOf({0.5, 0.5, 0.5}, 1), lookOf({0.54, 0.5, 0.5}, 1)};
  EXPECT_TRUE(rule.agree(2, 0, near, 2));
  SampleLook apart[2] = {lookOf({0.5, 0.5, 0.5}, 1), lookOf({0.57, 0.5, 0.5}, 1)};
  EXPECT_FALSE(rule.agree(2, 0, apart, 2));  // beyond the coarse tolerance
  EXPECT_TRUE(rule.agree(3, 0, apart, 2));   // within the corners'
}

// Coarse anchors spare samples for the same error: on the default scene at
// 160x120, 20,142 against 22,320 at --adaptive 0.1 --spp 16, for about the
// same RMSE (more at 1280x720, where more of the image is flat).
TEST(AdaptiveSampling, CoarseAnchorsSpareSamplesForAboutTheSameError) {
  RenderScene compiled(defaultScene());
  RenderSettings settings = adaptiveSettings(256, 0.0);
  settings.width = 160;
  settings.height = 120;
  Image reference = renderImage(compiled, settings);
  settings.samplesPerPixel = 16;
  settings.adaptiveThreshold = 0.1;
  RenderStatistics fine, coarse;
  settings.interpolatesAnchors = false;
  double fineError = clampedRmse(renderImage(compiled, settings, &fine), reference);
  settings.interpolatesAnchors = true;
  double coarseError = clampedRmse(renderImage(compiled, settings, &coarse), reference);
  EXPECT_LT(coarse.samples, fine.samples * 92 / 100);
  EXPECT_LT(coarseError, fineError * 1.02);
}

// Thin red posts before a grey wall, each 1.2 pixels wide, at various
// offsets from the anchors (even pixel corners): a post between two anchors
// that see the wall is missed by both.
scene::Scene thinPostsBeforeAWall(const RenderSettings& settings) {
  scene::Scene s = sceneLookingAt({0, 0, 5}, {0, 0, 0});
  s.objects.push_back(
      object(ObjectKind::Cube, {scale(20, 20, 1), translate(0, 0, -3)}, flat({0.5, 0.5, 0.5})));
  PinholeCamera camera(s.camera, settings);
  // The width of a pixel at the posts' distance (5).
  double pixel = 2.0 * camera.tanHalfWidth() * 5.0 / settings.width;
  for (double x : {8.3, 15.6, 23.0, 30.9, 38.5, 46.2, 53.7}) {
    double centre = (x - 0.5 * settings.width) * pixel;
    s.objects.push_back(object(ObjectKind::Cylinder,
                               {scale(0.6 * pixel, 10.0, 0.6 * pixel), translate(centre, 0, 0)},
                               flat({1.0, 0.0, 0.0})));
  }
  s.lights.push_back(light({0, 0, 5}));
  return s;
}

TEST(AdaptiveSampling, AnObjectBetweenAgreeingAnchorsIsTracedNotLost) {
  for (int spp : {4, 16}) {
    RenderSettings settings = adaptiveSettings(spp, 0.1);
    RenderScene compiled(thinPostsBeforeAWall(settings));
    Image interpolated = renderImage(compiled, settings);
    settings.interpolatesCorners = false;
    Image traced = renderImage(compiled, settings);
    float worst = 0.0f;
    for (std::size_t k = 0; k < traced.rgb.size(); ++k) {
      worst = std::max(worst, std::abs(interpolated.rgb[k] - traced.rgb[k]));
    }
    EXPECT_LE(worst, settings.adaptiveThreshold) << spp << " spp";
  }
}

// An anchor between coarse anchors that saw the wall is traced where a post
// reaches their block, so every pixel on a post has its corners traced, as
// without coarse anchors: the same pixel, bit for bit.
TEST(AdaptiveSampling, AnObjectBetweenAgreeingCoarseAnchorsIsTracedNotLost) {
  RenderSettings settings = adaptiveSettings(16, 0.1);
  RenderScene compiled(thinPostsBeforeAWall(settings));
  Image coarse = renderImage(compiled, settings);
  settings.interpolatesAnchors = false;
  Image fine = renderImage(compiled, settings);
  int onPosts = 0;
  for (int j = 0; j < settings.height; ++j) {
    for (int i = 0; i < settings.width; ++i) {
      glm::vec3 f = fine.pixel(i, j);
      if (f.x - f.y < 0.3f) continue;  // not red: the wall's
      ++onPosts;
      ASSERT_EQ(coarse.pixel(i, j), f) << i << "," << j;
    }
  }
  EXPECT_GT(onPosts, 7 * settings.height);
}

// Corners taken from agreeing anchors spare so many samples that half the
// threshold costs fewer than tracing every corner, for less error: on the
// default scene at 160x120, 23,077 samples against 29,528 and RMSE 0.00265
// against 0.00298 (larger images have more corners between agreeing
// anchors, and spare more).
TEST(AdaptiveSampling, InterpolatedCornersGiveLessErrorForFewerSamples) {
  RenderScene compiled(defaultScene());
  RenderSettings settings = adaptiveSettings(256, 0.0);
  settings.width = 160;
  settings.height = 120;
  Image reference = renderImage(compiled, settings);
  auto rmse = [&](const Image& image) { return clampedRmse(image, reference); };
  settings.samplesPerPixel = 16;
  settings.adaptiveThreshold = 0.1;
  RenderStatistics traced, interpolated;
  settings.interpolatesCorners = false;
  double tracedError = rmse(renderImage(compiled, settings, &traced));
  settings.interpolatesCorners = true;
  settings.adaptiveThreshold = 0.05;
  double interpolatedError = rmse(renderImage(compiled, settings, &interpolated));
  EXPECT_LT(interpolated.samples, traced.samples * 17 / 20);
  EXPECT_LT(interpolatedError, tracedError);
}

TEST(AdaptiveSampling, OneSampleAPixelRefinesNothing) {
  RenderScene compiled(defaultScene());
  RenderSettings settings = adaptiveSettings(1, 0.01);
  RenderStatistics statistics;
  Image adaptive = renderImage(compiled, settings, &statistics);
  settings.adaptiveThreshold = 0.0;
  EXPECT_EQ(adaptive.rgb, renderImage(compiled, settings).rgb);
  EXPECT_EQ(statistics.refinedPixels, 0u);
  EXPECT_EQ(statistics.samples, statistics.pixels);
}

// A sphere before a wall of nearly its colour: the two differ by far less
// than the threshold, and only the change of object shows the edge.
scene::Scene sphereOnWallOfItsColour() {
  scene::Scene s = sceneLookingAt({0, 0, 5}, {0, 0, 0});
  s.objects.push_back(object(ObjectKind::Sphere, {}, flat({0.5, 0.5, 0.5})));
  s.objects.push_back(
      object(ObjectKind::Cube, {scale(20, 20, 1), translate(0, 0, -3)}, flat({0.5, 0.5, 0.502})));
  s.lights.push_back(light({0, 0, 5}));
  return s;
}

TEST(AdaptiveSampling, RefinesAnEdgeBetweenObjectsOfOneColour) {
  scene::Scene s = sphereOnWallOfItsColour();
  RenderScene compiled(s);
  RenderSettings settings = adaptiveSettings(16, 0.1);
  settings.coverage = false;
  RenderStatistics statistics;
  Image adaptive = renderImage(compiled, settings, &statistics);
  settings.adaptiveThreshold = 0.0;
  settings.samplesPerPixel = 1;
  Image centres = renderImage(compiled, settings);
  std::vector<std::int32_t> ids = renderObjectIds(compiled, settings);
  auto id = [&](int i, int j) { return ids[static_cast<std::size_t>(j) * settings.width + i]; };
  // Every pixel that changed lies beside the sphere's silhouette, and some do.
  int changed = 0;
  for (int j = 0; j < settings.height; ++j) {
    for (int i = 0; i < settings.width; ++i) {
      std::size_t p = 3 * (static_cast<std::size_t>(j) * settings.width + i);
      if (adaptive.rgb[p + 2] == centres.rgb[p + 2]) continue;
      ++changed;
      // Beside: a neighbour, diagonal ones too (a pixel's corner is shared
      // with its diagonal neighbour), shows another object at its centre.
      bool edge = false;
      for (int dj = -1; dj <= 1; ++dj) {
        for (int di = -1; di <= 1; ++di) {
          int x = i + di, y = j + dj;
          if (x >= 0 && x < settings.width && y >= 0 && y < settings.height &&
              id(x, y) != id(i, j)) {
            edge = true;
          }
        }
      }
      EXPECT_TRUE(edge) << i << "," << j;
    }
  }
  EXPECT_GT(changed, 8);
  EXPECT_GT(statistics.refinedPixels, 0u);

  // Without the sphere nothing differs, and nothing is refined.
  s.objects.erase(s.objects.begin());
  settings.adaptiveThreshold = 0.1;
  settings.samplesPerPixel = 16;
  renderImage(RenderScene(s), settings, &statistics);
  EXPECT_EQ(statistics.refinedPixels, 0u);
}

// The coverage of a pixel is the weighted share of its samples that met an
// object: the wall's edge at x = 4.5625 cuts column 4's 4 x 4 squares
// between the lattice points 4.5 and 4.75, so of its columns of squares the
// last counts whole, the third three quarters (two of its four corners hit,
// an eighth each, and its centre at 4.625, a half), and the first two not at
// all: 1.75 of 4, the true share.
TEST(AdaptiveSampling, CoverageIsTheWeightedShareOfTheSamplesThatHit) {
  scene::Scene s = sceneLookingAt({0, 0, 0}, {0, 0, -1});
  RenderSettings settings = adaptiveSettings(16, 0.05);
  settings.width = 9;
  settings.height = 5;
  // x = 4.5625 of 9 columns, on the plane z = -4 (the wall's front), 60
  // degrees of vertical view over 5 rows.
  double tanHalfWidth = std::tan(std::numbers::pi / 6.0) * 9.0 / 5.0;
  double edge = (2.0 * 4.5625 / 9.0 - 1.0) * tanHalfWidth * 4.0;
  s.objects.push_back(object(ObjectKind::Cube, {scale(10, 10, 1), translate(edge + 10, 0, -5)},
                             flat({0.8, 0.4, 0.2})));
  s.lights.push_back(light({0, 0, 0}));
  RenderScene compiled(s);
  Image image = renderImage(compiled, settings);
  for (int j = 0; j < settings.height; ++j) {
    for (int i = 0; i < settings.width; ++i) {
      float expected = i < 4 ? 0.0f : i == 4 ? 0.4375f : 1.0f;
      float alpha = image.coverage[static_cast<std::size_t>(j) * settings.width + i];
      ASSERT_EQ(alpha, expected) << i << "," << j;
      ASSERT_FLOAT_EQ(image.pixel(i, j).x, 0.8f * expected) << i << "," << j;
    }
  }
}

}  // namespace
}  // namespace render
