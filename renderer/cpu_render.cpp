#include "renderer/cpu_render.h"

#include <algorithm>
#include <chrono>
#include <glm/vec2.hpp>
#include <limits>
#include <optional>

#include "renderer/adaptive_sampling.h"
#include "renderer/anchor_blocks.h"
#include "renderer/camera.h"
#include "renderer/camera_trace.h"
#include "renderer/parallel_parts.h"
#include "renderer/render_tiles.h"

namespace render {

namespace {

constexpr int kTileSize = kRenderTileSize;
// The share of adaptive sampling's threshold within which a corner's
// anchors must agree for it to be their mean (CornerInterpolation).
constexpr double kAnchorsAgreement = 0.1;
// The same for an anchor between coarse anchors, and their spacing: half
// the corners' share, as an anchor's mean spans twice the distance (at a
// tenth, the same error took as much time: docs/RENDERING.md).
constexpr double kCoarseAnchorsAgreement = 0.05;
constexpr int kCoarseSpan = 4;

// Keeps an image finite whatever the scene: NaN becomes 0, and values past
// the float range are clamped to it.
float toStoredChannel(double v) {
  if (!(v == v)) return 0.0f;
  constexpr double kMax = std::numeric_limits<float>::max();
  return static_cast<float>(std::clamp(v, -kMax, kMax));
}

// Whether every colour from v to v + slack, in each channel, is stored as
// the same level. The margin covers the rounding by which the full colour,
// summed in another order of terms, can stray past that range.
bool oneLevel(const glm::dvec3& v, double slack, double levels) {
  constexpr double kRounding = 1e-9;
  for (int c = 0; c < 3; ++c) {
    if (levelOf(toStoredChannel(v[c] - kRounding), levels) !=
        levelOf(toStoredChannel(v[c] + slack + kRounding), levels)) {
      return false;
    }
  }
  return true;
}

// The mean of some of a pixel's samples, with the bound on what adaptive
// depth control left out of it and how many of its camera rays met an
// object.
struct PixelSamples {
  glm::dvec3 colour{0.0};
  double slack = 0.0;
  double hits = 0.0;
  int count = 0;

  // Adds a sample to the sums; samples are added in their order, so that
  // every way of tracing them gives the same sums, bit for bit.
  void add(const SampleColour& sample) {
    colour += sample.colour;
    slack += sample.slack;
    hits += sample.hit() ? 1 : 0;
    ++count;
  }
  // Adds a sample of a weighted mean (adaptive subdivision): the weights
  // sum to 1, so the sums are the mean, and count stays 1.
  void add(const SampleColour& sample, double weight) {
    colour += weight * sample.colour;
    slack += weight * sample.slack;
    hits += sample.hit() ? weight : 0.0;
    count = 1;
  }
  // The sums made means. Dividing by 1 is exact: skipped, for one division
  // less a pixel.
  void average() {
    if (count > 1) {
      colour /= static_cast<double>(count);
      slack /= static_cast<double>(count);
    }
  }
};

// What one thread keeps for itself: its trace context and its counts.
struct alignas(64) Worker {
  TraceContext context;
  std::uint64_t retraced = 0;
  std::uint64_t samples = 0;
  std::uint64_t refined = 0;
  std::uint64_t fullySampled = 0;
  std::uint64_t centred = 0;
};

// Traces the samples of pixels: one for a render, shared by its threads.
class PixelTracer {
 public:
  PixelTracer(const RenderScene& scene, const RenderSettings& settings)
      : scene_(scene),
        settings_(settings),
        camera_(scene, settings),
        tracer_(scene, settings.maxDepth),
        // Not a number, or below 0, allows no error.
        tolerance_(std::max(0.0, settings.pruneTolerance)),
        allowance_(settings.maxRaysPerSample > 0 ? settings.maxRaysPerSample
                                                 : std::numeric_limits<std::uint64_t>::max()),
        // Retracing needs a finite bound, has nothing to mend at tolerance
        // 0, and traces in full: without an allowance that could never end.
        certifies_(tolerance_ > 0.0 && settings.maxRaysPerSample > 0 &&
                   tracer_.bound().at(0) < RadianceBound::kUnbounded) {
    // The media the camera starts in, for a camera inside glass.
    if (scene.hasTransparency()) {
      for (std::uint32_t object : scene.mediaContaining(camera_.camera().eye())) {
        eyeMedia_.push(object);
      }
    }
  }

