// embree_trace: sfrender's primary and shadow rays traced by Embree 3,
// against sfrender's own passes over the same rays, in one process.
//
//   embree_trace SCENE [--width W --height H --runs R --threads "1 2" --only VARIANT]
//
// Reads SCENE through the project's reader and compiles it as sfrender does
// (render::RenderScene). Embree gets one user geometry
// (RTC_GEOMETRY_TYPE_USER) with a primitive per bounded object, its box the
// object's world bounds (render::worldBounds) widened by a few float steps
// (Embree's boxes and rays are float), and an intersect callback that runs
// the renderer's exact double-precision test of that object on the double
// ray (the float ray Embree carries only steers its traversal). Planes,
// which have no bounds, are tested first, outside Embree, as RenderScene
// does. So the hits are the project's, and only the search differs.
//
// The rays are those of render::PinholeCamera through the pixel centres.
// Each variant is timed on each thread count: Embree one ray at a time
// (rtcIntersect1) and in packets of 4 (2x2 pixels, rtcIntersect4) and 8
// (4x2, rtcIntersect8), rows handed out to threads one at a time; and
// sfrender's camera path (render::traceCameraRays: the camera's rays, the
// eye's grid where it pays, the packets, tiles in turn). The object id of
// every pixel is compared with render::renderObjectIds (one ray at a time):
// a difference can only be a tie (two objects met at the same distance) or
// a ray whose float box test misses where the double one meets, and their
// count is printed. The primary rays are timed twice: ids only (Embree's
// callbacks find distances; sfrender's camera path makes its hits all the
// same), and like for like, every tracer making each pixel's hit in full
// (point, error bound, normal) inside its pass, Embree's by the renderer's
// RenderScene::hitsOnObjects on the closest object it found, every hit
// compared bit for bit with sfrender's.
//
// Shadow rays: from every primary hit toward every light, sfrender's
// render::Tracer::shadowed (its light grids, shadowCell, the occluder hint)
// against Embree's rtcOccluded1/4/8 on the same rays (the renderer's offset
// origin, its segment's end short of the light, the planes tested first,
// the renderer's exact test with the ray's source in the callback), in
// packets of consecutive hits of a tile's row; both take tiles in turn. The
// answers are compared, ray by ray.
//
// Prints "key: value" lines (for bench/tracers.sh) and then a table.
#include <embree3/rtcore.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <functional>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "bench/embree_geometry.h"
#include "bench/scene_loading.h"
#include "renderer/camera.h"
#include "renderer/camera_trace.h"
#include "renderer/float_error.h"
#include "renderer/render.h"
#include "renderer/render_scene.h"
#include "renderer/render_tiles.h"
#include "renderer/tracer.h"
#include "renderer/unit_shapes.h"

namespace {

using namespace bench;
using Clock = std::chrono::steady_clock;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// The calling thread's CPU time, in seconds: on one thread, what a pass
// costs whatever else the machine runs.
double threadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The float ray Embree steers by, from the renderer's double one, its
// segment ending at `tfar`.
void fillFloatRay(RTCRay& r, const render::Ray& ray, float tfar, unsigned id) {
  r.org_x = static_cast<float>(ray.origin.x);
  r.org_y = static_cast<float>(ray.origin.y);
  r.org_z = static_cast<float>(ray.origin.z);
  r.dir_x = static_cast<float>(ray.direction.x);
  r.dir_y = static_cast<float>(ray.direction.y);
  r.dir_z = static_cast<float>(ray.direction.z);
  r.tnear = 0.0f;
  r.tfar = tfar;
  r.time = 0.0f;
  r.mask = 0xFFFFFFFF;
  r.id = id;
  r.flags = 0;
}

// One pixel's ray, its nearest plane hit first: Embree then searches only
// nearer than that.
struct Pixel {
  render::Ray ray;
  double nearest = std::numeric_limits<double>::infinity();
  std::int32_t id = -1;
  std::uint32_t object = render::RaySource::kNone;  // as RenderScene numbers it
};

using Hits = std::vector<std::optional<render::Hit>>;

class Tracers {
 public:
  Tracers(const render::RenderScene& scene, const render::RenderSettings& settings,
          const Geometry& geometry, RTCScene embree)
      : scene_(scene),
        settings_(settings),
        camera_(scene.camera(), settings),
        geometry_(geometry),
        embree_(embree) {
    for (std::uint32_t i = 0; i < scene.objects().size(); ++i) {
      if (scene.objects()[i].kind == scene::ObjectKind::Plane) planes_.push_back(i);
    }
  }

