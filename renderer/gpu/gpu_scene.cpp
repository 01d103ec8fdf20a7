#include "renderer/gpu/gpu_scene.h"

#include <cstring>

namespace render::gpu {

GpuSceneData packScene(const RenderScene& scene) {
  GpuSceneData data;
  const std::vector<RenderObject>& objects = scene.objects();
  data.objects.assign(objects.size() * kObjectDoubles, 0.0);
  for (std::size_t i = 0; i < objects.size(); ++i) {
    double* o = &data.objects[i * kObjectDoubles];
    const RenderObject& object = objects[i];
    const glm::dmat3& toWorld = scene.linearToWorld(static_cast<std::uint32_t>(i));
    for (int c = 0; c < 3; ++c) {
      for (int r = 0; r < 3; ++r) {
        o[3 * c + r] = object.toLocal[c][r];
        o[12 + 3 * c + r] = toWorld[c][r];
      }
      o[9 + c] = object.translation[c];
    }
    o[21] = static_cast<double>(static_cast<int>(object.kind));
    const scene::Material& m = scene.material(static_cast<std::uint32_t>(i));
    double material[10] = {m.colour.r, m.colour.g,  m.colour.b,     m.ambient,      m.diffuse,
                           m.specular, m.shininess, m.reflectivity, m.transparency, m.ri};
    std::memcpy(o + 22, material, sizeof material);
  }
  // The nodes as they are: the shader reads the same float planes and walks
  // the same depth-first order. The last word is rebuilt from the fields, so
  // that no padding byte reaches the device.
  static_assert(sizeof(BvhNode) == 32);
  const std::vector<BvhNode>& nodes = scene.bvh().nodes();
  data.nodes.resize(nodes.size() * 8);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    std::uint32_t* n = &data.nodes[i * 8];
    std::memcpy(n, nodes[i].planes, sizeof nodes[i].planes);
    n[6] = nodes[i].offset;
    n[7] = static_cast<std::uint32_t>(nodes[i].count) |
           (static_cast<std::uint32_t>(nodes[i].axis) << 16);
  }
  const std::vector<std::uint32_t>& items = scene.bvh().items();
  data.items.resize(items.size());
  for (std::size_t k = 0; k < items.size(); ++k) data.items[k] = scene.boundedObjects()[items[k]];
  data.planes = scene.planeObjects();
  for (const RenderLight& light : scene.lights()) {
    for (int c = 0; c < 3; ++c) data.lights.push_back(light.position[c]);
    for (int c = 0; c < 3; ++c) data.lights.push_back(light.colour[c]);
  }
  return data;
}

namespace {

template <typename T>
VkDeviceSize bytesOf(const std::vector<T>& v) {
  return static_cast<VkDeviceSize>(v.size() * sizeof(T));
}

}  // namespace

GpuScene uploadScene(const VulkanContext& context, const GpuSceneData& data) {
  const VkBufferUsageFlags usage =
      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  const VkMemoryPropertyFlags local = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  struct Part {
    Buffer* target;
    const void* bytes;
    VkDeviceSize size;
  };
  GpuScene scene;
  Part parts[] = {{&scene.objects, data.objects.data(), bytesOf(data.objects)},
                  {&scene.nodes, data.nodes.data(), bytesOf(data.nodes)},
                  {&scene.items, data.items.data(), bytesOf(data.items)},
                  {&scene.planes, data.planes.data(), bytesOf(data.planes)},
                  {&scene.lights, data.lights.data(), bytesOf(data.lights)}};
  VkDeviceSize total = 0;
  for (const Part& p : parts) total += p.size;
  Buffer staging;
  try {
    for (Part& p : parts) *p.target = context.createBuffer(p.size, usage, local);
    staging = context.createBuffer(
        total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    void* mapped = nullptr;
    check(vkMapMemory(context.device(), staging.memory, 0, staging.size, 0, &mapped),
          "mapping the staging buffer");
    VkDeviceSize at = 0;
    for (const Part& p : parts) {
      if (p.size > 0) std::memcpy(static_cast<char*>(mapped) + at, p.bytes, p.size);
      at += p.size;
    }
    vkUnmapMemory(context.device(), staging.memory);
    VkCommandBuffer commands = context.beginCommands();
    at = 0;
    for (const Part& p : parts) {
      if (p.size > 0) {
        VkBufferCopy copy{at, 0, p.size};
        vkCmdCopyBuffer(commands, staging.buffer, p.target->buffer, 1, &copy);
      }
      at += p.size;
    }
    context.submitAndWait(commands);
  } catch (...) {
    context.destroy(staging);
    destroyScene(context, scene);
    throw;
  }
  context.destroy(staging);
  scene.bytes = total;
  return scene;
}

void destroyScene(const VulkanContext& context, GpuScene& scene) {
  for (Buffer* b : {&scene.objects, &scene.nodes, &scene.items, &scene.planes, &scene.lights}) {
    context.destroy(*b);
  }
}

}  // namespace render::gpu
