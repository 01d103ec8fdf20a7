// render_probe: the measurements bench/render_suite.sh needs that sfrender
// does not print, taken with the same libraries sfrender uses.
//
//   render_probe time SCENE [--width W --height H --spp S --depth D --threads T
//                            --packets 0|1 --light-grids auto|0|1]
//       Reads SCENE (any format sfrender reads), then times apart, on one
//       process: parsing (scene::parseScene on the file in memory, on T
//       threads), building the render scene and its BVH
//       (render::RenderSceneBuilder, room for the objects reserved, then
//       the objects added in batches of 65,536 as a streaming reader hands
//       them over, then finish), and
//       rendering (render::renderImage). Prints "key: value" lines:
//       file_bytes, objects, parse_s, build_s (add_s + finish_s; finish_s's
//       stages finish_bvh_s, finish_order_s, finish_grids_s),
//       records_bytes_per_object, bvh_bytes_per_object,
//       grids_bytes_per_object (RenderScene::memory), build_peak_bytes_per_object
//       (the most the build held beyond what was held before it, from
//       VmHWM), render_s, primary_rays,
//       total_rays, ns_per_primary_ray (render wall time over primary rays,
//       times the threads: CPU time per ray), peak_rss_bytes, and rgb_fnv1a
//       (a hash of the image's floats, to see that two renders agree bit
//       for bit). --packets 0 finds camera rays' hits one by one
//       (RenderSettings::packets), for comparing the two; --light-grids 0 or
//       1 leaves out or builds the lights' direction grids, which auto
//       builds as sfrender does (RenderScene::lightGridsPay).
//   render_probe default-scene OUT.txt
//       Writes render::defaultScene() (the scene sfrender draws with no
//       input) as an instruction file, materials included.
//   render_probe compare A B
//       RMSE and PSNR of A against B (B the reference), through OpenImageIO's
//       ImageBufAlgo::compare, on the images' values in [0, 1]. Prints rmse,
//       psnr_db, max_error.
//   render_probe adaptive SCENE|default [--width W --height H --reference-spp R]
//       Adaptive anti-aliasing against uniform sampling, on one thread (so
//       that the time is CPU time): renders a reference at R samples a pixel,
//       then uniform 1, 4, 16 and 64 spp and adaptive sampling at several
//       thresholds and spp, and prints for each its CPU
//       seconds, mean samples a pixel and RMSE against the reference (values
//       clamped to [0, 1], as the image stores them). docs/RENDERING.md,
//       "Adaptive sampling", holds the figures.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <span>
#include <sstream>
#include <string>

#include "libscene/formats/instruction/instruction_writer.h"
#include "renderer/default_scene.h"
#include "renderer/render.h"
#include "renderer/render_scene.h"
#include "renderer/render_scene_builder.h"
#include "scenefile/read.h"

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// A kB field of /proc/self/status ("VmHWM:", "VmRSS:"), in bytes.
long statusBytes(const std::string& key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(key, 0) == 0) return std::stol(line.substr(key.size())) * 1024;
  }
  return 0;
}

long peakRssBytes() {
  return statusBytes("VmHWM:");
}

// Sets VmHWM to what is held now (Linux 4.0 on), so that the next reading
// is the peak from here.
void resetPeakRss() {
  std::ofstream("/proc/self/clear_refs") << "5";
}

// Builds the render scene as sfrender's streaming read does, and prints
// the build's times and memory by stage.
render::RenderScene buildInBatches(const scene::Scene& scene, int threads,
                                   const std::string& lightGrids, std::uint64_t samples,
                                   std::uint64_t imageSamples) {
  constexpr std::size_t kBatch = 65536;
  const double objects = std::max<double>(1.0, static_cast<double>(scene.objects.size()));
  resetPeakRss();
  const long before = statusBytes("VmRSS:");
  auto t0 = Clock::now();
  render::RenderSceneBuilder builder(threads);
  // As a reader that knows the count (or a bound on it) tells the builder.
  builder.reserve(scene.objects.size());
  std::span<const scene::Object> all(scene.objects);
  for (std::size_t first = 0; first < all.size(); first += kBatch) {
    builder.add(all.subspan(first, std::min(kBatch, all.size() - first)));
  }
  const double add = since(t0);
  t0 = Clock::now();
  render::RenderScene compiled = std::move(builder).finish(
      scene,
      lightGrids == "auto" ? render::RenderScene::lightGridsPay(scene.objects.size(), samples)
                           : lightGrids == "1",
      imageSamples);
  const double finish = since(t0);
  const long peak = peakRssBytes();
  render::RenderSceneMemory memory = compiled.memory();
  std::printf("add_s: %.6f\n", add);
  std::printf("finish_s: %.6f\n", finish);
  std::printf("finish_bvh_s: %.6f\n", builder.stageSeconds().bvh);
  std::printf("finish_order_s: %.6f\n", builder.stageSeconds().order);
  std::printf("finish_grids_s: %.6f\n", builder.stageSeconds().grids);
  std::printf("build_s: %.6f\n", add + finish);
  std::printf("records_bytes_per_object: %.1f\n", memory.records / objects);
  std::printf("bvh_bytes_per_object: %.1f\n", memory.bvh / objects);
  std::printf("grids_bytes_per_object: %.1f\n", memory.grids / objects);
  std::printf("build_peak_bytes_per_object: %.1f\n", (peak - before) / objects);
  return compiled;
}