  // The stack each sample starts with: copied afresh per sample only where
  // it can matter (a scene without transparency never reads or changes it),
  // as the copy costs as much as a tenth of a primary ray.
  const MediumStack& eyeMedia() const { return eyeMedia_; }
  const RenderScene& scene() const { return scene_; }
  const PinholeCamera& camera() const { return camera_.camera(); }
  // The error adaptive depth control may make in a sample.
  double tolerance() const { return tolerance_; }

  // Traces the camera rays through the `count` image positions `at`, each a
  // sample of its own (its allowance, slack and media afresh), to within
  // `allowed`, into out[0, count). With RenderSettings::packets the closest
  // hits of each Bvh::kPacketSize consecutive rays are found together
  // (RenderScene::closestHits), then their shadow rays toward each light
  // (Tracer::primaryShadows), and each sample is shaded from its hit: the
  // same colours as tracing each alone, bit for bit (docs/TRACING.md,
  // "Packets").
  void traceSamples(const glm::dvec2* at, int count, double allowed, MediumStack& media,
                    TraceContext& context, SampleColour* out) const {
    constexpr int kPacket = Bvh::kPacketSize;
    for (int first = 0; first < count; first += kPacket) {
      int n = std::min(kPacket, count - first);
      Ray rays[kPacket];
      for (int k = 0; k < n; ++k) camera_.makeRay(at[first + k], rays[k]);
      std::optional<Hit> hits[kPacket];
      ShadowAnswers shadows[kPacket];
      if (settings_.packets) {
        camera_.closestHits(rays, n, hits);
        tracer_.primaryShadows(rays, hits, n, context, shadows);
      }
      for (int k = 0; k < n; ++k) {
        if (scene_.hasTransparency()) media = eyeMedia_;
        ++context.counts.primary;
        context.allowance = allowance_;
        context.slack = 0.0;
        context.shadows = shadows[k];
        glm::dvec3 colour = settings_.packets
                                ? tracer_.traceFromHit(rays[k], hits[k], media, context, allowed)
                                : tracer_.trace(rays[k], RaySource{}, 0, media, context, allowed);
        out[first + k] = SampleColour{colour, context.slack, context.primaryObject};
      }
    }
  }

  // The mean of pixel (i, j)'s `count` samples (samplePosition), traced to
  // within `allowed`; onSample(sample) hears of each.
  template <typename OnSample>
  PixelSamples trace(int i, int j, int count, double allowed, MediumStack& media,
                     TraceContext& context, OnSample&& onSample) const {
    constexpr int kBatch = 16;
    glm::dvec2 at[kBatch];
    SampleColour samples[kBatch];
    PixelSamples pixel;
    for (int first = 0; first < count; first += kBatch) {
      int n = std::min(kBatch, count - first);
      for (int s = 0; s < n; ++s) at[s] = samplePosition(i, j, first + s, count, settings_.seed);
      traceSamples(at, n, allowed, media, context, samples);
      for (int s = 0; s < n; ++s) {
        onSample(samples[s]);
        pixel.add(samples[s]);
      }
    }
    pixel.average();
    return pixel;
  }

  PixelSamples trace(int i, int j, int count, MediumStack& media, TraceContext& context) const {
    return trace(i, j, count, tolerance_, media, context, [](const SampleColour&) {});
  }

  // `pixel`, traced at the tolerance, made exact to the image's levels: the
  // full colour lies in [colour, colour + slack]; where that range holds two
  // levels, the pixel is traced again (retrace(finer): its samples to within
  // `finer`) with a 64th of the tolerance, then in full, until the range
  // holds one level (a trace that runs out of its allowance proves nothing,
  // and if every one does, the first stays).
  template <typename Retrace>
  PixelSamples certified(PixelSamples pixel, Worker& worker, Retrace&& retrace) const {
    if (!(pixel.slack > 0.0 && certifies_ &&
          !oneLevel(pixel.colour, pixel.slack, settings_.levels))) {
      return pixel;
    }
    ++worker.retraced;
    for (double finer : {tolerance_ / 64.0, 0.0}) {
      std::uint64_t cutBefore = worker.context.counts.cut;
      PixelSamples again = retrace(finer);
      pixel.hits = again.hits;
      if (worker.context.counts.cut == cutBefore &&
          (finer == 0.0 || oneLevel(again.colour, again.slack, settings_.levels))) {
        return again;
      }
    }
    return pixel;
  }

