// What a render is asked for (RenderSettings), and what follows from it
// alone: the pixels it covers, whether it samples adaptively, how many
// samples a uniform one takes.
#pragma once

#include <cstdint>

#include "renderer/image.h"

namespace render {

class GpuDevice;

// Where renderImage traces (scenefile/render.h).
using RenderDevice = scene::RenderDevice;

// What a render is asked for: what a user chooses (scenefile/render.h's
// RenderSettings, the base) and what only this tree's programs set.
struct RenderSettings : scene::RenderSettings {
  // The most adaptive depth control may lower a channel of a sample (and so
  // of a pixel) by leaving out reflected and refracted rays: half a level of
  // an 8-bit image. A pixel whose level that could change is traced again
  // (RenderStatistics::retracedPixels), so every level is what full tracing
  // gives (docs/RENDERING.md,
  // "Cost"). 0 traces every branch to the depth limit.
  double pruneTolerance = 0.5 / 255.0;
  // The most reflected and refracted rays one sample traces, whatever the
  // scene: where every hit passes on nearly all it receives to both its
  // children, no tolerance bounds the work, and this does (docs/RENDERING.md,
  // "Cost"). 0: no limit, and then no pixel is retraced, so that an 8-bit
  // level can come out one below what full tracing gives.
  std::uint64_t maxRaysPerSample = 4096;
  // The largest level of the integer image the render will be stored in
  // (levelOf): what retracing keeps to the level of full tracing (255 for 8
  // bits, 65535 for 16, with pruneTolerance half of one of its levels).
  double levels = 255.0;
  // Whether camera rays find their hits as packets (RenderScene::closestHits,
  // docs/TRACING.md, "Packets"): the same image, bit for bit, either way;
  // false traces each alone, for the tests and benchmarks that compare.
  bool packets = true;
  // Whether camera rays find their hits through the eye's direction grid
  // (RenderScene::closestHitsFromEye, docs/TRACING.md, "Direction
  // grids") where it can answer: the same image, bit for bit, either way.
  bool eyeGrid = true;
  // Whether adaptive sampling takes a pixel corner between traced anchors
  // that agree as their mean instead of tracing it (CornerInterpolation,
  // docs/RENDERING.md, "Adaptive sampling"); false traces every corner, for
  // the tests and benchmarks that compare.
  bool interpolatesCorners = true;
  // Whether, with interpolatesCorners, an anchor between coarse anchors
  // (corners 4 apart) that agree is their mean too; false traces every
  // anchor, for the tests and benchmarks that compare.
  bool interpolatesAnchors = true;
  // The device GPU renders go through, kept open by the caller for as long
  // as renders use it; null: each GPU render opens a device of its own.
  // Auto with one given asks no probe: it takes it where it is a real GPU.
  const GpuDevice* gpu = nullptr;
};

/// The pixels of the full image that `settings` asks for: its region cut to
/// the image, or all of it.
PixelRegion regionToRender(const RenderSettings& settings);

/// Whether a render with `settings` samples adaptively (docs/RENDERING.md,
/// "Adaptive sampling"): a threshold above 0 and more than one sample a
/// pixel to refine to.
bool samplesAdaptively(const RenderSettings& settings);

/// The camera samples a uniform render with `settings` takes: the pixels
/// of regionToRender times samplesPerPixel (at least 1).
std::uint64_t uniformSampleCount(const RenderSettings& settings);

/// The camera samples a uniform render of the whole image with `settings`
/// takes, whatever its region: width times height times samplesPerPixel
/// (at least 1). What is chosen by it (the BVH's kind, Bvh::nodeCostFor)
/// is the same for every region, so that a region's pixels are the whole
/// image's.
std::uint64_t fullImageSampleCount(const RenderSettings& settings);

/// An image of the pixels `settings` asks for (regionToRender), every
/// value 0, with its place in the full image, and coverage when asked for:
/// what each device's render fills in.
Image blankImageFor(const RenderSettings& settings);

}  // namespace render
