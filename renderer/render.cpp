#include "renderer/render.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>
#include <mutex>
#include <numbers>
#include <thread>

#include "renderer/saturating.h"
#include "scenefile/matrix.h"

namespace render {

namespace {

constexpr int kTileSize = 32;

// SplitMix64: a counter-based generator, so each pixel's samples depend on
// the seed and the pixel alone.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

double unitInterval(std::uint64_t bits) {
  return static_cast<double>(bits >> 11) * 0x1.0p-53;
}

// Keeps an image finite whatever the scene: NaN becomes 0, and values past
// the float range are clamped to it.
float toStoredChannel(double v) {
  if (!(v == v)) return 0.0f;
  constexpr double kMax = std::numeric_limits<float>::max();
  return static_cast<float>(std::clamp(v, -kMax, kMax));
}

template <typename PerTile>
void forEachTile(int width, int height, int threads, PerTile&& perTile,
                 const ProgressCallback& progress) {
  int tilesX = (width + kTileSize - 1) / kTileSize;
  int tilesY = (height + kTileSize - 1) / kTileSize;
  int total = tilesX * tilesY;
  std::atomic<int> next{0};
  std::atomic<int> done{0};
  std::mutex progressMutex;
  // An exception must not leave a thread's function (that ends the
  // program): the first one (std::bad_alloc, say) stops the handing out of
  // tiles and is thrown again once every thread has been joined.
  std::exception_ptr failure;
  std::mutex failureMutex;
  auto work = [&](int worker) {
    try {
      for (int tile = next++; tile < total; tile = next++) {
        int x0 = (tile % tilesX) * kTileSize;
        int y0 = (tile / tilesX) * kTileSize;
        perTile(worker, x0, y0, std::min(x0 + kTileSize, width), std::min(y0 + kTileSize, height));
        int finished = ++done;
        if (progress) {
          std::lock_guard<std::mutex> lock(progressMutex);
          progress(finished, total);
        }
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(failureMutex);
      if (!failure) failure = std::current_exception();
      next = total;
    }
  };
  std::vector<std::thread> pool;
  try {
    for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
  } catch (...) {
    // A thread that cannot start (std::system_error): the running ones
    // finish their tile and are joined before the caller hears of it.
    next = total;
    for (std::thread& t : pool) t.join();
    throw;
  }
  work(0);
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

// The level of an integer image of `levels` + 1 levels
// (tools::quantizeChannel): round(clamp(v, 0, 1) * levels). For 255 the
// float product is the one the 8-bit writer rounds.
long levelOf(float v, double levels) {
  float clamped = std::clamp(v, 0.0f, 1.0f);
  if (levels == 255.0) return std::lround(clamped * 255.0f);
  return std::lround(static_cast<double>(clamped) * levels);
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

int threadCount(int requested) {
  if (requested > 0) return requested;
  return std::max(1u, std::thread::hardware_concurrency());
}

// A sample's colour, the bound on what adaptive depth control left out of
// it (TraceContext::slack), and whether its camera ray met an object.
struct SampleColour {
  glm::dvec3 colour{0.0};
  double slack = 0.0;
  bool hit = false;
};

// What every sample of a render is traced with.
struct SampleTracing {
  const RenderScene& scene;
  const Tracer& tracer;
  const PinholeCamera& camera;
  // The media the camera starts in, and the sample's copy of them.
  const MediumStack& eyeMedia;
  MediumStack& media;
  TraceContext& context;
  std::uint64_t allowance;
  bool packets;
};

// Traces the camera rays through the `count` image positions `at`, each a
// sample of its own (its allowance, slack and media afresh), to within
// `tolerance`, into out[0, count). With packets, the closest hits of each
// Bvh::kPacketSize consecutive rays are found together
// (RenderScene::closestHits), and each sample is shaded from its hit: the
// same colours as tracing each alone, bit for bit.
void traceSamples(const SampleTracing& with, const glm::dvec2* at, int count, double tolerance,
                  SampleColour* out) {
  constexpr int kPacket = Bvh::kPacketSize;
  TraceContext& context = with.context;
  for (int first = 0; first < count; first += kPacket) {
    int n = std::min(kPacket, count - first);
    Ray rays[kPacket];
    for (int k = 0; k < n; ++k) rays[k] = with.camera.rayThrough(at[first + k].x, at[first + k].y);
    std::optional<Hit> hits[kPacket];
    if (with.packets) {
      const RaySource fromCamera[kPacket] = {};
      with.scene.closestHits(rays, fromCamera, n, hits);
    }
    for (int k = 0; k < n; ++k) {
      if (with.scene.hasTransparency()) with.media = with.eyeMedia;
      ++context.counts.primary;
      context.allowance = with.allowance;
      context.slack = 0.0;
      glm::dvec3 colour =
          with.packets ? with.tracer.traceFromHit(rays[k], hits[k], with.media, context, tolerance)
                       : with.tracer.trace(rays[k], RaySource{}, 0, with.media, context, tolerance);
      out[first + k] = SampleColour{colour, context.slack, context.primaryHit};
    }
  }
}

}  // namespace

PinholeCamera::PinholeCamera(const scene::Camera& camera, const RenderSettings& settings)
    : width_(settings.width), height_(settings.height) {
  eye_ = glm::dvec3(camera.matrix[3]);
  // Axes of any finite length are valid (1e-300, 1e300): unitDirection is
  // glm::normalize where that neither underflows nor overflows.
  forward_ = scene::unitDirection(-glm::dvec3(camera.matrix[2]));
  glm::dvec3 up(camera.matrix[1]);
  if (!scene::isModerate(up)) up = scene::unitDirection(up);
  up_ = scene::unitDirection(up - glm::dot(up, forward_) * forward_);
  right_ = glm::cross(forward_, up_);
  tanHalfHeight_ = std::tan(settings.verticalFovDegrees * std::numbers::pi / 360.0);
  tanHalfWidth_ = tanHalfHeight_ * width_ / height_;
}

Ray PinholeCamera::rayThrough(double x, double y) const {
  double sx = (2.0 * x / width_ - 1.0) * tanHalfWidth_;
  double sy = (1.0 - 2.0 * y / height_) * tanHalfHeight_;
  return Ray{eye_, glm::normalize(forward_ + sx * right_ + sy * up_)};
}

glm::dvec2 samplePosition(int i, int j, int index, int count, std::uint64_t seed) {
  if (count <= 1) return {i + 0.5, j + 0.5};
  int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
  int rows = (count + columns - 1) / columns;
  std::uint64_t state =
      mix(seed ^ mix((static_cast<std::uint64_t>(j) << 32) ^ static_cast<std::uint32_t>(i)) ^
          mix(static_cast<std::uint64_t>(index) + 0x5851F42D4C957F2Dull));
  double u = unitInterval(mix(state));
  double v = unitInterval(mix(state + 1));
  return {i + ((index % columns) + u) / columns, j + ((index / columns) + v) / rows};
}

std::uint64_t Image::bytesFor(int width, int height, bool withCoverage) {
  std::uint64_t pixels = saturatingProduct(static_cast<std::uint64_t>(width > 0 ? width : 0),
                                           static_cast<std::uint64_t>(height > 0 ? height : 0));
  return saturatingProduct(pixels, (kChannels + (withCoverage ? 1 : 0)) * sizeof(float));
}

Image renderImage(const RenderScene& scene, const RenderSettings& settings,
                  RenderStatistics* statistics, const ProgressCallback& progress,
                  const CancelFlag* cancel) {
  auto start = std::chrono::steady_clock::now();
  Image image;
  image.width = settings.width;
  image.height = settings.height;
  std::size_t pixels = static_cast<std::size_t>(settings.width) * settings.height;
  image.rgb.assign(pixels * Image::kChannels, 0.0f);
  if (settings.coverage) image.coverage.assign(pixels, 0.0f);
  PinholeCamera camera(scene.camera(), settings);
  Tracer tracer(scene, settings.maxDepth);
  // Not a number, or below 0, allows no error.
  double tolerance = std::max(0.0, settings.pruneTolerance);
  std::uint64_t allowance = settings.maxRaysPerSample > 0
                                ? settings.maxRaysPerSample
                                : std::numeric_limits<std::uint64_t>::max();
  // The media the camera starts in, for a camera inside glass.
  MediumStack eyeMedia;
  if (scene.hasTransparency()) {
    for (std::uint32_t object : scene.mediaContaining(camera.eye())) eyeMedia.push(object);
  }

  // Retracing needs a finite bound, has nothing to mend at tolerance 0, and
  // traces in full: without an allowance that could never end.
  bool certifies = tolerance > 0.0 && settings.maxRaysPerSample > 0 &&
                   tracer.bound().at(0) < RadianceBound::kUnbounded;

  int threads = threadCount(settings.threads);
  std::vector<TraceContext> contexts(threads);
  std::vector<std::uint64_t> retraced(threads, 0);
  int spp = std::max(1, settings.samplesPerPixel);
  forEachTile(
      settings.width, settings.height, threads,
      [&](int worker, int x0, int y0, int x1, int y1) {
        // The stack each sample starts with: copied afresh per sample only
        // where it can matter (a scene without transparency never reads or
        // changes it), as the copy cost as much as a tenth of a primary ray.
        MediumStack media = eyeMedia;
        TraceContext& context = contexts[worker];
        SampleTracing with{scene, tracer,  camera,    eyeMedia,
                           media, context, allowance, settings.packets};
        glm::dvec2 at[kTileSize];
        SampleColour samples[kTileSize];
        // Dividing by 1 is exact: skipped, for one division less a pixel.
        auto mean = [&](glm::dvec3& sum, double& slack) {
          if (spp > 1) {
            sum /= static_cast<double>(spp);
            slack /= static_cast<double>(spp);
          }
        };
        // The mean of a pixel's samples, traced to within `allowed`, in
        // `slack` the bound on what adaptive depth control left out of it,
        // and in `hits` how many of its camera rays met an object.
        auto tracePixel = [&](int i, int j, double allowed, double& slack, int& hits) {
          glm::dvec3 sum(0.0);
          slack = 0.0;
          hits = 0;
          for (int first = 0; first < spp; first += kTileSize) {
            int n = std::min(kTileSize, spp - first);
            for (int s = 0; s < n; ++s) at[s] = samplePosition(i, j, first + s, spp, settings.seed);
            traceSamples(with, at, n, allowed, samples);
            for (int s = 0; s < n; ++s) {
              sum += samples[s].colour;
              slack += samples[s].slack;
              hits += samples[s].hit ? 1 : 0;
            }
          }
          mean(sum, slack);
          return sum;
        };
        glm::dvec3 rowSums[kTileSize];
        double rowSlacks[kTileSize];
        int rowHits[kTileSize];
        for (int j = y0; j < y1; ++j) {
          // forEachTile stops handing out tiles at the first exception.
          if (cancel && cancel->requested()) throw RenderCancelled();
          // Sample s of the row's pixels side by side: neighbouring camera
          // rays, coherent enough to be traced as packets.
          int n = x1 - x0;
          for (int k = 0; k < n; ++k) {
            rowSums[k] = glm::dvec3(0.0);
            rowSlacks[k] = 0.0;
            rowHits[k] = 0;
          }
          for (int s = 0; s < spp; ++s) {
            for (int k = 0; k < n; ++k) at[k] = samplePosition(x0 + k, j, s, spp, settings.seed);
            traceSamples(with, at, n, tolerance, samples);
            for (int k = 0; k < n; ++k) {
              rowSums[k] += samples[k].colour;
              rowSlacks[k] += samples[k].slack;
              rowHits[k] += samples[k].hit ? 1 : 0;
            }
          }
          for (int i = x0; i < x1; ++i) {
            glm::dvec3 sum = rowSums[i - x0];
            double slack = rowSlacks[i - x0];
            int hits = rowHits[i - x0];
            mean(sum, slack);
            // The full colour lies in [sum, sum + slack]: where that range
            // holds two 8-bit levels, the pixel is traced again with a 64th
            // of the tolerance, then in full, until the range holds one
            // level (a trace that runs out of its allowance proves nothing,
            // and if every one does, the first stays).
            if (slack > 0.0 && certifies && !oneLevel(sum, slack, settings.levels)) {
              ++retraced[worker];
              for (double finer : {tolerance / 64.0, 0.0}) {
                std::uint64_t cutBefore = context.counts.cut;
                double finerSlack = 0.0;
                glm::dvec3 again = tracePixel(i, j, finer, finerSlack, hits);
                if (context.counts.cut == cutBefore &&
                    (finer == 0.0 || oneLevel(again, finerSlack, settings.levels))) {
                  sum = again;
                  break;
                }
              }
            }
            std::size_t pixel = static_cast<std::size_t>(j) * settings.width + i;
            float* p = &image.rgb[3 * pixel];
            for (int c = 0; c < 3; ++c) p[c] = toStoredChannel(sum[c]);
            if (settings.coverage) {
              image.coverage[pixel] = static_cast<float>(static_cast<double>(hits) / spp);
            }
          }
        }
      },
      progress);

  if (statistics) {
    statistics->rays = RayCounts{};
    for (const TraceContext& c : contexts) statistics->rays += c.counts;
    statistics->retracedPixels = 0;
    for (std::uint64_t r : retraced) statistics->retracedPixels += r;
    statistics->seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return image;
}

std::vector<std::int32_t> renderObjectIds(const RenderScene& scene,
                                          const RenderSettings& settings) {
  std::vector<std::int32_t> ids(static_cast<std::size_t>(settings.width) * settings.height, -1);
  PinholeCamera camera(scene.camera(), settings);
  forEachTile(
      settings.width, settings.height, threadCount(settings.threads),
      [&](int, int x0, int y0, int x1, int y1) {
        for (int j = y0; j < y1; ++j) {
          for (int i = x0; i < x1; ++i) {
            if (auto hit = scene.closestHit(camera.rayThrough(i + 0.5, j + 0.5), RaySource{})) {
              ids[static_cast<std::size_t>(j) * settings.width + i] =
                  static_cast<std::int32_t>(hit->object);
            }
          }
        }
      },
      {});
  return ids;
}

}  // namespace render