  // certified for the pixel (i, j) of `pixel.count` stratified samples.
  PixelSamples certified(int i, int j, const PixelSamples& pixel, MediumStack& media,
                         Worker& worker) const {
    return certified(pixel, worker, [&](double finer) {
      return trace(i, j, pixel.count, finer, media, worker.context, [](const SampleColour&) {});
    });
  }

 private:
  const RenderScene& scene_;
  const RenderSettings& settings_;
  CameraTrace camera_;
  Tracer tracer_;
  double tolerance_;
  std::uint64_t allowance_;
  bool certifies_;
  MediumStack eyeMedia_;
};

// Where pixels go in the image of a region.
class ImageWriter {
 public:
  explicit ImageWriter(Image& image) : image_(image) {}
  void store(int i, int j, const PixelSamples& pixel) const {
    std::size_t at = static_cast<std::size_t>(j - image_.originY) * image_.width +
                     static_cast<std::size_t>(i - image_.originX);
    float* p = &image_.rgb[Image::kChannels * at];
    for (int c = 0; c < 3; ++c) p[c] = toStoredChannel(pixel.colour[c]);
    if (!image_.coverage.empty()) {
      image_.coverage[at] = static_cast<float>(static_cast<double>(pixel.hits) / pixel.count);
    }
  }

 private:
  Image& image_;
};

// Every pixel of `region` with samplesPerPixel samples.
void renderUniform(const PixelTracer& tracer, const PixelRegion& region,
                   const RenderSettings& settings, std::vector<Worker>& workers,
                   const ImageWriter& writer, const ProgressCallback& progress,
                   const CancelFlag* cancel) {
  int spp = std::max(1, settings.samplesPerPixel);
  forEachTile(
      region, static_cast<int>(workers.size()),
      [&](int index, const PixelRegion& tile) {
        Worker& worker = workers[index];
        MediumStack media = tracer.eyeMedia();
        int n = tile.width();
        glm::dvec2 at[kTileSize];
        SampleColour samples[kTileSize];
        PixelSamples row[kTileSize];
        for (int j = tile.y0; j < tile.y1; ++j) {
          // forEachTile stops handing out tiles at the first exception.
          if (cancel && cancel->requested()) throw RenderCancelled();
          // Sample s of the row's pixels side by side: neighbouring camera
          // rays, coherent enough to be traced as packets. Each pixel still
          // adds its samples in their order, so its sum is what tracing it
          // alone gives.
          for (int k = 0; k < n; ++k) row[k] = PixelSamples{};
          for (int s = 0; s < spp; ++s) {
            for (int k = 0; k < n; ++k)
              at[k] = samplePosition(tile.x0 + k, j, s, spp, settings.seed);
            tracer.traceSamples(at, n, tracer.tolerance(), media, worker.context, samples);
            for (int k = 0; k < n; ++k) row[k].add(samples[k]);
          }
          for (int k = 0; k < n; ++k) {
            PixelSamples& pixel = row[k];
            pixel.average();
            writer.store(tile.x0 + k, j, tracer.certified(tile.x0 + k, j, pixel, media, worker));
          }
          worker.samples += static_cast<std::uint64_t>(spp) * static_cast<std::uint64_t>(n);
        }
      },
      progress);
}

// The samples at the corners of the pixels of a tile, and their looks:
// corner (x, y) is the image point (x, y), the top-left corner of pixel
// (x, y). One for each thread, filled tile by tile (fillTileCorners).
struct CornerSamples {
  PixelRegion corners;
  std::vector<SampleColour> samples;
  std::vector<SampleLook> looks;
  // fillTileCorners' work lists, kept to spare their allocations: the
  // corners of a stage to trace and where their samples go, and the
  // anchors outside the tile with their samples.
  std::vector<glm::ivec2> now;
  std::vector<SampleColour*> into;
  std::vector<glm::ivec2> outside;
  std::vector<SampleColour> outsideSamples;