  // The ids of one packet of `count` pixels starting at (x, y), `columns`
  // wide, traced with rtcIntersect<count> (count 1, 4 or 8); with `hits`,
  // each pixel's hit too, made by the renderer's code (hitsOnObjects) on the
  // closest object Embree found, as a renderer built on Embree would.
  void tracePacket(int count, int columns, int x, int y, std::int32_t* ids,
                   std::optional<render::Hit>* hits) const {
    Pixel pixels[8];
    double nearest[8];
    render::Ray rays[8];
    for (int k = 0; k < count; ++k) {
      Pixel& p = pixels[k];
      p.ray = camera_.rayThrough(x + k % columns + 0.5, y + k / columns + 0.5);
      for (std::uint32_t plane : planes_) {
        double t = objectDistance(scene_.objects()[plane], p.ray, p.nearest);
        if (t >= 0.0) {
          p.nearest = t;
          p.id = static_cast<std::int32_t>(scene_.sceneObject(plane));
          p.object = plane;
        }
      }
      nearest[k] = p.nearest;
      rays[k] = p.ray;
    }
    TraceContext context;
    rtcInitIntersectContext(&context.embree);
    context.rays = rays;
    context.nearest = nearest;
    if (count == 1) {
      RTCRayHit rh;
      fill(rh.ray, rh.hit, pixels[0], 0);
      rtcIntersect1(embree_, &context.embree, &rh);
      collect(rh.hit.geomID, rh.hit.primID, pixels[0], ids[0]);
    } else if (count == 4) {
      alignas(16) RTCRayHit4 rh;
      alignas(16) int valid[4];
      tracePacketN(rh, valid, 4, context, pixels, ids, columns);
      rtcIntersect4(valid, embree_, &context.embree, &rh);
      collectN(rh, 4, pixels, ids, columns);
    } else {
      alignas(32) RTCRayHit8 rh;
      alignas(32) int valid[8];
      tracePacketN(rh, valid, 8, context, pixels, ids, columns);
      rtcIntersect8(valid, embree_, &context.embree, &rh);
      collectN(rh, 8, pixels, ids, columns);
    }
    if (!hits) return;
    // Nearer than just past its distance: the same end of the same span.
    std::uint32_t objects[8];
    for (int k = 0; k < count; ++k) {
      objects[k] = pixels[k].object;
      nearest[k] = std::nextafter(nearest[k], kInfinity);
    }
    scene_.hitsOnObjects(objects, rays, nearest, count, hits);
  }

