#include "renderer/gpu/gpu_scene.h"

#include <algorithm>
#include <cstring>
#include <span>

#include "renderer/parallel_parts.h"

namespace render::gpu {

namespace {

// The shader's number for `kind` (render.comp: kPlane, kSphere, kCylinder,
// kCube). A switch with no default, so that a kind added to
// scenefile/object_kinds.def does not compile here until the shader has it.
double shaderKind(scene::ObjectKind kind) {
  switch (kind) {
    case scene::ObjectKind::Plane:
      return 0.0;
    case scene::ObjectKind::Sphere:
      return 1.0;
    case scene::ObjectKind::Cylinder:
      return 2.0;
    case scene::ObjectKind::Cube:
      return 3.0;
  }
  return -1.0;
}

// Object i in the shader's layout: toLocal, translation, toWorld (column
// by column), the kind, then the material.
void packObject(const RenderScene& scene, std::size_t i, double* o) {
  const RenderObject& object = scene.objects()[i];
  const glm::dmat3& toWorld = scene.linearToWorld(static_cast<std::uint32_t>(i));
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) {
      o[3 * c + r] = object.toLocal[c][r];
      o[12 + 3 * c + r] = toWorld[c][r];
    }
    o[9 + c] = object.translation[c];
  }
  o[21] = shaderKind(object.kind);
  const scene::Material& m = scene.material(static_cast<std::uint32_t>(i));
  double material[kObjectDoubles - 22] = {m.colour.r,     m.colour.g, m.colour.b,  m.ambient,
                                          m.diffuse,      m.specular, m.shininess, m.reflectivity,
                                          m.transparency, m.ri};
  std::memcpy(o + 22, material, sizeof material);
}

// The nodes as they are: the shader reads the same float planes and walks
// the same depth-first order. The last word is rebuilt from the fields, so
// that no padding byte reaches the device.
void packNode(const BvhNode& node, std::uint32_t* n) {
  static_assert(sizeof(BvhNode) == 32);
  std::memcpy(n, node.planes, sizeof node.planes);
  n[6] = node.offset;
  n[7] = static_cast<std::uint32_t>(node.count) | (static_cast<std::uint32_t>(node.axis) << 16);
}

// Objects a part of the packing takes on: enough that a thread's start is
// paid back, few enough that the parts spread over the threads.
constexpr std::size_t kObjectsPerPart = 1 << 15;

// Writes the scene into `out` (layout.bytes of it) as `layout` places it,
// the objects on `threads` threads (0: every core).
void packScene(const RenderScene& scene, const GpuSceneLayout& layout, char* out, int threads) {
  // The objects, most of the bytes (256 each), on the render's threads.
  auto* objects = reinterpret_cast<double*>(out + layout.objects.offset);
  std::size_t count = scene.objects().size();
  runParts((count + kObjectsPerPart - 1) / kObjectsPerPart, resolveThreads(threads),
           [&](std::size_t part) {
             std::size_t end = std::min(count, (part + 1) * kObjectsPerPart);
             for (std::size_t i = part * kObjectsPerPart; i < end; ++i) {
               packObject(scene, i, objects + i * kObjectDoubles);
             }
           });
  auto* nodes = reinterpret_cast<std::uint32_t*>(out + layout.nodes.offset);
  std::span<const BvhNode> bvhNodes = scene.bvh().nodes();
  for (std::size_t i = 0; i < bvhNodes.size(); ++i) packNode(bvhNodes[i], nodes + i * 8);
  const std::vector<std::uint32_t>& planes = scene.planeObjects();
  if (!planes.empty()) {
    std::memcpy(out + layout.planes.offset, planes.data(), planes.size() * sizeof planes[0]);
  }
  auto* lights = reinterpret_cast<double*>(out + layout.lights.offset);
  for (const RenderLight& light : scene.lights()) {
    for (int c = 0; c < 3; ++c) *lights++ = light.position[c];
    for (int c = 0; c < 3; ++c) *lights++ = light.colour[c];
  }
}

}  // namespace

GpuSceneLayout layoutOf(const RenderScene& scene) {
  GpuSceneLayout layout;
  VkDeviceSize at = 0;
  auto place = [&](GpuSceneLayout::Part& part, VkDeviceSize bytes) {
    part = GpuSceneLayout::Part{at, bytes};
    at += bytes;
  };
  // The arrays of doubles first, so that each array starts aligned for its
  // type when the buffer does.
  place(layout.objects, scene.objects().size() * kObjectDoubles * sizeof(double));
  place(layout.lights, scene.lights().size() * 6 * sizeof(double));
  place(layout.nodes, scene.bvh().nodes().size() * 8 * sizeof(std::uint32_t));
  place(layout.planes, scene.planeObjects().size() * sizeof(std::uint32_t));
  layout.bytes = at;
  return layout;
}

GpuScene uploadScene(const VulkanContext& context, const RenderScene& source, int threads) {
  const VkBufferUsageFlags usage =
      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  const VkMemoryPropertyFlags local = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  GpuSceneLayout layout = layoutOf(source);
  GpuScene scene;
  struct Part {
    Buffer* target;
    GpuSceneLayout::Part place;
  };
  Part parts[] = {{&scene.objects, layout.objects},
                  {&scene.nodes, layout.nodes},
                  {&scene.planes, layout.planes},
                  {&scene.lights, layout.lights}};
  Buffer staging;
  try {
    for (Part& p : parts) *p.target = context.createBuffer(p.place.bytes, usage, local);
    staging = context.createBuffer(
        layout.bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    void* mapped = nullptr;
    check(vkMapMemory(context.device(), staging.memory, 0, staging.size, 0, &mapped),
          "mapping the staging buffer");
    // Packed where the copy reads it: no second copy of the scene on the
    // host (256 MB at 1,000,000 objects).
    packScene(source, layout, static_cast<char*>(mapped), threads);
    vkUnmapMemory(context.device(), staging.memory);
    VkCommandBuffer commands = context.beginCommands();
    for (const Part& p : parts) {
      if (p.place.bytes > 0) {
        VkBufferCopy copy{p.place.offset, 0, p.place.bytes};
        vkCmdCopyBuffer(commands, staging.buffer, p.target->buffer, 1, &copy);
      }
    }
    context.submitAndWait(commands);
  } catch (...) {
    context.destroy(staging);
    destroyScene(context, scene);
    throw;
  }
  context.destroy(staging);
  scene.bytes = layout.bytes;
  return scene;
}

void destroyScene(const VulkanContext& context, GpuScene& scene) {
  for (Buffer* b : {&scene.objects, &scene.nodes, &scene.planes, &scene.lights}) {
    context.destroy(*b);
  }
}

}  // namespace render::gpu
