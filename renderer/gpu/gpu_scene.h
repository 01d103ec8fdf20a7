// A RenderScene as the compute shader (renderer/gpu/render.comp) reads it:
// flat arrays in the shader's layouts, uploaded once into device-local
// buffers.
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/gpu/vulkan_context.h"
#include "renderer/render_scene.h"

namespace render::gpu {

// The shader's Params block, field for field (std430).
struct GpuParams {
  double eye[4];
  double forward[4];
  double up[4];
  double right[4];
  double tanHalfWidth;
  double tanHalfHeight;
  double imageWidth;
  double imageHeight;
  std::uint64_t seed;
  std::int32_t regionX0;
  std::int32_t regionY0;
  std::int32_t regionWidth;
  std::int32_t regionHeight;
  std::int32_t rowBase;
  std::int32_t samplesPerPixel;
  std::int32_t maxDepth;
  std::int32_t planeCount;
  std::int32_t lightCount;
  std::int32_t nodeCount;
  std::int32_t hasTransparency;
  std::int32_t eyeMediaCount;
  std::int32_t idsOnly;
  std::int32_t pad0;
  std::uint32_t eyeMedia[8];
};
static_assert(sizeof(GpuParams) == 256, "GpuParams must match render.comp's Params");

// The shader's media stack holds this many solids (the CPU's, 64); a ray
// inside more nested solids keeps the outermost ones, as the CPU's stack
// does past its own capacity.
inline constexpr int kGpuMediaCapacity = 8;
// Doubles an object in the objects buffer (the shader's kObjectDoubles).
inline constexpr int kObjectDoubles = 32;

// Where each array of the scene lies in one host buffer, in the shader's
// layouts: the objects (kObjectDoubles each), the lights (position,
// colour), the BVH nodes (BvhNode's 32 bytes as 8 words; a leaf's item k is
// the object planeCount + k), the plane objects; each aligned for its type
// where the buffer is aligned to 8 bytes.
struct GpuSceneLayout {
  struct Part {
    VkDeviceSize offset = 0;
    VkDeviceSize bytes = 0;
  };
  Part objects, nodes, planes, lights;
  VkDeviceSize bytes = 0;
};
GpuSceneLayout layoutOf(const RenderScene& scene);

// The scene's buffers on the device.
struct GpuScene {
  Buffer objects, nodes, planes, lights;
  std::uint64_t bytes = 0;
};

// Packs the scene into one staging buffer and copies it into device-local
// buffers.
GpuScene uploadScene(const VulkanContext& context, const RenderScene& scene, int threads);
void destroyScene(const VulkanContext& context, GpuScene& scene);

}  // namespace render::gpu
