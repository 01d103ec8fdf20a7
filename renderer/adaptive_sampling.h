// Adaptive anti-aliasing's decisions (docs/RENDERING.md, "Adaptive
// sampling"): which pixels get more than their centre sample, and how many.
// Every decision reads samples that are functions of their own pixel's
// coordinates and the seed, so a pixel comes out the same whatever the
// threads, the tile order or the region rendered.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "renderer/render_scene.h"

namespace render {

// What one camera sample showed, as far as the decisions need it: its colour
// as an image shows it (each channel clamped to [0, 1]) and the object its
// ray met first (RaySource::kNone: the background).
struct SampleLook {
  glm::vec3 colour{0.0f};
  std::uint32_t object = RaySource::kNone;
};

// The look of a traced colour and the object its camera ray met.
SampleLook lookOf(const glm::dvec3& colour, std::uint32_t object);

// Whether two samples differ by more than `threshold` in some channel, or
// show different objects (an edge between two objects of one colour).
bool looksDiffer(const SampleLook& a, const SampleLook& b, double threshold);

// The range of a set of samples: whether any two of them differ as
// looksDiffer says, without keeping them all.
class SampleSpread {
 public:
  void add(const SampleLook& look);
  bool exceeds(double threshold) const;

 private:
  glm::vec3 low_{0.0f}, high_{0.0f};
  std::uint32_t object_ = RaySource::kNone;
  bool mixedObjects_ = false;
  bool empty_ = true;
};

// The sample counts a refined pixel goes through after its centre, the
// last one `samplesPerPixel`: `firstLevel` stratified samples first where it
// is above 1 and below samplesPerPixel, then all of them. Each level is a
// stratified set of its own (samplePosition with that count) and replaces
// the one before in the pixel's colour; the pixel stops at the first level
// whose samples agree. Empty for one sample a pixel: nothing to refine.
std::vector<int> refinementLevels(int samplesPerPixel, int firstLevel);

// The bytes adaptive sampling keeps beside the image of a region of
// `width` x `height` pixels: one centre sample's look for each pixel and its
// one-pixel apron. Saturates.
std::uint64_t adaptiveSamplingBytes(int width, int height);

}  // namespace render
