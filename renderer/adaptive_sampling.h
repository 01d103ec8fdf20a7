// Adaptive anti-aliasing's decisions (docs/RENDERING.md, "Adaptive
// sampling"): which pixels get more than their centre sample, and how many.
// Every decision reads samples that are functions of their own pixel's
// coordinates and the seed, so a pixel comes out the same whatever the
// threads, the tile order or the region rendered.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "renderer/huge_pages.h"
#include "renderer/render_scene.h"

namespace render {

class AnchorBlocks;

// A camera sample's colour, the bound on what adaptive depth control left
// out of it (TraceContext::slack), and the object its ray met (or
// RaySource::kNone).
struct SampleColour {
  glm::dvec3 colour{0.0};
  double slack = 0.0;
  std::uint32_t object = RaySource::kNone;
  bool hit() const { return object != RaySource::kNone; }
};

// What one camera sample showed, as far as the decisions need it: its colour
// as an image shows it (each channel clamped to [0, 1]) and the object its
// ray met first (RaySource::kNone: the background).
struct SampleLook {
  glm::vec3 colour{0.0f};
  std::uint32_t object = RaySource::kNone;
};

// The look of a traced colour and the object its camera ray met. Inline,
// as SampleSpread's members are: they run for every corner of every pixel.
inline SampleLook lookOf(const glm::dvec3& colour, std::uint32_t object) {
  SampleLook look;
  for (int c = 0; c < 3; ++c) {
    // NaN, which the image stores as 0, compares as 0 here too.
    double v = colour[c] == colour[c] ? colour[c] : 0.0;
    look.colour[c] = static_cast<float>(std::clamp(v, 0.0, 1.0));
  }
  look.object = object;
  return look;
}

// Whether two samples differ by more than `threshold` in some channel, or
// show different objects (an edge between two objects of one colour).
bool looksDiffer(const SampleLook& a, const SampleLook& b, double threshold);

// The range of a set of samples: whether any two of them differ as
// looksDiffer says, without keeping them all.
class SampleSpread {
 public:
  void add(const SampleLook& look) {
    if (empty_) {
      low_ = high_ = look.colour;
      object_ = look.object;
      empty_ = false;
      return;
    }
    low_ = glm::min(low_, look.colour);
    high_ = glm::max(high_, look.colour);
    mixedObjects_ = mixedObjects_ || look.object != object_;
  }
  // Whether the samples show different objects, or differ by more than
  // `threshold` in some channel.
  bool exceeds(double threshold) const { return mixedObjects_ || coloursDiffer(threshold); }
  // Whether they differ by more than `threshold` in some channel, whatever
  // the objects.
  bool coloursDiffer(double threshold) const {
    for (int c = 0; c < 3; ++c) {
      if (static_cast<double>(high_[c]) - low_[c] > threshold) return true;
    }
    return false;
  }

 private:
  glm::vec3 low_{0.0f}, high_{0.0f};
  std::uint32_t object_ = RaySource::kNone;
  bool mixedObjects_ = false;
  bool empty_ = true;
};

// The depth of adaptive subdivision for `samplesPerPixel`: the most times a
// pixel's squares are cut in four, floor(log4 samplesPerPixel), so that a
// pixel holds at most samplesPerPixel squares; at most kMaxSubdivisionDepth.
inline constexpr int kMaxSubdivisionDepth = 6;
int subdivisionDepth(int samplesPerPixel);

// One pixel's adaptive subdivision (docs/RENDERING.md, "Adaptive sampling").
// Its samples lie on a lattice of side() x side() points, side() =
// 2^(depth + 1) + 1, a step finer than the finest squares so that each has
// a centre: point (a, b), index b * side() + a, sits at (a, b) / 2^(depth +
// 1) of a pixel from the pixel's top-left corner. The pixel starts as one
// square, its four corners; a square whose corners differ (SampleSpread) is
// cut into four, which needs the looks of up to five more points, down to
// `depth` cuts. The pixel is cut where its corners show different objects
// or colours that differ by more than the threshold; a square `level` cuts
// down, only where its corners' colours differ by more than threshold *
// 2^level. A square left whole counts as the mean of its corners, or, where
// they differ by more than half its level's threshold, as half their mean
// and half its centre (one sample where a cut takes five). Which squares are
// cut depends on the looks alone, so a pixel is the same however its points
// are traced. One for each thread: it keeps its arrays from pixel to pixel.
class PixelLattice {
 public:
  explicit PixelLattice(int depth);

  int depth() const { return depth_; }
  int side() const { return side_; }

  // Traces the points of one level of cuts: looks[k] for points[k], which
  // are lattice indices not traced before in this pixel.
  using TraceLevel =
      std::function<void(const std::vector<int>& points, std::vector<SampleLook>& looks)>;