int timeScene(const std::string& path, const render::RenderSettings& settings,
              const std::string& lightGrids) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::cerr << "render_probe: cannot read " << path << "\n";
    return 1;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  const std::size_t fileBytes = text.size();

  scene::ReadOptions read;
  read.threads = static_cast<unsigned>(std::max(0, settings.threads));
  // Any size: this measures, it does not guard.
  read.maxFileSize = UINT64_MAX;
  read.maxObjects = SIZE_MAX;
  auto t0 = Clock::now();
  scene::ReadResult result = scene::parseScene(text, path, read);
  const double parse = since(t0);
  if (!result.ok()) {
    std::cerr << "render_probe: " << path << " has errors\n";
    return 1;
  }
  std::string().swap(text);
  std::printf("objects: %zu\n", result.scene.objects.size());
  std::printf("parse_s: %.6f\n", parse);
  const render::RenderScene compiled =
      buildInBatches(result.scene, settings.threads, lightGrids,
                     render::uniformSampleCount(settings), render::fullImageSampleCount(settings));
  render::RenderStatistics stats;
  t0 = Clock::now();
  render::Image image = render::renderImage(compiled, settings, &stats);
  const double renderSeconds = since(t0);
  const auto total = stats.rays.primary + stats.rays.secondary + stats.rays.shadow;
  const int threads = settings.threads > 0 ? settings.threads : 1;
  std::printf("file_bytes: %zu\n", fileBytes);
  std::printf("render_s: %.6f\n", renderSeconds);
  std::printf("primary_rays: %llu\n", static_cast<unsigned long long>(stats.rays.primary));
  std::printf("total_rays: %llu\n", static_cast<unsigned long long>(total));
  std::printf("ns_per_primary_ray: %.3f\n",
              stats.rays.primary ? renderSeconds * threads * 1e9 / stats.rays.primary : 0.0);
  std::printf("peak_rss_bytes: %ld\n", peakRssBytes());
  std::uint64_t hash = 0xCBF29CE484222325ull;
  for (float v : image.rgb) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    for (int byte = 0; byte < 4; ++byte) {
      hash = (hash ^ ((bits >> (8 * byte)) & 0xFFu)) * 0x100000001B3ull;
    }
  }
  std::printf("rgb_fnv1a: %016llx\n", static_cast<unsigned long long>(hash));
  return image.rgb.empty() ? 1 : 0;
}

int writeDefault(const std::string& out) {
  scene::DiagnosticList diagnostics;
  scene::ConversionOptions options;
  options.instructions.approximate = true;
  auto text = scene::writeInstructionFile(render::defaultScene(), options, diagnostics);
  if (!text) {
    std::cerr << "render_probe: cannot write the default scene as an instruction file\n";
    return 1;
  }
  std::ofstream(out, std::ios::binary) << *text;
  return 0;
}

int compareImages(const std::string& a, const std::string& b) {
  OIIO::ImageBuf A(a), B(b);
  if (!A.read(0, 0, true, OIIO::TypeDesc::FLOAT) || !B.read(0, 0, true, OIIO::TypeDesc::FLOAT)) {
    std::cerr << "render_probe: cannot read " << a << " or " << b << "\n";
    return 1;
  }
  auto r = OIIO::ImageBufAlgo::compare(A, B, 1e30f, 1e30f);
  if (A.has_error() || B.has_error()) {
    std::cerr << "render_probe: compare failed\n";
    return 1;
  }
  // OIIO's PSNR is 20 log10(1 / rms) for values in [0, 1].
  std::printf("rmse: %.8f\n", r.rms_error);
  std::printf("psnr_db: %.4f\n", r.rms_error > 0 ? 20.0 * std::log10(1.0 / r.rms_error) : 99.0);
  std::printf("max_error: %.6f\n", r.maxerror);
  return 0;
}

