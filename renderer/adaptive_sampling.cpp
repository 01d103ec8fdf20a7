#include "renderer/adaptive_sampling.h"

#include <algorithm>

#include "renderer/anchor_blocks.h"
#include "renderer/saturating.h"

namespace render {

bool looksDiffer(const SampleLook& a, const SampleLook& b, double threshold) {
  if (a.object != b.object) return true;
  for (int c = 0; c < 3; ++c) {
    if (std::abs(static_cast<double>(a.colour[c]) - b.colour[c]) > threshold) return true;
  }
  return false;
}

int subdivisionDepth(int samplesPerPixel) {
  int depth = 0;
  while (depth < kMaxSubdivisionDepth &&
         (std::int64_t{1} << (2 * (depth + 1))) <= std::int64_t{samplesPerPixel}) {
    ++depth;
  }
  return depth;
}

PixelLattice::PixelLattice(int depth)
    : depth_(std::clamp(depth, 0, kMaxSubdivisionDepth)), side_((1 << (depth_ + 1)) + 1) {
  std::size_t points = static_cast<std::size_t>(side_) * side_;
  looks_.resize(points);
  weightOf_.assign(points, 0.0);
  known_.assign(points, 0);
}

void PixelLattice::start(const SampleLook corners[4]) {
  // Forget the last pixel: only the points it touched.
  for (int p : touched_) {
    weightOf_[p] = 0.0;
    known_[p] = 0;
  }
  touched_.clear();
  const int last = side_ - 1;
  preset(0, corners[0]);
  preset(last, corners[1]);
  preset(last * side_, corners[2]);
  preset(last * side_ + last, corners[3]);
}

void PixelLattice::preset(int point, const SampleLook& look) {
  looks_[point] = look;
  if (!known_[point]) {
    known_[point] = 1;
    touched_.push_back(point);
  }
}

int PixelLattice::subdivide(double threshold, const TraceLevel& traceLevel) {
  const int last = side_ - 1;
  // Squares of one level by their top-left points; `size` lattice steps a
  // side, and each corner's share of a whole square's weight.
  std::vector<int>& squares = squares_;
  std::vector<int>& next = next_;
  std::vector<int>& queued = queued_;
  std::vector<SampleLook>& traced = traced_;
  squares.assign(1, 0);
  int size = last;
  double share = 0.25;
  int cuts = 0;
  // A square left whole moves the pixel by at most its share of the area
  // times how far its corners are from what it covers, so a smaller square
  // must differ by more to be worth its five samples: the threshold
  // doubles with each level. The object test is the pixel's alone: below
  // it, two objects of one colour need no finer squares. With one
  // threshold and the object test at every level, the same error took 8
  // to 13% more CPU time (docs/RENDERING.md, "Adaptive sampling").
  double levelThreshold = threshold;
  for (int level = 0; !squares.empty(); ++level, levelThreshold *= 2.0) {
    next.clear();
    queued.clear();
    int half = size / 2;
    for (int p : squares) {
      const int corner[4] = {p, p + size, p + size * side_, p + size * side_ + size};
      SampleSpread spread;
      for (int c : corner) spread.add(looks_[c]);
      bool differ =
          level == 0 ? spread.exceeds(levelThreshold) : spread.coloursDiffer(levelThreshold);
      if (level == depth_ || !differ) {
        const int centre = p + half * side_ + half;
        if (spread.coloursDiffer(0.5 * levelThreshold)) {
          // Corners that differ by more than half the level's threshold:
          // one sample where a cut takes five, the centre, half the square
          // (and an eighth each corner), as a pixel's own (docs/RENDERING.md,
          // "Adaptive sampling"). On the default scene, floor-1000 and
          // glass-mirror 3 to 12% fewer rays for the same error.
          for (int c : corner) weightOf_[c] += 0.5 * share;
          weightOf_[centre] += 2.0 * share;
          if (!known_[centre]) {
            known_[centre] = 1;
            touched_.push_back(centre);
            queued.push_back(centre);
          }
          continue;
        }
        for (int c : corner) weightOf_[c] += share;
        continue;
      }
      // Cut in four: the midpoints of the sides and the centre.
      for (int m : {p + half, p + half * side_, p + half * side_ + half, p + half * side_ + size,
                    p + size * side_ + half}) {
        if (!known_[m]) {
          known_[m] = 1;
          touched_.push_back(m);
          queued.push_back(m);
        }
      }
      for (int child : {p, p + half, p + half * side_, p + half * side_ + half}) {
        next.push_back(child);
      }
    }
    if (!queued.empty()) {
      traced.resize(queued.size());
      traceLevel(queued, traced);
      for (std::size_t k = 0; k < queued.size(); ++k) looks_[queued[k]] = traced[k];
    }
    if (!next.empty()) cuts = level + 1;
    squares.swap(next);
    size = half;
    share /= 4.0;
  }

  // The weighted points in lattice order, the order the pixel's sums take:
  // a small lattice read in order costs less than sorting the points it
  // touched (only those have weights).
  points_.clear();
  weights_.clear();
  auto take = [&](int p) {
    if (weightOf_[p] > 0.0) {
      points_.push_back(p);
      weights_.push_back(weightOf_[p]);
    }
  };
  if (side_ * side_ <= kScannedLattice) {
    for (int p = 0; p < side_ * side_; ++p) take(p);
  } else {
    std::sort(touched_.begin(), touched_.end());
    for (int p : touched_) take(p);
  }
  return cuts;
}

SharedSides::SharedSides(int side, int columns)
    : side_(side),
      right_(static_cast<std::size_t>(side)),
      rightKnown_(static_cast<std::size_t>(side)),
      bottom_(static_cast<std::size_t>(side) * columns),
      bottomKnown_(static_cast<std::size_t>(side) * columns),
      bottomValid_(static_cast<std::size_t>(columns)) {}

void SharedSides::startTile() {
  std::fill(bottomValid_.begin(), bottomValid_.end(), 0);
  rightValid_ = false;
}

void SharedSides::lend(int column, PixelLattice& lattice, SampleColour* samples) const {
  const int last = side_ - 1;
  if (rightValid_) {
    for (int b = 1; b < last; ++b) {
      if (!rightKnown_[b]) continue;
      samples[b * side_] = right_[b];
      lattice.preset(b * side_, lookOf(right_[b].colour, right_[b].object));
    }
  }
  if (bottomValid_[column]) {
    for (int a = 1; a < last; ++a) {
      std::size_t at = static_cast<std::size_t>(column) * side_ + a;
      if (!bottomKnown_[at]) continue;
      samples[a] = bottom_[at];
      lattice.preset(a, lookOf(bottom_[at].colour, bottom_[at].object));
    }
  }
}

void SharedSides::keep(int column, const PixelLattice& lattice, const SampleColour* samples) {
  const int last = side_ - 1;
  for (int b = 1; b < last; ++b) {
    int p = b * side_ + last;
    rightKnown_[b] = lattice.known(p) ? 1 : 0;
    if (rightKnown_[b]) right_[b] = samples[p];
  }
  for (int a = 1; a < last; ++a) {
    int p = last * side_ + a;
    std::size_t at = static_cast<std::size_t>(column) * side_ + a;
    bottomKnown_[at] = lattice.known(p) ? 1 : 0;
    if (bottomKnown_[at]) bottom_[at] = samples[p];
  }
  rightValid_ = true;
  bottomValid_[column] = 1;
}

bool CornerInterpolation::agree(int x, int y, const SampleLook* looks, int count) const {
  SampleSpread spread;
  for (int k = 0; k < count; ++k) spread.add(looks[k]);
  if (stageOf(x, y) == 1) {
    return !spread.exceeds(coarseTolerance) &&
           (!coarseBlocks || coarseBlocks->onlyShows(x, y, looks[0].object));
  }
  return !spread.exceeds(tolerance) && (!blocks || blocks->onlyShows(x, y, looks[0].object));
}

SampleColour meanOf(const SampleColour* const* samples, int count) {
  SampleColour mean;
  for (int k = 0; k < count; ++k) {
    mean.colour += samples[k]->colour;
    mean.slack += samples[k]->slack;
  }
  mean.colour /= static_cast<double>(count);
  mean.slack /= static_cast<double>(count);
  mean.object = samples[0]->object;
  return mean;
}

TileEdgeCorners::TileEdgeCorners(int x0, int y0, int width, int height, int tileSize)
    : x0_(x0),
      y0_(y0),
      width_(std::max(0, width)),
      height_(std::max(0, height)),
      tileSize_(std::max(1, tileSize)) {
  if (width_ == 0 || height_ == 0) return;
  samples_.resize(static_cast<std::size_t>(edgeRows()) * (width_ + 1) +
                  static_cast<std::size_t>(edgeColumns()) * (height_ + 1));
  // Each edge row in pieces of a tile's width, the last taking the far
  // corner too.
  for (int r = 0; r < edgeRows(); ++r) {
    int y = y0_ + std::min(r * tileSize_, height_);
    for (int u = 0; u <= width_; u += tileSize_) {
      int count = std::min(tileSize_, width_ + 1 - u);
      if (width_ + 1 - (u + count) == 1) ++count;
      runs_.push_back(Run{x0_ + u, y, false, count});
      if (u + count > width_) break;
    }
  }
  // Each edge column between each two edge rows.
  for (int c = 0; c < edgeColumns(); ++c) {
    int x = x0_ + std::min(c * tileSize_, width_);
    for (int v = 0; v < height_; v += tileSize_) {
      int count = std::min(tileSize_, height_ - v) - 1;
      if (count > 0) runs_.push_back(Run{x, y0_ + v + 1, true, count});
    }
  }
}

std::uint64_t TileEdgeCorners::bytesFor(int width, int height, int tileSize) {
  auto lines = [&](int side) {
    return side > 0 ? static_cast<std::uint64_t>((side + tileSize - 1) / tileSize) + 1 : 0;
  };
  auto corners = [](int side) { return static_cast<std::uint64_t>(side > 0 ? side + 1 : 0); };
  std::uint64_t samples = saturatingSum(saturatingProduct(lines(height), corners(width)),
                                        saturatingProduct(lines(width), corners(height)));
  // At most one run a tile's side of each line.
  std::uint64_t runs = saturatingSum(saturatingProduct(lines(height), lines(width)),
                                     saturatingProduct(lines(width), lines(height)));
  return saturatingSum(saturatingProduct(samples, sizeof(SampleColour)),
                       saturatingProduct(runs, sizeof(Run)));
}

std::uint64_t adaptiveSamplingBytes(int width, int height, int threads, int tileSize) {
  tileSize = std::max(1, tileSize);
  std::uint64_t tileCorners = static_cast<std::uint64_t>(tileSize + 1) * (tileSize + 1);
  // Each corner's sample and look, and the inner corners' positions and
  // samples while they are traced or interpolated.
  std::uint64_t perThread =
      tileCorners * (2 * sizeof(SampleColour) + sizeof(SampleLook) + 2 * sizeof(int));
  // And the anchors' blocks and the coarse anchors', which decide where
  // corners are interpolated.
  std::uint64_t blocks = saturatingSum(AnchorBlocks::bytesFor(width, height),
                                       AnchorBlocks::bytesFor(width, height, 4));
  return saturatingSum(
      saturatingSum(TileEdgeCorners::bytesFor(width, height, tileSize), blocks),
      saturatingProduct(static_cast<std::uint64_t>(std::max(1, threads)), perThread));
}

}  // namespace render