  bool inside(int x, int y) const {
    return x >= corners.x0 && x < corners.x1 && y >= corners.y0 && y < corners.y1;
  }
  std::size_t at(int x, int y) const {
    return static_cast<std::size_t>(y - corners.y0) * corners.width() + (x - corners.x0);
  }
  const SampleColour& outsideSample(int x, int y) const {
    auto it = std::find(outside.begin(), outside.end(), glm::ivec2(x, y));
    return outsideSamples[static_cast<std::size_t>(it - outside.begin())];
  }
};

// Traces the pixel corners `corners` into the samples `into` points at, as
// packets.
void traceCorners(const PixelTracer& tracer, const std::vector<glm::ivec2>& corners,
                  const std::vector<SampleColour*>& into, MediumStack& media, Worker& worker) {
  if (corners.empty()) return;
  std::vector<glm::dvec2> at(corners.begin(), corners.end());
  std::vector<SampleColour> traced(corners.size());
  tracer.traceSamples(at.data(), static_cast<int>(at.size()), tracer.tolerance(), media,
                      worker.context, traced.data());
  for (std::size_t k = 0; k < corners.size(); ++k) *into[k] = traced[k];
  worker.samples += corners.size();
}

// The samples of the pixel corners `corners` into out[0, corners.size()),
// as `rule` says (CornerInterpolation), stage by stage (stageOf): each
// corner traced, or from its anchors, which an earlier stage gave.
// find(x, y) gives the sample of an anchor that the caller holds, or that
// this batch gives in an earlier stage; nullptr for any other, which is
// found here as the batch's corners are, with its own anchors.
template <typename Find>
void sampleCorners(const PixelTracer& tracer, const CornerInterpolation& rule,
                   const std::vector<glm::ivec2>& corners, SampleColour* out, Find&& find,
                   MediumStack& media, Worker& worker) {
  int anchors[4][2];
  // The anchors the caller lacks (beyond a run's ends, or its region's),
  // and theirs in turn.
  std::vector<glm::ivec2> extra;
  auto addAnchorsOf = [&](glm::ivec2 corner) {  // a copy: it may be one of `extra`, which grows
    int count = rule.anchorsOf(corner.x, corner.y, anchors);
    for (int a = 0; a < count; ++a) {
      glm::ivec2 at(anchors[a][0], anchors[a][1]);
      if (!find(at.x, at.y) && std::find(extra.begin(), extra.end(), at) == extra.end()) {
        extra.push_back(at);
      }
    }
  };
  for (const glm::ivec2& corner : corners) addAnchorsOf(corner);
  for (std::size_t k = 0; k < extra.size(); ++k) addAnchorsOf(extra[k]);
  std::vector<SampleColour> extraSamples(extra.size());
  auto lookup = [&](const glm::ivec2& at) -> const SampleColour* {
    const SampleColour* known = find(at.x, at.y);
    if (known) return known;
    auto it = std::find(extra.begin(), extra.end(), at);
    return &extraSamples[static_cast<std::size_t>(it - extra.begin())];
  };
  // The batch's corners, then the extra anchors: position and sample.
  auto cornerAt = [&](std::size_t k) {
    return k < corners.size() ? corners[k] : extra[k - corners.size()];
  };
  auto sampleAt = [&](std::size_t k) {
    return k < corners.size() ? &out[k] : &extraSamples[k - corners.size()];
  };
  std::vector<glm::ivec2> now;
  std::vector<SampleColour*> into;
  for (int stage = 0; stage <= 2; ++stage) {
    now.clear();
    into.clear();
    for (std::size_t k = 0; k < corners.size() + extra.size(); ++k) {
      glm::ivec2 corner = cornerAt(k);
      if (rule.stageOf(corner.x, corner.y) != stage) continue;
      int count = rule.anchorsOf(corner.x, corner.y, anchors);
      const SampleColour* samples[4];
      SampleLook looks[4];
      for (int a = 0; a < count; ++a) {
        samples[a] = lookup(glm::ivec2(anchors[a][0], anchors[a][1]));
        looks[a] = lookOf(samples[a]->colour, samples[a]->object);
      }
      if (count > 0 && rule.agree(corner.x, corner.y, looks, count)) {
        *sampleAt(k) = meanOf(samples, count);
      } else {
        now.push_back(corner);
        into.push_back(sampleAt(k));
      }
    }
    traceCorners(tracer, now, into, media, worker);
  }
}

// Adaptive sampling's pass 1: the corners on the edges of the region's
// tiles, which neighbouring tiles share (TileEdgeCorners), a run at a time.
void traceTileEdges(const PixelTracer& tracer, const CornerInterpolation& rule,
                    TileEdgeCorners& edges, std::vector<Worker>& workers,
                    const ProgressCallback& progress, const CancelFlag* cancel) {
  forEachPart(
      static_cast<int>(edges.runCount()), static_cast<int>(workers.size()),
      [&](int index, int part) {
        if (cancel && cancel->requested()) throw RenderCancelled();
        Worker& worker = workers[index];
        MediumStack media = tracer.eyeMedia();
        const TileEdgeCorners::Run& run = edges.run(static_cast<std::size_t>(part));
        std::vector<glm::ivec2> corners(static_cast<std::size_t>(run.count));
        for (int k = 0; k < run.count; ++k) {
          corners[k] = run.down ? glm::ivec2(run.x, run.y + k) : glm::ivec2(run.x + k, run.y);
        }
        SampleColour* out = edges.samples(run);
        // The run's own anchors, traced first.
        auto find = [&](int x, int y) -> const SampleColour* {
          int k = run.down ? y - run.y : x - run.x;
          bool on = run.down ? x == run.x : y == run.y;
          return on && k >= 0 && k < run.count ? &out[k] : nullptr;
        };
        sampleCorners(tracer, rule, corners, out, find, media, worker);
      },
      progress);
}

// The anchors of `tile`'s inner corners that lie outside it (a tile off
// the coarse anchors' spacing, whose corners look two corners away) into
// corners.outside, found as pass 1 finds its corners: the tile's edges
// known, any other traced or from its own anchors.
void sampleOutsideAnchors(const PixelTracer& tracer, const CornerInterpolation& rule,
                          const PixelRegion& tile, CornerSamples& corners, MediumStack& media,
                          Worker& worker) {
  std::vector<glm::ivec2>& outside = corners.outside;
  outside.clear();
  if (!rule.coarse() || ((tile.x0 | tile.y0 | tile.x1 | tile.y1) & 3) == 0) return;
  int anchors[4][2];
  for (int y = tile.y0 + 1; y < tile.y1; ++y) {
    for (int x = tile.x0 + 1; x < tile.x1; ++x) {
      int count = rule.anchorsOf(x, y, anchors);
      for (int a = 0; a < count; ++a) {
        glm::ivec2 at(anchors[a][0], anchors[a][1]);
        if (!corners.inside(at.x, at.y) &&
            std::find(outside.begin(), outside.end(), at) == outside.end()) {
          outside.push_back(at);
        }
      }
    }
  }
  corners.outsideSamples.resize(outside.size());
  auto find = [&](int x, int y) -> const SampleColour* {
    bool edge = x == tile.x0 || x == tile.x1 || y == tile.y0 || y == tile.y1;
    return corners.inside(x, y) && edge ? &corners.samples[corners.at(x, y)] : nullptr;
  };
  sampleCorners(tracer, rule, outside, corners.outsideSamples.data(), find, media, worker);
}

// The corners of `tile`'s pixels into `corners`, with their looks: those on
// its edges from pass 1, the inner ones stage by stage
// (CornerInterpolation::stageOf), each the mean of its anchors or traced,
// as packets, a stage at a time. The tile's corners are a grid: an anchor
// inside it is read in place.
void fillTileCorners(const PixelTracer& tracer, const CornerInterpolation& rule,
                     const PixelRegion& tile, const TileEdgeCorners& edges, CornerSamples& corners,
                     MediumStack& media, Worker& worker) {
  corners.corners = PixelRegion{tile.x0, tile.y0, tile.x1 + 1, tile.y1 + 1};
  std::size_t count = static_cast<std::size_t>(corners.corners.width()) * corners.corners.height();
  corners.samples.resize(count);
  corners.looks.resize(count);
  auto setLook = [&](std::size_t c) {
    corners.looks[c] = lookOf(corners.samples[c].colour, corners.samples[c].object);
  };
  for (int y = tile.y0; y <= tile.y1; ++y) {
    std::size_t row = corners.at(tile.x0, y);
    for (int x = tile.x0; x <= tile.x1; ++x) {
      if (!edges.onEdgeRow(y) && x != tile.x0 && x != tile.x1) continue;
      corners.samples[row + (x - tile.x0)] = edges.sample(x, y);
      setLook(row + (x - tile.x0));
    }
  }
  sampleOutsideAnchors(tracer, rule, tile, corners, media, worker);
  std::vector<glm::ivec2>& now = corners.now;
  std::vector<SampleColour*>& into = corners.into;
  int anchors[4][2];
  for (int stage = 0; stage <= 2; ++stage) {
    now.clear();
    into.clear();
    for (int y = tile.y0; y <= tile.y1; ++y) {
      if (edges.onEdgeRow(y)) continue;
      for (int x = tile.x0 + 1; x < tile.x1; ++x) {
        if (rule.stageOf(x, y) != stage) continue;
        std::size_t c = corners.at(x, y);
        int n = rule.anchorsOf(x, y, anchors);
        const SampleColour* samples[4];
        SampleLook looks[4];
        for (int a = 0; a < n; ++a) {
          int ax = anchors[a][0], ay = anchors[a][1];
          if (corners.inside(ax, ay)) {
            samples[a] = &corners.samples[corners.at(ax, ay)];
            looks[a] = corners.looks[corners.at(ax, ay)];
          } else {
            samples[a] = &corners.outsideSample(ax, ay);
            looks[a] = lookOf(samples[a]->colour, samples[a]->object);
          }
        }
        if (n > 0 && rule.agree(x, y, looks, n)) {
          corners.samples[c] = meanOf(samples, n);
          setLook(c);
        } else {
          now.emplace_back(x, y);
          into.push_back(&corners.samples[c]);
        }
      }
    }
    traceCorners(tracer, now, into, media, worker);
    for (const glm::ivec2& corner : now) setLook(corners.at(corner.x, corner.y));
  }
}

// Adaptive sampling's pass 2 on one thread: each pixel from its corners; from
// its corners and its centre where they differ by more than half the
// threshold; and where they differ by more than the threshold, from its
// lattice (PixelLattice), its neighbours' shared points lent (SharedSides).
class PixelSubdivider {
 public:
  PixelSubdivider(const PixelTracer& tracer, const CornerInterpolation& rule,
                  const TileEdgeCorners& edges, double threshold, int depth)
      : tracer_(tracer),
        rule_(rule),
        edges_(edges),
        threshold_(threshold),
        lattice_(depth),
        shared_(lattice_.side(), kTileSize),
        samples_(static_cast<std::size_t>(lattice_.side()) * lattice_.side()) {
    const int side = lattice_.side(), last = side - 1;
    cornerPoints_ = {0, last, last * side, last * side + last};
    // The centre is a lattice point from one cut on (side 3 and up).
    centrePoint_ = {(side / 2) * side + side / 2};
    centredPoints_ = {0, last, centrePoint_[0], last * side, last * side + last};
  }

