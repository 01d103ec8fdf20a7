// float_trace: the single-precision experiment of docs/PERFORMANCE.md
// ("Single precision"): primary and shadow rays with direct Phong lighting,
// traced by the double renderer and by bench/float_tracer.h's float tracer
// (its shadow rays moved off the surface by a fixed 1e-4 or by a float error
// bound), on one thread.
//
//   float_trace scene SCENE [--width W --height H --runs R]
//       Times one pass over every pixel centre of each tracer (median of R,
//       alternating), and prints per tracer: ns per primary ray (with its
//       shadow rays), ns per ray, object ids that differ from
//       render::renderObjectIds, the lit points whose shadow ray meets their
//       own object, and the RMSE of the direct-lit image against the double
//       one (channels clamped to [0, 1], as an image stores them).
//   float_trace scene SCENE --only TRACER [--width W --height H]
//       One pass of one tracer (double, float_fixed or float_bound) and
//       nothing else, for an instruction count under callgrind.
//   float_trace hard
//       The same, untimed, on the hard scenes: the acne scene of
//       docs/ACCURACY.md at each of its layouts (1e-6 to 1e6, and moved 1e6
//       from the origin) and a grazing scene, at 160x120; with acne counted
//       by the accuracy tests' own judge (acne::evaluate: pixels that must be
//       lit drawn at ambient level, pixels that must be dark drawn lit).
//
// Prints "key: value" lines, keys prefixed by the tracer (double,
// float_fixed, float_bound); `hard` starts each scene with "scene: LABEL".
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <optional>
#include <string>
#include <vector>

#include "bench/float_tracer.h"
#include "bench/scene_loading.h"
#include "renderer/camera.h"
#include "renderer/render.h"
#include "renderer/render_scene.h"
#include "renderer/tracer.h"
#include "scenefile/transform.h"
#include "tests/geometry/acne_scene.h"

namespace {

using Clock = std::chrono::steady_clock;

enum class Variant { Double, FloatFixed, FloatBound };
constexpr Variant kVariants[] = {Variant::Double, Variant::FloatFixed, Variant::FloatBound};
const char* name(Variant v) {
  return v == Variant::Double ? "double" : v == Variant::FloatFixed ? "float_fixed" : "float_bound";
}

// One pass of a tracer over the pixel centres.
struct Pass {
  std::vector<float> rgb;
  std::vector<std::int32_t> ids;
  std::uint64_t primary = 0, shadow = 0, litPoints = 0, selfShadowed = 0;
  double seconds = 0.0;
};

Pass traceDouble(const render::RenderScene& scene, const render::RenderSettings& settings) {
  Pass pass;
  const std::size_t pixels = static_cast<std::size_t>(settings.width) * settings.height;
  pass.rgb.assign(3 * pixels, 0.0f);
  pass.ids.assign(pixels, -1);
  render::PinholeCamera camera(scene.camera(), settings);
  render::Tracer tracer(scene, 0);
  render::TraceContext context;
  auto start = Clock::now();
  for (int j = 0; j < settings.height; ++j) {
    for (int i = 0; i < settings.width; ++i) {
      render::Ray ray = camera.rayThrough(i + 0.5, j + 0.5);
      std::size_t k = static_cast<std::size_t>(j) * settings.width + i;
      std::optional<render::Hit> hit = scene.closestHit(ray, render::RaySource{});
      if (!hit) continue;
      glm::dvec3 d = glm::normalize(ray.direction);
      glm::dvec3 n = glm::dot(hit->normal, d) > 0.0 ? -hit->normal : hit->normal;
      glm::dvec3 c = tracer.shadeSurface(*hit, n, -d, context);
      pass.ids[k] = static_cast<std::int32_t>(scene.sceneObject(hit->object));
      for (int ch = 0; ch < 3; ++ch) pass.rgb[3 * k + ch] = static_cast<float>(c[ch]);
    }
  }
  pass.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  pass.primary = pixels;
  pass.shadow = context.counts.shadow;
  return pass;
}

Pass traceFloat(const render::RenderScene& scene, const render::RenderSettings& settings,
                bench::ShadowOffset offset, bool measureSelf) {
  Pass pass;
  const std::size_t pixels = static_cast<std::size_t>(settings.width) * settings.height;
  pass.rgb.assign(3 * pixels, 0.0f);
  pass.ids.assign(pixels, -1);
  render::PinholeCamera camera(scene.camera(), settings);
  bench::FloatTracer tracer(scene, offset);
  bench::FloatCounts counts;
  std::vector<std::uint32_t> hints(scene.lights().size(), render::RaySource::kNone);
  auto start = Clock::now();
  for (int j = 0; j < settings.height; ++j) {
    for (int i = 0; i < settings.width; ++i) {
      // The camera's ray, rounded to float: a float tracer's camera.
      render::Ray ray = camera.rayThrough(i + 0.5, j + 0.5);
      bench::FloatRay r{glm::vec3(ray.origin), glm::vec3(ray.direction)};
      std::size_t k = static_cast<std::size_t>(j) * settings.width + i;
      bench::FloatHit hit;
      if (!tracer.closestHit(r, hit)) continue;
      glm::vec3 c = tracer.shade(hit, r, hints, counts, measureSelf);
      pass.ids[k] = static_cast<std::int32_t>(scene.sceneObject(hit.object));
      for (int ch = 0; ch < 3; ++ch) pass.rgb[3 * k + ch] = c[ch];
    }
  }
  pass.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  pass.primary = pixels;
  pass.shadow = counts.shadow;
  pass.litPoints = counts.litPoints;
  pass.selfShadowed = counts.selfShadowed;
  return pass;
}

Pass trace(Variant v, const render::RenderScene& scene, const render::RenderSettings& settings,
           bool measureSelf) {
  if (v == Variant::Double) return traceDouble(scene, settings);
  return traceFloat(
      scene, settings,
      v == Variant::FloatFixed ? bench::ShadowOffset::Fixed : bench::ShadowOffset::ErrorBound,
      measureSelf);
}

double rmse(const std::vector<float>& a, const std::vector<float>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    double d = std::clamp(a[i], 0.0f, 1.0f) - std::clamp(b[i], 0.0f, 1.0f);
    sum += d * d;
  }
  return a.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(a.size()));
}