// RMSE of two images' values clamped to [0, 1].
double clampedRmse(const render::Image& a, const render::Image& b) {
  double sum = 0.0;
  for (std::size_t k = 0; k < a.rgb.size(); ++k) {
    double d = std::clamp(a.rgb[k], 0.0f, 1.0f) - std::clamp(b.rgb[k], 0.0f, 1.0f);
    sum += d * d;
  }
  return a.rgb.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(a.rgb.size()));
}

int adaptiveSweep(const std::string& path, render::RenderSettings settings, int referenceSpp) {
  scene::Scene scene;
  if (path == "default") {
    scene = render::defaultScene();
  } else {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream buffer;
    buffer << in.rdbuf();
    scene::ReadResult result = scene::parseScene(buffer.str(), path);
    if (!in || !result.ok()) {
      std::cerr << "render_probe: cannot read " << path << "\n";
      return 1;
    }
    scene = std::move(result.scene);
  }
  render::RenderScene compiled(scene);
  settings.threads = 1;
  render::RenderSettings reference = settings;
  reference.samplesPerPixel = referenceSpp;
  reference.seed = 12345;  // samples apart from those measured
  render::Image truth = render::renderImage(compiled, reference);
  std::printf("%-9s %4s %6s %9s %9s %10s %9s\n", "mode", "spp", "thresh", "cpu_s", "samples",
              "rmse", "refined%");
  auto run = [&](int spp, double threshold) {
    render::RenderSettings s = settings;
    s.samplesPerPixel = spp;
    s.adaptiveThreshold = threshold;
    render::RenderStatistics stats;
    auto t0 = Clock::now();
    render::Image image = render::renderImage(compiled, s, &stats);
    double seconds = since(t0);
    std::printf("%-9s %4d %6.3f %9.3f %9.2f %10.6f %9.2f\n", threshold > 0 ? "adaptive" : "uniform",
                spp, threshold, seconds, static_cast<double>(stats.samples) / stats.pixels,
                clampedRmse(image, truth), 100.0 * stats.refinedPixels / stats.pixels);
    std::fflush(stdout);
  };
  for (int spp : {1, 4, 16, 64}) run(spp, 0.0);
  for (int spp : {16, 64}) {
    for (double threshold : {0.01, 0.03, 0.1, 0.3}) run(spp, threshold);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Render measurements for bench/render_suite.sh"};
  app.require_subcommand(1);
  render::RenderSettings settings;
  std::string input, output, a, b;
  auto* timeCmd = app.add_subcommand("time", "parse, build and render times of a scene");
  timeCmd->add_option("scene", input)->required();
  timeCmd->add_option("--width", settings.width);
  timeCmd->add_option("--height", settings.height);
  timeCmd->add_option("--spp", settings.samplesPerPixel);
  timeCmd->add_option("--depth", settings.maxDepth);
  timeCmd->add_option("--threads", settings.threads);
  timeCmd->add_option("--packets", settings.packets);
  std::string lightGrids = "auto";
  timeCmd->add_option("--light-grids", lightGrids)->check(CLI::IsMember({"auto", "0", "1"}));
  auto* defaultCmd = app.add_subcommand("default-scene", "write the default scene");
  defaultCmd->add_option("output", output)->required();
  auto* compareCmd = app.add_subcommand("compare", "RMSE and PSNR of A against B");
  compareCmd->add_option("a", a)->required();
  compareCmd->add_option("b", b)->required();
  int referenceSpp = 256;
  auto* adaptiveCmd = app.add_subcommand("adaptive", "adaptive against uniform sampling");
  adaptiveCmd->add_option("scene", input)->required();
  adaptiveCmd->add_option("--width", settings.width);
  adaptiveCmd->add_option("--height", settings.height);
  adaptiveCmd->add_option("--reference-spp", referenceSpp);
  CLI11_PARSE(app, argc, argv);
  if (*adaptiveCmd) return adaptiveSweep(input, settings, referenceSpp);
  if (*timeCmd) return timeScene(input, settings, lightGrids);
  if (*defaultCmd) return writeDefault(output);
  return compareImages(a, b);
}