  // Every pixel, `threads` threads taking rows (packets of two or one rows)
  // in turn; the ids into `ids`, row by row, and with `hits` the hits.
  void traceAll(int count, int threads, std::vector<std::int32_t>& ids,
                Hits* hits = nullptr) const {
    int columns = count == 1 ? 1 : count / 2;
    int rows = count == 1 ? 1 : 2;
    std::atomic<int> nextRow{0};
    auto work = [&] {
      std::int32_t packet[8];
      std::optional<render::Hit> packetHits[8];
      for (int y; (y = nextRow.fetch_add(rows)) < settings_.height;) {
        for (int x = 0; x < settings_.width; x += columns) {
          tracePacket(count, columns, x, y, packet, hits ? packetHits : nullptr);
          for (int k = 0; k < count; ++k) {
            int px = x + k % columns, py = y + k / columns;
            if (px < settings_.width && py < settings_.height) {
              std::size_t at = static_cast<std::size_t>(py) * settings_.width + px;
              ids[at] = packet[k];
              if (hits) (*hits)[at] = packetHits[k];
            }
          }
        }
      }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
    for (auto& t : pool) t.join();
  }

 private:
  static void fill(RTCRay& r, RTCHit& h, const Pixel& p, unsigned id) {
    fillFloatRay(r, p.ray,
                 std::isinf(p.nearest) ? std::numeric_limits<float>::infinity()
                                       : render::floatAtOrAbove(p.nearest),
                 id);
    h.geomID = RTC_INVALID_GEOMETRY_ID;
    h.instID[0] = RTC_INVALID_GEOMETRY_ID;
  }
  void collect(unsigned geomID, unsigned primID, Pixel& p, std::int32_t& id) const {
    if (geomID != RTC_INVALID_GEOMETRY_ID) p.object = geometry_.bounded[primID];
    id = p.object == render::RaySource::kNone
             ? -1
             : static_cast<std::int32_t>(scene_.sceneObject(p.object));
  }
  // Packets: lanes past the image's edge are left out (valid 0).
  template <typename RayHitN>
  void tracePacketN(RayHitN& rh, int* valid, int n, const TraceContext&, const Pixel* pixels,
                    const std::int32_t*, int) const {
    for (int k = 0; k < n; ++k) {
      RTCRay r;
      RTCHit h;
      fill(r, h, pixels[k], static_cast<unsigned>(k));
      rh.ray.org_x[k] = r.org_x, rh.ray.org_y[k] = r.org_y, rh.ray.org_z[k] = r.org_z;
      rh.ray.dir_x[k] = r.dir_x, rh.ray.dir_y[k] = r.dir_y, rh.ray.dir_z[k] = r.dir_z;
      rh.ray.tnear[k] = r.tnear, rh.ray.tfar[k] = r.tfar, rh.ray.time[k] = 0.0f;
      rh.ray.mask[k] = r.mask, rh.ray.id[k] = r.id, rh.ray.flags[k] = 0;
      rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
      valid[k] = -1;
    }
  }
  template <typename RayHitN>
  void collectN(const RayHitN& rh, int n, Pixel* pixels, std::int32_t* ids, int) const {
    for (int k = 0; k < n; ++k) collect(rh.hit.geomID[k], rh.hit.primID[k], pixels[k], ids[k]);
  }

  const render::RenderScene& scene_;
  render::RenderSettings settings_;
  render::PinholeCamera camera_;
  const Geometry& geometry_;
  RTCScene embree_;
  std::vector<std::uint32_t> planes_;
};

// A shadow ray as render::Tracer::shadowed makes it from a hit toward a
// light, for Embree.
struct ShadowQuery {
  render::Ray ray;
  render::RaySource source;
  double tMax = 0.0;
};

// The primary hits, pixel by pixel, and the shadow rays' answers (1:
// blocked), per pixel and light.
struct ShadowWork {
  std::vector<std::optional<render::Hit>> hits;
  std::size_t lights = 0;
  std::size_t rays = 0;  // (hit, light) pairs
};

class ShadowTracers {
 public:
  ShadowTracers(const render::RenderScene& scene, const render::RenderSettings& settings,
                const ShadowWork& work, RTCScene embree)
      : scene_(scene), settings_(settings), work_(work), embree_(embree) {
    for (std::uint32_t i = 0; i < scene.objects().size(); ++i) {
      if (scene.objects()[i].kind == scene::ObjectKind::Plane) planes_.push_back(i);
    }
  }

  // sfrender: render::Tracer::shadowed for every hit and light, with each
  // thread's trace context (its occluder hints), tiles in turn.
  void sfrender(int threads, std::vector<std::uint8_t>& answers) const {
    render::Tracer tracer(scene_, settings_.maxDepth);
    std::vector<render::TraceContext> contexts(static_cast<std::size_t>(threads));
    forTiles(threads, [&](int worker, int x0, int x1, int y) {
      render::TraceContext& context = contexts[static_cast<std::size_t>(worker)];
      for (int x = x0; x < x1; ++x) {
        std::size_t pixel = static_cast<std::size_t>(y) * settings_.width + x;
        const std::optional<render::Hit>& hit = work_.hits[pixel];
        if (!hit) continue;
        for (std::size_t light = 0; light < work_.lights; ++light) {
          std::uint32_t* hint = &context.lastOccluder[light % render::TraceContext::kOccluderSlots];
          answers[pixel * work_.lights + light] = tracer.shadowed(*hit, light, context, hint);
        }
      }
    });
  }

  // Embree: rtcOccluded<width> on the rays of consecutive hits of a tile's
  // row toward one light (width 1, 4 or 8).
  void embree(int width, int threads, std::vector<std::uint8_t>& answers) const {
    forTiles(threads, [&](int, int x0, int x1, int y) {
      for (std::size_t light = 0; light < work_.lights; ++light) {
        ShadowQuery batch[8];
        std::size_t at[8];
        int n = 0;
        for (int x = x0; x < x1; ++x) {
          std::size_t pixel = static_cast<std::size_t>(y) * settings_.width + x;
          const std::optional<render::Hit>& hit = work_.hits[pixel];
          if (!hit) continue;
          std::size_t answer = pixel * work_.lights + light;
          int state = prepare(*hit, light, batch[n]);
          if (state >= 0) {
            answers[answer] = static_cast<std::uint8_t>(state);
            continue;
          }
          at[n++] = answer;
          if (n == width) {
            occluded(width, batch, n, at, answers);
            n = 0;
          }
        }
        if (n > 0) occluded(width, batch, n, at, answers);
      }
    });
  }