  // A new tile: its corners traced or taken from the edges.
  void startTile(const PixelRegion& tile, MediumStack& media, Worker& worker) {
    fillTileCorners(tracer_, rule_, tile, edges_, corners_, media, worker);
    shared_.startTile();
  }
  void startRow() { shared_.startRow(); }

  // Pixel (i, j), in `column` of its tile's row, traced at the tolerance.
  PixelSamples pixel(int i, int j, int column, MediumStack& media, Worker& worker) {
    const std::size_t own[4] = {corners_.at(i, j), corners_.at(i + 1, j), corners_.at(i, j + 1),
                                corners_.at(i + 1, j + 1)};
    SampleSpread spread;
    for (std::size_t c : own) spread.add(corners_.looks[c]);
    if (lattice_.depth() == 0 || !spread.exceeds(threshold_)) {
      shared_.forget(column);
      if (lattice_.depth() > 0 && spread.coloursDiffer(0.5 * threshold_)) {
        // Corners that differ by more than half the threshold: their mean
        // and the centre, half and half (docs/RENDERING.md, "Adaptive
        // sampling"): one sample where a cut takes five.
        for (int k = 0; k < 4; ++k) samples_[cornerPoints_[k]] = corners_.samples[own[k]];
        trace(i, j, centrePoint_, tracer_.tolerance(), media, worker);
        ++worker.samples;
        ++worker.centred;
        points_ = &centredPoints_;
        weights_ = &kCentredWeights;
        return weightedMean();
      }
      // Corners that agree: their mean, the sums the lattice would make (in
      // lattice order), without it.
      points_ = &cornerPoints_;
      weights_ = &kCornerWeights;
      PixelSamples pixel;
      for (std::size_t c : own) pixel.add(corners_.samples[c], 0.25);
      return pixel;
    }
    SampleLook looks[4];
    for (int k = 0; k < 4; ++k) {
      looks[k] = corners_.looks[own[k]];
      samples_[cornerPoints_[k]] = corners_.samples[own[k]];
    }
    lattice_.start(looks);
    shared_.lend(column, lattice_, samples_.data());
    int cuts = lattice_.subdivide(
        threshold_, [&](const std::vector<int>& points, std::vector<SampleLook>& traced) {
          trace(i, j, points, tracer_.tolerance(), media, worker);
          for (std::size_t k = 0; k < points.size(); ++k) {
            traced[k] = lookOf(samples_[points[k]].colour, samples_[points[k]].object);
          }
          worker.samples += points.size();
        });
    shared_.keep(column, lattice_, samples_.data());
    ++worker.refined;
    if (cuts == lattice_.depth()) ++worker.fullySampled;
    points_ = &lattice_.points();
    weights_ = &lattice_.weights();
    return weightedMean();
  }