  // Starts a pixel whose corners look as `corners` says (top-left,
  // top-right, bottom-left, bottom-right).
  void start(const SampleLook corners[4]);
  // A point whose look is known already (traced for a neighbouring pixel,
  // the same sample): subdivide uses it instead of tracing it.
  void preset(int point, const SampleLook& look);
  bool known(int point) const { return known_[point] != 0; }

  // Subdivides the pixel started, tracing the points it needs level by
  // level. Returns the number of levels it cut (0: none; depth(): the
  // finest).
  int subdivide(double threshold, const TraceLevel& traceLevel);

  // After subdivide: the points the pixel is the weighted mean of, in
  // lattice order, and their weights (parallel): multiples of
  // 4^-(depth + 1) / 4 that sum to 1, all exact in a double.
  const std::vector<int>& points() const { return points_; }
  const std::vector<double>& weights() const { return weights_; }

 private:
  int depth_;
  int side_;
  std::vector<SampleLook> looks_;
  std::vector<double> weightOf_;
  std::vector<std::uint8_t> known_;
  std::vector<int> touched_;
  std::vector<int> points_;
  std::vector<double> weights_;
  // Lattices of up to this many points (depth 2) are read in order for
  // their weighted points; larger ones sort the points the pixel touched.
  static constexpr int kScannedLattice = 81;
  // subdivide's work lists, kept to spare their allocations.
  std::vector<int> squares_, next_, queued_;
  std::vector<SampleLook> traced_;
};

// The samples on the sides of the pixels last subdivided in a row of
// `columns` pixels (a tile's): the right side of the pixel to the left, and
// the bottom side of the pixel above each column, which the next pixel's
// lattice shares. Lending them traces a shared point once, not twice; a
// point's sample is the same whichever pixel traces it, so the image is the
// same either way. One for each thread.
class SharedSides {
 public:
  SharedSides(int side, int columns);

  // A new tile: no pixel above; a new row: no pixel to the left.
  void startTile();
  void startRow() { rightValid_ = false; }

  // Presets the lattice of the pixel in `column`, just started, with the
  // points its neighbours traced, and `samples` (indexed by lattice point)
  // with their samples.
  void lend(int column, PixelLattice& lattice, SampleColour* samples) const;
  // Keeps the right and bottom sides of the pixel in `column`, just
  // subdivided, for its neighbours.
  void keep(int column, const PixelLattice& lattice, const SampleColour* samples);
  // The pixel in `column` traced no point of its sides.
  void forget(int column) {
    rightValid_ = false;
    bottomValid_[column] = 0;
  }

 private:
  int side_;
  std::vector<SampleColour> right_;
  std::vector<std::uint8_t> rightKnown_;
  bool rightValid_ = false;
  std::vector<SampleColour> bottom_;
  std::vector<std::uint8_t> bottomKnown_;
  std::vector<std::uint8_t> bottomValid_;
};

// Which pixel corners adaptive sampling takes from their neighbours instead
// of tracing (docs/RENDERING.md, "Adaptive sampling"). A corner (x, y) of
// the full image with x and y even is an anchor; any other lies between two
// anchors (x or y odd) or four (both odd), and is their mean where they
// show one object and colours within `tolerance`, and no other bounded
// object reaches the square or side between them (`blocks`), else traced.
// With coarse anchors on, anchors come in two levels: those with x and y
// multiples of 4 are always traced, and any other anchor lies between two
// or four of them, two corners away, and is their mean where they agree
// within `coarseTolerance` and no other object reaches the 4 x 4 block or
// side between them (`coarseBlocks`); without, every anchor is traced. A
// corner's sample is thus a function of its position alone, whichever tile
// or region asks for it.
struct CornerInterpolation {
  double tolerance = -1.0;  // below 0: every corner is traced
  int fullWidth = 0, fullHeight = 0;
  const AnchorBlocks* blocks = nullptr;  // nullptr: no object is looked for
  double coarseTolerance = -1.0;         // below 0: every anchor is traced
  const AnchorBlocks* coarseBlocks = nullptr;