 private:
  // perRow(worker, x0, x1, y) for each row of each 32x32 tile, tiles in
  // turn on `threads` threads.
  template <typename PerRow>
  void forTiles(int threads, PerRow&& perRow) const {
    render::forEachTile(render::PixelRegion{0, 0, settings_.width, settings_.height}, threads,
                        [&](int worker, const render::PixelRegion& tile) {
                          for (int y = tile.y0; y < tile.y1; ++y)
                            perRow(worker, tile.x0, tile.x1, y);
                        },
                        {});
  }

  // Tracer::shadowed's ray from `hit` toward light `light` into q, and the
  // planes' test: 0 clear, 1 blocked, -1 for Embree to say.
  int prepare(const render::Hit& hit, std::size_t light, ShadowQuery& q) const {
    const glm::dvec3& position = scene_.lights()[light].position;
    glm::dvec3 toLight = position - hit.point;
    q.ray.origin = render::offsetRayOrigin(hit.point, hit.pointError, hit.normal, toLight);
    q.ray.direction = position - q.ray.origin;
    q.source = render::RaySource{hit.object, glm::dot(q.ray.direction, hit.normal) < 0.0};
    const glm::dvec3& o = q.ray.origin;
    const glm::dvec3& d = q.ray.direction;
    double extent = std::max({std::abs(position.x), std::abs(position.y), std::abs(position.z),
                              std::abs(o.x), std::abs(o.y), std::abs(o.z)});
    double length = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    if (length == 0.0) return 0;
    q.tMax = 1.0 - render::gamma(32) * extent / length;
    if (q.tMax <= 0.0) return 0;
    for (std::uint32_t plane : planes_) {
      if (blocks(scene_.objects()[plane], plane, q.ray, q.source, q.tMax)) return 1;
    }
    return -1;
  }

  void occluded(int width, const ShadowQuery* batch, int n, const std::size_t* at,
                std::vector<std::uint8_t>& answers) const {
    render::Ray rays[8];
    render::RaySource sources[8];
    double limits[8];
    for (int k = 0; k < n; ++k) {
      rays[k] = batch[k].ray;
      sources[k] = batch[k].source;
      limits[k] = batch[k].tMax;
    }
    TraceContext context;
    rtcInitIntersectContext(&context.embree);
    context.rays = rays;
    context.nearest = limits;
    context.sources = sources;
    if (width == 1) {
      RTCRay r;
      fill(r, batch[0], 0);
      rtcOccluded1(embree_, &context.embree, &r);
      answers[at[0]] = r.tfar < 0.0f;
    } else if (width == 4) {
      alignas(16) RTCRay4 r;
      alignas(16) int valid[4];
      fillN(r, valid, 4, batch, n);
      rtcOccluded4(valid, embree_, &context.embree, &r);
      for (int k = 0; k < n; ++k) answers[at[k]] = r.tfar[k] < 0.0f;
    } else {
      alignas(32) RTCRay8 r;
      alignas(32) int valid[8];
      fillN(r, valid, 8, batch, n);
      rtcOccluded8(valid, embree_, &context.embree, &r);
      for (int k = 0; k < n; ++k) answers[at[k]] = r.tfar[k] < 0.0f;
    }
  }

  // The float ray Embree steers by; its segment ends at tMax rounded up.
  static void fill(RTCRay& r, const ShadowQuery& q, unsigned id) {
    fillFloatRay(r, q.ray, render::floatAtOrAbove(q.tMax), id);
  }
  template <typename RayN>
  static void fillN(RayN& rays, int* valid, int width, const ShadowQuery* batch, int n) {
    for (int k = 0; k < width; ++k) {
      RTCRay r;
      fill(r, batch[k < n ? k : 0], static_cast<unsigned>(k));
      rays.org_x[k] = r.org_x, rays.org_y[k] = r.org_y, rays.org_z[k] = r.org_z;
      rays.dir_x[k] = r.dir_x, rays.dir_y[k] = r.dir_y, rays.dir_z[k] = r.dir_z;
      rays.tnear[k] = r.tnear, rays.tfar[k] = r.tfar, rays.time[k] = 0.0f;
      rays.mask[k] = r.mask, rays.id[k] = r.id, rays.flags[k] = 0;
      valid[k] = k < n ? -1 : 0;
    }
  }

