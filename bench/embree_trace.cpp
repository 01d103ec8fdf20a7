// embree_trace: sfrender's primary rays traced by Embree 3, against
// sfrender's own pass over the same rays, in one process.
//
//   embree_trace SCENE [--width W --height H --runs R --threads "1 2"]
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
// Each variant is timed on each thread count (rows handed out to threads
// one at a time): Embree one ray at a time (rtcIntersect1) and in packets
// of 4 (2x2 pixels, rtcIntersect4) and 8 (4x2, rtcIntersect8), and
// render::renderObjectIds, sfrender's own primary-ray pass. The object id
// of every pixel is compared with renderObjectIds: a difference can only be
// a tie (two objects met at the same distance) or a ray whose float box
// test misses where the double one meets, and their count is printed.
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
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "bench/scene_loading.h"
#include "renderer/camera.h"
#include "renderer/render.h"
#include "renderer/render_scene.h"
#include "renderer/unit_shapes.h"

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// The renderer's test of one object by a camera ray (RenderScene's
// intersectObject for a ray that leaves no surface): the nearest end of the
// object's span ahead of the origin and nearer than tMax, or a negative
// value for none.
double objectDistance(const render::RenderObject& object, const render::Ray& ray, double tMax) {
  glm::dvec3 o = object.toLocalPoint(ray.origin);
  glm::dvec3 d = object.toLocal * ray.direction;
  render::SpanDistances span = render::unitShapeDistances(object.kind, o, d);
  if (span.empty) return -1.0;
  if (span.enter > 0.0 && span.enter < tMax) return span.enter;
  if (object.kind != scene::ObjectKind::Plane && span.exit > 0.0 && span.exit < tMax) {
    return span.exit;
  }
  return -1.0;
}

// What the callbacks share: the objects, and Embree primitive -> object.
struct Geometry {
  const std::vector<render::RenderObject>* objects = nullptr;
  std::vector<std::uint32_t> bounded;
  std::vector<render::Bounds> bounds;
};

// Embree's context, extended with the double rays of the current call
// (one, or a packet's) and the exact distance of each one's nearest hit so
// far: Embree's float tfar only prunes its traversal.
struct TraceContext {
  RTCIntersectContext embree;
  const render::Ray* rays = nullptr;
  double* nearest = nullptr;
};

void boundsOf(const RTCBoundsFunctionArguments* args) {
  const auto* g = static_cast<const Geometry*>(args->geometryUserPtr);
  const render::Bounds& b = g->bounds[args->primID];
  // Widened by 4 float steps of the box's size: a float ray, rounded from
  // the double one, must not miss a box the double ray meets.
  glm::dvec3 pad =
      (glm::abs(b.lo) + glm::abs(b.hi)) * (4.0 * std::numeric_limits<float>::epsilon());
  RTCBounds* out = args->bounds_o;
  out->lower_x = render::floatAtOrBelow(b.lo.x - pad.x);
  out->lower_y = render::floatAtOrBelow(b.lo.y - pad.y);
  out->lower_z = render::floatAtOrBelow(b.lo.z - pad.z);
  out->upper_x = render::floatAtOrAbove(b.hi.x + pad.x);
  out->upper_y = render::floatAtOrAbove(b.hi.y + pad.y);
  out->upper_z = render::floatAtOrAbove(b.hi.z + pad.z);
}

void intersect(const RTCIntersectFunctionNArguments* args) {
  const auto* g = static_cast<const Geometry*>(args->geometryUserPtr);
  auto* context = reinterpret_cast<TraceContext*>(args->context);
  std::uint32_t object = g->bounded[args->primID];
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
  for (unsigned lane = 0; lane < args->N; ++lane) {
    if (args->valid[lane] != -1) continue;
    unsigned id = RTCRayN_id(rays, args->N, lane);
    double& nearest = context->nearest[id];
    double t = objectDistance((*g->objects)[object], context->rays[id], nearest);
    if (t < 0.0) continue;
    nearest = t;
    RTCRayN_tfar(rays, args->N, lane) = render::floatAtOrAbove(t);
    RTCHitN_primID(hits, args->N, lane) = args->primID;
    RTCHitN_geomID(hits, args->N, lane) = args->geomID;
    RTCHitN_instID(hits, args->N, lane, 0) = RTC_INVALID_GEOMETRY_ID;
  }
}

struct EmbreeScene {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  ~EmbreeScene() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

// One pixel's ray, its nearest plane hit first: Embree then searches only
// nearer than that.
struct Pixel {
  render::Ray ray;
  double nearest = std::numeric_limits<double>::infinity();
  std::int32_t id = -1;
};

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
  // wide, traced with rtcIntersect<count> (count 1, 4 or 8).
  void tracePacket(int count, int columns, int x, int y, std::int32_t* ids) const {
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
  }