  bool on() const { return tolerance >= 0.0; }
  bool coarse() const { return on() && coarseTolerance >= 0.0; }
  // The anchors of corner (x, y) into `anchors`, and how many: 0 for a
  // corner always traced (an anchor, or a coarse anchor with coarse anchors
  // on), a corner whose anchors leave the image, or with interpolation
  // off; each of those is traced.
  int anchorsOf(int x, int y, int anchors[4][2]) const {
    if (!on()) return 0;
    int stage = stageOf(x, y);
    if (stage == 0) return 0;
    // A corner between anchors looks one corner away, an anchor between
    // coarse anchors two; along each axis where the coordinate is off the
    // anchors' spacing.
    int step = stage == 2 ? 1 : 2;
    bool offX = (x & (2 * step - 1)) != 0, offY = (y & (2 * step - 1)) != 0;
    if (x + (offX ? step : 0) > fullWidth || y + (offY ? step : 0) > fullHeight) return 0;
    int count = 0;
    for (int dy = offY ? -step : 0; dy <= (offY ? step : 0); dy += 2 * step) {
      for (int dx = offX ? -step : 0; dx <= (offX ? step : 0); dx += 2 * step) {
        anchors[count][0] = x + dx;
        anchors[count][1] = y + dy;
        ++count;
      }
    }
    return count;
  }
  // The order in which corners are known: 0 for those traced whatever their
  // neighbours, 1 for anchors between coarse anchors, 2 for the corners
  // between anchors. A corner's anchors come earlier in this order.
  int stageOf(int x, int y) const {
    if (((x | y) & 1) != 0) return 2;
    return coarse() && ((x | y) & 3) != 0 ? 1 : 0;
  }
  // Whether corner (x, y), between anchors that look as `looks`, is their
  // mean.
  bool agree(int x, int y, const SampleLook* looks, int count) const;
};

// The mean of `count` anchors' samples: a corner between them.
SampleColour meanOf(const SampleColour* const* samples, int count);

// The samples at the pixel corners that lie on the edges of a region's
// tiles (squares of `tileSize` pixels from the region's top-left corner,
// cut at its far edges), the corners that neighbouring tiles share: every
// tile's top and bottom corner rows, and its left and right corner columns.
// Pass 1 of adaptive sampling traces these once; each tile then traces its
// own inner corners, so that every corner is traced once, and the image's
// corners are never all held at once (a tile's are, on its thread).
class TileEdgeCorners {
 public:
  // The region's pixels are [x0, x0 + width) x [y0, y0 + height); its
  // corners (x, y) run to x0 + width and y0 + height.
  TileEdgeCorners(int x0, int y0, int width, int height, int tileSize);

  // A run of edge corners traced together: `count` corners from (x, y),
  // along a row or down a column, kept side by side in memory (samples()).
  struct Run {
    int x = 0, y = 0;
    bool down = false;
    int count = 0;
  };
  // The runs cover every edge corner once: each edge row in pieces of at
  // most tileSize + 1 corners, and each edge column's stretch inside each
  // band of tiles (its corners between two edge rows).
  std::size_t runCount() const { return runs_.size(); }
  const Run& run(std::size_t index) const { return runs_[index]; }
  SampleColour* samples(const Run& run) { return &samples_[indexOf(run.x, run.y)]; }

  // The sample of edge corner (x, y): on an edge row, or on an edge column.
  const SampleColour& sample(int x, int y) const { return samples_[indexOf(x, y)]; }
  bool onEdgeRow(int y) const { return (y - y0_) % tileSize_ == 0 || y == y0_ + height_; }

  // The bytes an instance holds for such a region (Run list included).
  static std::uint64_t bytesFor(int width, int height, int tileSize);

 private:
  int x0_, y0_, width_, height_, tileSize_;
  // The edge rows, (width + 1) corners each, then the edge columns,
  // (height + 1) each (their corners on edge rows unused).
  std::vector<SampleColour, HugePageAllocator<SampleColour>> samples_;
  std::vector<Run> runs_;

  int edgeRows() const { return (height_ + tileSize_ - 1) / tileSize_ + 1; }
  int edgeColumns() const { return (width_ + tileSize_ - 1) / tileSize_ + 1; }
  // The index of the edge line through corner coordinate `v` (counted from
  // the region's first corner) among `count` lines a tile apart, the last
  // at the far edge.
  int lineOf(int v, int count) const { return v % tileSize_ == 0 ? v / tileSize_ : count - 1; }
  std::size_t indexOf(int x, int y) const {
    int u = x - x0_, v = y - y0_;
    if (onEdgeRow(y)) {
      return static_cast<std::size_t>(lineOf(v, edgeRows())) * (width_ + 1) + u;
    }
    return static_cast<std::size_t>(edgeRows()) * (width_ + 1) +
           static_cast<std::size_t>(lineOf(u, edgeColumns())) * (height_ + 1) + v;
  }
};

// The bytes adaptive sampling keeps beside the image of a region of
// `width` x `height` pixels rendered on `threads` threads: the samples of
// its tiles' edge corners (TileEdgeCorners, tiles of `tileSize`), and for
// each thread a tile's corners, their samples and looks, and its inner
// corners' work lists. Saturates.
std::uint64_t adaptiveSamplingBytes(int width, int height, int threads, int tileSize);

}  // namespace render