  const render::RenderScene& scene_;
  render::RenderSettings settings_;
  const ShadowWork& work_;
  RTCScene embree_;
  std::vector<std::uint32_t> planes_;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

template <typename T>
std::size_t differences(const std::vector<T>& a, const std::vector<T>& b) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < a.size(); ++i) count += a[i] != b[i];
  return count;
}

// Hits differ unless every field has the same bits.
bool sameHit(const std::optional<render::Hit>& a, const std::optional<render::Hit>& b) {
  if (!a || !b) return !a == !b;
  auto same = [](const glm::dvec3& u, const glm::dvec3& v) {
    return std::memcmp(&u, &v, sizeof u) == 0;
  };
  return std::memcmp(&a->t, &b->t, sizeof a->t) == 0 && a->object == b->object &&
         same(a->point, b->point) && same(a->pointError, b->pointError) &&
         same(a->normal, b->normal) && a->fromInside == b->fromInside;
}

std::size_t differences(const Hits& a, const Hits& b) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < a.size(); ++i) count += !sameHit(a[i], b[i]);
  return count;
}

struct Row {
  std::string name;
  std::vector<double> mrays;
  std::size_t diff = 0;
};

// How each variant is timed: runs (median), thread counts, and, when not
// empty, the one variant to time (for a profiler).
struct Timing {
  int runs = 3;
  std::vector<int> threadCounts{1, 2};
  std::string only;
};

template <typename T>
struct Variant {
  std::string name;
  std::function<void(int threads, std::vector<T>& out)> pass;
};

// Times each variant `runs` times on each thread count, the variants in
// turn in each run (a load that comes and goes hits them alike), for
// `rays` rays; their medians, and the entries of each one's output that
// differ from `reference`. Prints the key lines.
template <typename T>
std::vector<Row> timed(std::vector<Variant<T>> variants, double rays, const Timing& timing,
                       const std::vector<T>& reference) {
  if (!timing.only.empty()) {
    std::erase_if(variants, [&](const Variant<T>& v) { return v.name != timing.only; });
  }
  const int runs = timing.runs;
  const std::vector<int>& threadCounts = timing.threadCounts;
  std::vector<Row> rows;
  for (const Variant<T>& v : variants) rows.push_back(Row{v.name, {}, 0});
  for (int threads : threadCounts) {
    std::vector<std::vector<double>> seconds(variants.size());
    std::vector<std::vector<double>> cpuSeconds(variants.size());
    std::vector<T> out(reference.size());
    for (int r = 0; r < runs; ++r) {
      for (std::size_t v = 0; v < variants.size(); ++v) {
        auto start = Clock::now();
        double cpuStart = threadSeconds();
        variants[v].pass(threads, out);
        seconds[v].push_back(since(start));
        cpuSeconds[v].push_back(threadSeconds() - cpuStart);
        rows[v].diff = std::max(rows[v].diff, differences(out, reference));
      }
    }
    for (std::size_t v = 0; v < variants.size(); ++v) {
      double mrays = rays / median(seconds[v]) / 1e6;
      rows[v].mrays.push_back(mrays);
      std::printf("%s_%dt_mrays: %.4f\n", rows[v].name.c_str(), threads, mrays);
      if (threads == 1) {
        std::printf("%s_1t_cpu_mrays: %.4f\n", rows[v].name.c_str(),
                    rays / median(cpuSeconds[v]) / 1e6);
      }
    }
  }
  for (const Row& row : rows) std::printf("%s_differences: %zu\n", row.name.c_str(), row.diff);
  return rows;
}

void printTable(const char* title, const std::vector<Row>& table,
                const std::vector<int>& threadCounts) {
  std::printf("\n%-16s", title);
  for (int threads : threadCounts) std::printf(" | %2d thread(s), Mrays/s", threads);
  std::printf(" | differing\n");
  for (const Row& row : table) {
    std::printf("%-16s", row.name.c_str());
    for (double m : row.mrays) std::printf(" | %21.3f", m);
    std::printf(" | %zu\n", row.diff);
  }
}