  // Every pixel, `threads` threads taking rows (packets of two or one rows)
  // in turn; the ids into `ids`, row by row.
  void traceAll(int count, int threads, std::vector<std::int32_t>& ids) const {
    int columns = count == 1 ? 1 : count / 2;
    int rows = count == 1 ? 1 : 2;
    std::atomic<int> nextRow{0};
    auto work = [&] {
      std::int32_t packet[8];
      for (int y; (y = nextRow.fetch_add(rows)) < settings_.height;) {
        for (int x = 0; x < settings_.width; x += columns) {
          tracePacket(count, columns, x, y, packet);
          for (int k = 0; k < count; ++k) {
            int px = x + k % columns, py = y + k / columns;
            if (px < settings_.width && py < settings_.height) {
              ids[static_cast<std::size_t>(py) * settings_.width + px] = packet[k];
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
    r.org_x = static_cast<float>(p.ray.origin.x);
    r.org_y = static_cast<float>(p.ray.origin.y);
    r.org_z = static_cast<float>(p.ray.origin.z);
    r.dir_x = static_cast<float>(p.ray.direction.x);
    r.dir_y = static_cast<float>(p.ray.direction.y);
    r.dir_z = static_cast<float>(p.ray.direction.z);
    r.tnear = 0.0f;
    r.tfar = std::isinf(p.nearest) ? std::numeric_limits<float>::infinity()
                                   : render::floatAtOrAbove(p.nearest);
    r.time = 0.0f;
    r.mask = 0xFFFFFFFF;
    r.id = id;
    r.flags = 0;
    h.geomID = RTC_INVALID_GEOMETRY_ID;
    h.instID[0] = RTC_INVALID_GEOMETRY_ID;
  }
  void collect(unsigned geomID, unsigned primID, const Pixel& p, std::int32_t& id) const {
    id = geomID == RTC_INVALID_GEOMETRY_ID
             ? p.id
             : static_cast<std::int32_t>(scene_.sceneObject(geometry_.bounded[primID]));
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
  void collectN(const RayHitN& rh, int n, const Pixel* pixels, std::int32_t* ids, int) const {
    for (int k = 0; k < n; ++k) collect(rh.hit.geomID[k], rh.hit.primID[k], pixels[k], ids[k]);
  }

  const render::RenderScene& scene_;
  render::RenderSettings settings_;
  render::PinholeCamera camera_;
  const Geometry& geometry_;
  RTCScene embree_;
  std::vector<std::uint32_t> planes_;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::size_t differences(const std::vector<std::int32_t>& a, const std::vector<std::int32_t>& b) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < a.size(); ++i) count += a[i] != b[i];
  return count;
}

int run(const std::string& path, render::RenderSettings settings, int runs,
        const std::vector<int>& threadCounts) {
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
  const std::vector<std::int32_t> reference = render::renderObjectIds(compiled, settings);
  const double pixels = static_cast<double>(settings.width) * settings.height;
  Tracers tracers(compiled, settings, geometry, embree.scene);

  std::printf("objects: %zu\n", compiled.objects().size());
  std::printf("rays: %.0f\n", pixels);
  std::printf("sfrender_build_s: %.6f\n", sfBuild);
  std::printf("embree_build_s: %.6f\n", embreeBuild);
  struct Row {
    std::string name;
    std::vector<double> mrays;
    std::size_t diff = 0;
  };
  std::vector<Row> table;
  const char* names[] = {"sfrender", "embree1", "embree4", "embree8"};
  const int packet[] = {0, 1, 4, 8};
  for (int v = 0; v < 4; ++v) {
    Row row{names[v], {}, 0};
    for (int threads : threadCounts) {
      std::vector<double> seconds;
      std::vector<std::int32_t> ids(reference.size(), -2);
      for (int r = 0; r < runs; ++r) {
        auto start = Clock::now();
        if (packet[v] == 0) {
          render::RenderSettings s = settings;
          s.threads = threads;
          ids = render::renderObjectIds(compiled, s);
        } else {
          tracers.traceAll(packet[v], threads, ids);
        }
        seconds.push_back(since(start));
      }
      row.diff = std::max(row.diff, differences(ids, reference));
      double mrays = pixels / median(seconds) / 1e6;
      row.mrays.push_back(mrays);
      std::printf("%s_%dt_mrays: %.4f\n", names[v], threads, mrays);
    }
    std::printf("%s_differences: %zu\n", names[v], row.diff);
    table.push_back(row);
  }

  std::printf("\n%-10s", "variant");
  for (int threads : threadCounts) std::printf(" | %2d thread(s), Mrays/s", threads);
  std::printf(" | ids differing\n");
  for (const Row& row : table) {
    std::printf("%-10s", row.name.c_str());
    for (double m : row.mrays) std::printf(" | %21.3f", m);
    std::printf(" | %zu\n", row.diff);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"sfrender's primary rays traced by Embree 3 (user geometry) and by sfrender"};
  render::RenderSettings settings;
  settings.width = 1920;
  settings.height = 1080;
  std::string input;
  int runs = 3;
  std::vector<int> threads{1, 2};
  app.add_option("scene", input, "scene file (any format sfrender reads)")->required();
  app.add_option("--width", settings.width, "image width")->check(CLI::Range(1, 1 << 15));
  app.add_option("--height", settings.height, "image height")->check(CLI::Range(1, 1 << 15));
  app.add_option("--runs", runs, "timed runs of each variant (median)")->check(CLI::Range(1, 100));
  app.add_option("--threads", threads, "thread counts to time")->check(CLI::Range(1, 256));
  CLI11_PARSE(app, argc, argv);
  return run(input, settings, runs, threads);
}