std::size_t differences(const std::vector<std::int32_t>& a, const std::vector<std::int32_t>& b) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < a.size(); ++i) count += a[i] != b[i];
  return count;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The figures every scene gets, per tracer: ids against the exact
// reference, self-intersections of lit points, RMSE against the double
// image.
void printAccuracy(const std::string& key, const Pass& pass, const Pass& reference,
                   const std::vector<std::int32_t>& exactIds) {
  std::printf("%s_ids_differing: %zu\n", key.c_str(), differences(pass.ids, exactIds));
  std::printf("%s_pixels: %zu\n", key.c_str(), exactIds.size());
  std::printf("%s_lit_points: %llu\n", key.c_str(),
              static_cast<unsigned long long>(pass.litPoints));
  std::printf("%s_self_shadowed: %llu\n", key.c_str(),
              static_cast<unsigned long long>(pass.selfShadowed));
  std::printf("%s_rmse: %.8f\n", key.c_str(), rmse(pass.rgb, reference.rgb));
}

// One pass of one tracer and nothing else (no reference ids, no other
// tracer): what an instruction count (callgrind, toggled on the pass) sees.
int traceOnly(const std::string& path, render::RenderSettings settings, const std::string& only) {
  std::optional<scene::Scene> loaded = bench::loadScene(path, "float_trace");
  if (!loaded) return 1;
  render::RenderScene scene(*loaded);
  for (Variant v : kVariants) {
    if (only != name(v)) continue;
    Pass pass = trace(v, scene, settings, false);
    std::printf("%s_seconds: %.6f\n%s_rays: %llu\n", name(v), pass.seconds, name(v),
                static_cast<unsigned long long>(pass.primary + pass.shadow));
    return 0;
  }
  std::fprintf(stderr, "float_trace: error: no tracer %s\n", only.c_str());
  return 1;
}

int timeScene(const std::string& path, render::RenderSettings settings, int runs) {
  std::optional<scene::Scene> loaded = bench::loadScene(path, "float_trace");
  if (!loaded) return 1;
  render::RenderScene scene(*loaded);
  settings.threads = 1;
  const std::vector<std::int32_t> exactIds = render::renderObjectIds(scene, settings);
  std::vector<std::vector<double>> seconds(3);
  std::vector<Pass> last(3);
  for (int r = 0; r < runs; ++r) {
    // Alternating, and the order turned each round.
    for (int k = 0; k < 3; ++k) {
      int v = r % 2 ? 2 - k : k;
      last[v] = trace(kVariants[v], scene, settings, false);
      seconds[v].push_back(last[v].seconds);
    }
  }
  std::printf("objects: %zu\n", scene.objects().size());
  for (int v = 0; v < 3; ++v) {
    // The self-intersection count comes from one more, untimed pass.
    Pass counted = trace(kVariants[v], scene, settings, true);
    std::string key = name(kVariants[v]);
    double s = median(seconds[v]);
    std::printf("%s_seconds: %.6f\n", key.c_str(), s);
    std::printf("%s_ns_per_primary: %.2f\n", key.c_str(), s * 1e9 / last[v].primary);
    std::printf("%s_ns_per_ray: %.2f\n", key.c_str(),
                s * 1e9 / static_cast<double>(last[v].primary + last[v].shadow));
    std::printf("%s_shadow_rays: %llu\n", key.c_str(),
                static_cast<unsigned long long>(last[v].shadow));
    printAccuracy(key, counted, last[0], exactIds);
  }
  return 0;
}