// sfrender's camera path, the ids of its hits into `ids`; `hits`, when
// given, gets the hits themselves.
void sfrenderIds(const render::RenderScene& scene, render::RenderSettings settings, int threads,
                 std::vector<std::int32_t>& ids,
                 std::vector<std::optional<render::Hit>>* hits = nullptr) {
  settings.threads = threads;
  render::traceCameraRays(
      scene, settings,
      [&](int y, int x0, int n, const render::Ray*, const std::optional<render::Hit>* found) {
        std::size_t at = static_cast<std::size_t>(y) * settings.width + x0;
        for (int k = 0; k < n; ++k) {
          ids[at + k] =
              found[k] ? static_cast<std::int32_t>(scene.sceneObject(found[k]->object)) : -1;
          if (hits) (*hits)[at + k] = found[k];
        }
      });
}

std::vector<Row> primaryRays(const render::RenderScene& compiled,
                             const render::RenderSettings& settings, const Tracers& tracers,
                             const Timing& timing) {
  const std::vector<std::int32_t> reference = render::renderObjectIds(compiled, settings);
  const double pixels = static_cast<double>(reference.size());
  std::vector<Variant<std::int32_t>> variants;
  variants.push_back({"sfrender", [&](int threads, std::vector<std::int32_t>& ids) {
                        sfrenderIds(compiled, settings, threads, ids);
                      }});
  // The same without the eye's grid (RenderSettings::eyeGrid), where it
  // has one: what the grid gains.
  if (render::CameraTrace(compiled, settings).hasEyeGrid()) {
    render::RenderSettings packetsOnly = settings;
    packetsOnly.eyeGrid = false;
    variants.push_back(
        {"sfrender_packets", [&compiled, packetsOnly](int threads, std::vector<std::int32_t>& ids) {
           sfrenderIds(compiled, packetsOnly, threads, ids);
         }});
  }
  for (int width : {1, 4, 8}) {
    variants.push_back({"embree" + std::to_string(width),
                        [&tracers, width](int threads, std::vector<std::int32_t>& ids) {
                          tracers.traceAll(width, threads, ids);
                        }});
  }
  return timed(variants, pixels, timing, reference);
}

// Like for like: every tracer makes each pixel's hit in full (point, error
// bound, normal) by the renderer's code, timed inside its pass, and every
// hit is compared bit for bit with sfrender's (one thread).
std::vector<Row> primaryHits(const render::RenderScene& compiled,
                             const render::RenderSettings& settings, const Tracers& tracers,
                             const Timing& timing) {
  std::size_t pixels = static_cast<std::size_t>(settings.width) * settings.height;
  std::vector<std::int32_t> ids(pixels);
  Hits reference(pixels);
  sfrenderIds(compiled, settings, 1, ids, &reference);
  std::vector<Variant<std::optional<render::Hit>>> variants;
  variants.push_back({"sfrender_hits", [&](int threads, Hits& hits) {
                        sfrenderIds(compiled, settings, threads, ids, &hits);
                      }});
  if (render::CameraTrace(compiled, settings).hasEyeGrid()) {
    render::RenderSettings packetsOnly = settings;
    packetsOnly.eyeGrid = false;
    variants.push_back({"sfrender_packets_hits", [&, packetsOnly](int threads, Hits& hits) {
                          sfrenderIds(compiled, packetsOnly, threads, ids, &hits);
                        }});
  }
  for (int width : {1, 4, 8}) {
    variants.push_back(
        {"embree" + std::to_string(width) + "_hits",
         [&, width](int threads, Hits& hits) { tracers.traceAll(width, threads, ids, &hits); }});
  }
  return timed(variants, static_cast<double>(pixels), timing, reference);
}

std::vector<Row> shadowRays(const render::RenderScene& compiled,
                            const render::RenderSettings& settings, RTCScene embree,
                            const Timing& timing) {
  ShadowWork work;
  std::size_t pixels = static_cast<std::size_t>(settings.width) * settings.height;
  work.hits.resize(pixels);
  work.lights = compiled.lights().size();
  std::vector<std::int32_t> ids(pixels);
  sfrenderIds(compiled, settings, 1, ids, &work.hits);
  for (const auto& hit : work.hits) work.rays += hit ? work.lights : 0;
  std::printf("shadow_rays: %zu\n", work.rays);
  ShadowTracers tracers(compiled, settings, work, embree);
  // The reference: one thread of sfrender's own pass.
  std::vector<std::uint8_t> reference(pixels * work.lights, 0);
  tracers.sfrender(1, reference);
  std::vector<Variant<std::uint8_t>> variants;
  variants.push_back({"sfrender_shadow", [&](int threads, std::vector<std::uint8_t>& answers) {
                        tracers.sfrender(threads, answers);
                      }});
  for (int width : {1, 4, 8}) {
    variants.push_back({"embree" + std::to_string(width) + "_shadow",
                        [&tracers, width](int threads, std::vector<std::uint8_t>& answers) {
                          tracers.embree(width, threads, answers);
                        }});
  }
  return timed(variants, static_cast<double>(work.rays), timing, reference);
}

