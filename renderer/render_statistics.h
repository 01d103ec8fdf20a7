// What a render counted and timed: its rays, samples and retraces, and on
// the GPU the parts of its time.
#pragma once

#include <cstdint>
#include <string>

#include "renderer/tracer.h"

namespace render {

struct RenderStatistics {
  double seconds = 0.0;
  RayCounts rays;
  // Pixels traced again, with a 64th of the tolerance and then in full,
  // because what adaptive depth control left out could have moved their
  // 8-bit level (their primary rays count again).
  std::uint64_t retracedPixels = 0;
  // The pixels rendered, and the camera samples traced for them (retraces
  // aside; with adaptive sampling the pixel corners, (width + 1) x
  // (height + 1), and each lattice point a pixel traced, a point on the
  // side of two pixels of different tiles twice): samples / pixels is the
  // mean samples a pixel.
  std::uint64_t pixels = 0;
  std::uint64_t samples = 0;
  // Adaptive sampling: the pixels cut (whose corners differ), those of
  // them cut somewhere to the finest squares, and the pixels not cut that
  // took their centre too (whose corners differ by more than half the
  // threshold).
  std::uint64_t refinedPixels = 0;
  std::uint64_t fullySampledPixels = 0;
  std::uint64_t centredPixels = 0;
  // The GPU path's device (empty on the CPU), and the parts of `seconds`:
  // creating the device and compiling the pipeline, packing and uploading
  // the scene, the kernel (timestamp queries), and reading the image back.
  std::string device;
  double deviceStartSeconds = 0.0;
  double uploadSeconds = 0.0;
  double kernelSeconds = 0.0;
  double readbackSeconds = 0.0;
};

}  // namespace render