// The grazing scene of tests/geometry/geometry_test.cpp (0.01 above a long
// box and a long cylinder lying on the plane, looking along them), lit from
// low behind the camera, so that the light too grazes the plane and the
// box's top.
scene::Scene grazingScene() {
  auto object = [](scene::ObjectKind kind, const glm::dmat4& m, const glm::dvec3& colour) {
    scene::Object o;
    o.kind = kind;
    o.matrix = m;
    o.material.colour = colour;
    o.material.specular = 0.0;
    return o;
  };
  const glm::dmat4 identity(1.0);
  scene::Scene s;
  s.camera.matrix = scene::cameraFromLookAt({0.2, 2.01, 3}, {0.2, 1.8, -20});
  scene::Light light;
  light.matrix[3] = glm::dvec4(-0.5, 3.0, 40.0, 1.0);
  s.lights.push_back(light);
  using K = scene::ObjectKind;
  s.objects.push_back(object(K::Plane, identity, {0.6, 0.6, 0.6}));
  s.objects.push_back(object(K::Cylinder,
                             glm::translate(identity, {-1.2, 1, -8}) *
                                 glm::rotate(identity, std::acos(-1.0) / 2, {1, 0, 0}) *
                                 glm::scale(identity, {1, 10, 1}),
                             {0.3, 0.3, 0.9}));
  s.objects.push_back(
      object(K::Cube, glm::translate(identity, {1.3, 1, -8}) * glm::scale(identity, {1, 1, 10}),
             {0.3, 0.9, 0.3}));
  s.objects.push_back(
      object(K::Sphere, glm::translate(identity, {0, 2, -40}) * glm::scale(identity, glm::dvec3(2)),
             {0.9, 0.3, 0.3}));
  return s;
}

void measureHard(const std::string& label, const scene::Scene& s, double size) {
  render::RenderSettings settings;
  settings.width = acne::kWidth;
  settings.height = acne::kHeight;
  settings.verticalFovDegrees = acne::kFovDegrees;
  settings.threads = 1;
  render::RenderScene scene(s);
  const std::vector<std::int32_t> exactIds = render::renderObjectIds(scene, settings);
  const std::vector<acne::PixelTruth> truth = acne::referencePixels(s, size);
  std::printf("scene: %s\n", label.c_str());
  Pass reference = trace(Variant::Double, scene, settings, true);
  for (Variant v : kVariants) {
    Pass pass = v == Variant::Double ? reference : trace(v, scene, settings, true);
    std::string key = name(v);
    printAccuracy(key, pass, reference, exactIds);
    acne::Counts c = acne::evaluate(truth, pass.rgb, 1e-5, 0.0);
    int lit = 0, dark = 0, shadowed = 0, leaks = 0;
    for (int p = 0; p < acne::kPrimitives; ++p) {
      lit += c.lit[p], dark += c.darkLit[p], shadowed += c.shadowed[p], leaks += c.leaks[p];
    }
    std::printf("%s_must_be_lit: %d\n%s_drawn_dark: %d\n", key.c_str(), lit, key.c_str(), dark);
    std::printf("%s_must_be_dark: %d\n%s_drawn_lit: %d\n", key.c_str(), shadowed, key.c_str(),
                leaks);
  }
}

int hardScenes() {
  for (const acne::Layout& layout : acne::layouts()) {
    measureHard("acne " + layout.label, acne::buildScene(layout), acne::sceneSize(layout));
  }
  measureHard("grazing", grazingScene(), 50.0);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Single-precision primary and shadow rays against the double renderer"};
  app.require_subcommand(1);
  render::RenderSettings settings;
  settings.width = 1920;
  settings.height = 1080;
  std::string input;
  int runs = 3;
  auto* sceneCmd = app.add_subcommand("scene", "time and compare on a scene file");
  sceneCmd->add_option("scene", input)->required();
  sceneCmd->add_option("--width", settings.width)->check(CLI::Range(1, 1 << 15));
  sceneCmd->add_option("--height", settings.height)->check(CLI::Range(1, 1 << 15));
  sceneCmd->add_option("--runs", runs)->check(CLI::Range(1, 100));
  std::string only;
  sceneCmd->add_option("--only", only, "one pass of one tracer: double, float_fixed, float_bound");
  auto* hardCmd = app.add_subcommand("hard", "accuracy and acne on the hard scenes");
  CLI11_PARSE(app, argc, argv);
  if (*hardCmd) return hardScenes();
  if (!only.empty()) return traceOnly(input, settings, only);
  return timeScene(input, settings, runs);
}