  // The last pixel's samples traced again to within `allowed`
  // (PixelTracer::certified).
  PixelSamples retrace(int i, int j, double allowed, MediumStack& media, Worker& worker) {
    trace(i, j, *points_, allowed, media, worker);
    return weightedMean();
  }

 private:
  inline static const std::vector<double> kCornerWeights = std::vector<double>(4, 0.25);
  // centredPoints_' weights: an eighth each corner, a half the centre.
  inline static const std::vector<double> kCentredWeights = {0.125, 0.125, 0.5, 0.125, 0.125};
  const PixelTracer& tracer_;
  CornerInterpolation rule_;
  const TileEdgeCorners& edges_;
  CornerSamples corners_;  // the tile's
  double threshold_;
  PixelLattice lattice_;
  SharedSides shared_;
  std::vector<SampleColour> samples_;  // by lattice point
  std::vector<int> cornerPoints_;
  std::vector<int> centrePoint_;    // the centre alone, to trace
  std::vector<int> centredPoints_;  // the corners and the centre, in lattice order
  const std::vector<int>* points_ = nullptr;
  const std::vector<double>* weights_ = nullptr;
  std::vector<glm::dvec2> at_;
  std::vector<SampleColour> traced_;

  // The mean of the last pixel's points (points_) with their weights, in
  // lattice order.
  PixelSamples weightedMean() const {
    PixelSamples pixel;
    for (std::size_t k = 0; k < points_->size(); ++k) {
      pixel.add(samples_[(*points_)[k]], (*weights_)[k]);
    }
    return pixel;
  }