int run(const std::string& path, render::RenderSettings settings, const Timing& timing) {
  std::optional<scene::Scene> loaded = bench::loadScene(path, "embree_trace");
  if (!loaded) return 1;
  auto t0 = Clock::now();
  render::RenderScene compiled(*loaded);
  const double sfBuild = since(t0);

  t0 = Clock::now();
  Geometry geometry;
  geometry.objects = &compiled.objects();
  for (std::uint32_t i = 0; i < compiled.objects().size(); ++i) {
    // RenderScene numbers its objects in its own order (sceneObject).
    const scene::Object& o = loaded->objects[compiled.sceneObject(i)];
    if (auto b = render::worldBounds(o.kind, o.matrix)) {
      geometry.bounded.push_back(i);
      geometry.bounds.push_back(*b);
    }
  }
  EmbreeScene embree;
  embree.device = rtcNewDevice("threads=2");
  if (!embree.device) {
    std::cerr << "embree_trace: error: rtcNewDevice failed\n";
    return 1;
  }
  embree.scene = rtcNewScene(embree.device);
  RTCGeometry user = rtcNewGeometry(embree.device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(user, static_cast<unsigned>(geometry.bounded.size()));
  rtcSetGeometryUserData(user, &geometry);
  rtcSetGeometryBoundsFunction(user, boundsOf, nullptr);
  rtcSetGeometryIntersectFunction(user, intersect);
  rtcSetGeometryOccludedFunction(user, occluded);
  rtcCommitGeometry(user);
  rtcAttachGeometry(embree.scene, user);
  rtcReleaseGeometry(user);
  rtcCommitScene(embree.scene);
  const double embreeBuild = since(t0);
  if (rtcGetDeviceError(embree.device) != RTC_ERROR_NONE) {
    std::cerr << "embree_trace: error: building the embree scene failed\n";
    return 1;
  }

  settings.threads = 1;
  Tracers tracers(compiled, settings, geometry, embree.scene);
  std::printf("objects: %zu\n", compiled.objects().size());
  std::printf("rays: %lld\n", static_cast<long long>(settings.width) * settings.height);
  std::printf("sfrender_build_s: %.6f\n", sfBuild);
  std::printf("embree_build_s: %.6f\n", embreeBuild);
  std::printf("sfrender_eye_grid: %d\n",
              render::CameraTrace(compiled, settings).hasEyeGrid() ? 1 : 0);
  std::vector<Row> primary = primaryRays(compiled, settings, tracers, timing);
  std::vector<Row> hits = primaryHits(compiled, settings, tracers, timing);
  std::vector<Row> shadow = shadowRays(compiled, settings, embree.scene, timing);
  printTable("primary, ids", primary, timing.threadCounts);
  printTable("primary, hits", hits, timing.threadCounts);
  printTable("shadow", shadow, timing.threadCounts);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "sfrender's primary and shadow rays traced by Embree 3 (user geometry) and by sfrender"};
  render::RenderSettings settings;
  settings.width = 1920;
  settings.height = 1080;
  std::string input;
  Timing timing;
  app.add_option("scene", input, "scene file (any format sfrender reads)")->required();
  app.add_option("--width", settings.width, "image width")->check(CLI::Range(1, 1 << 15));
  app.add_option("--height", settings.height, "image height")->check(CLI::Range(1, 1 << 15));
  app.add_option("--runs", timing.runs, "timed runs of each variant (median)")
      ->check(CLI::Range(1, 100));
  app.add_option("--threads", timing.threadCounts, "thread counts to time")
      ->check(CLI::Range(1, 256));
  app.add_option("--only", timing.only, "time this variant alone (sfrender, embree8_shadow, ...)");
  CLI11_PARSE(app, argc, argv);
  return run(input, settings, timing);
}