  // The lattice points of pixel (i, j), traced to within `allowed` into
  // samples_.
  void trace(int i, int j, const std::vector<int>& points, double allowed, MediumStack& media,
             Worker& worker) {
    const int side = lattice_.side();
    const double step = 1.0 / (side - 1);  // exact: a power of two
    at_.resize(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
      at_[k] = glm::dvec2(i + (points[k] % side) * step, j + (points[k] / side) * step);
    }
    // Traced straight into a buffer kept from call to call: an array here
    // would initialise its 32 samples on every call, a level of a pixel.
    traced_.resize(points.size());
    for (std::size_t first = 0; first < points.size(); first += kTileSize) {
      int n = static_cast<int>(std::min<std::size_t>(kTileSize, points.size() - first));
      tracer_.traceSamples(&at_[first], n, allowed, media, worker.context, &traced_[first]);
    }
    for (std::size_t k = 0; k < points.size(); ++k) samples_[points[k]] = traced_[k];
  }
};

// Adaptive anti-aliasing (docs/RENDERING.md, "Adaptive sampling"). Pass 1
// traces the pixel corners on the edges of the region's tiles. Pass 2,
// tile by tile, traces the tile's other corners, gives a pixel whose four
// corners agree their mean, and subdivides the others. Every
// sample lies at a fixed position and every decision reads only the samples
// of its own pixel's square, so a pixel is the same whatever the threads or
// region.
void renderAdaptive(const PixelTracer& tracer, const PixelRegion& region,
                    const RenderSettings& settings, std::vector<Worker>& workers,
                    const ImageWriter& writer, const ProgressCallback& progress,
                    const CancelFlag* cancel) {
  // One progress for both passes.
  TileEdgeCorners edges(region.x0, region.y0, region.width(), region.height(), kTileSize);
  int firstTiles = static_cast<int>(edges.runCount());
  int secondTiles = tileCount(region);
  ProgressCallback firstProgress, secondProgress;
  if (progress) {
    firstProgress = [&](int done, int) { progress(done, firstTiles + secondTiles); };
    secondProgress = [&](int done, int) { progress(firstTiles + done, firstTiles + secondTiles); };
  }
  const int depth = subdivisionDepth(std::max(1, settings.samplesPerPixel));
  CornerInterpolation rule;
  // From one cut on (--spp 4), corners between anchors that agree to a tenth
  // of the threshold are their mean: on the default scene and glass-mirror
  // a third of the samples for the same error (docs/RENDERING.md).
  // Where no other object's box reaches between them, so that an object
  // narrower than the anchors' spacing is traced, not lost.
  std::optional<AnchorBlocks> blocks, coarseBlocks;
  if (depth > 0 && settings.interpolatesCorners) {
    rule.tolerance = kAnchorsAgreement * settings.adaptiveThreshold;
    blocks.emplace(tracer.scene(), tracer.camera(), settings.width, settings.height);
    rule.blocks = &*blocks;
    if (settings.interpolatesAnchors) {
      rule.coarseTolerance = kCoarseAnchorsAgreement * settings.adaptiveThreshold;
      coarseBlocks.emplace(tracer.scene(), tracer.camera(), settings.width, settings.height,
                           kCoarseSpan);
      rule.coarseBlocks = &*coarseBlocks;
    }
  }
  rule.fullWidth = settings.width;
  rule.fullHeight = settings.height;
  traceTileEdges(tracer, rule, edges, workers, firstProgress, cancel);
  std::vector<PixelSubdivider> subdividers(
      workers.size(), PixelSubdivider(tracer, rule, edges, settings.adaptiveThreshold, depth));
  forEachTile(
      region, static_cast<int>(workers.size()),
      [&](int index, const PixelRegion& tile) {
        Worker& worker = workers[index];
        PixelSubdivider& subdivider = subdividers[index];
        MediumStack media = tracer.eyeMedia();
        subdivider.startTile(tile, media, worker);
        for (int j = tile.y0; j < tile.y1; ++j) {
          if (cancel && cancel->requested()) throw RenderCancelled();
          subdivider.startRow();
          for (int i = tile.x0; i < tile.x1; ++i) {
            PixelSamples pixel = subdivider.pixel(i, j, i - tile.x0, media, worker);
            writer.store(i, j, tracer.certified(pixel, worker, [&](double finer) {
              return subdivider.retrace(i, j, finer, media, worker);
            }));
          }
        }
      },
      secondProgress);
}

}  // namespace

Image renderImageCpu(const RenderScene& scene, const RenderSettings& settings,
                     RenderStatistics* statistics, const ProgressCallback& progress,
                     const CancelFlag* cancel) {
  auto start = std::chrono::steady_clock::now();
  PixelRegion region = regionToRender(settings);
  Image image = blankImageFor(settings);
  std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;

  PixelTracer tracer(scene, settings);
  std::vector<Worker> workers(resolveThreads(settings.threads));
  ImageWriter writer(image);
  if (samplesAdaptively(settings)) {
    renderAdaptive(tracer, region, settings, workers, writer, progress, cancel);
  } else {
    renderUniform(tracer, region, settings, workers, writer, progress, cancel);
  }

  if (statistics) {
    *statistics = RenderStatistics{};
    for (const Worker& w : workers) {
      statistics->rays += w.context.counts;
      statistics->retracedPixels += w.retraced;
      statistics->samples += w.samples;
      statistics->refinedPixels += w.refined;
      statistics->fullySampledPixels += w.fullySampled;
      statistics->centredPixels += w.centred;
    }
    statistics->pixels = pixels;
    statistics->seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return image;
}

std::vector<std::int32_t> renderObjectIdsCpu(const RenderScene& scene,
                                             const RenderSettings& settings) {
  std::vector<std::int32_t> ids(static_cast<std::size_t>(settings.width) * settings.height, -1);
  PinholeCamera camera(scene.camera(), settings);
  forEachTile(
      PixelRegion{0, 0, settings.width, settings.height}, resolveThreads(settings.threads),
      [&](int, const PixelRegion& tile) {
        for (int j = tile.y0; j < tile.y1; ++j) {
          for (int i = tile.x0; i < tile.x1; ++i) {
            if (auto hit = scene.closestHit(camera.rayThrough(i + 0.5, j + 0.5), RaySource{})) {
              ids[static_cast<std::size_t>(j) * settings.width + i] =
                  static_cast<std::int32_t>(scene.sceneObject(hit->object));
            }
          }
        }
      },
      {});
  return ids;
}

}  // namespace render
