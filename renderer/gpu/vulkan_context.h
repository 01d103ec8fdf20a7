// A Vulkan device for compute in double precision: the instance, the first
// device with shaderFloat64 and shaderInt64 and a compute queue, and the
// buffers and one-off command buffers the GPU renderer needs. No window, no
// validation layers: nothing but what a headless compute job uses.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

namespace render::gpu {

// Any failure of a Vulkan call, with what was being done.
class VulkanError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What the probe found: whether a device fits, its name, whether it is a
// CPU implementation (lavapipe), or why none fits.
struct DeviceProbe {
  bool found = false;
  bool isCpu = false;
  std::string name;
  std::string reason;  // when not found
};

// A buffer and its memory, freed with the context's device.
struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize size = 0;
};

class VulkanContext {
 public:
  // The first device that fits, preferring a real GPU to a CPU
  // implementation; throws VulkanError when none does. With `allowCpu`
  // false a CPU implementation does not count.
  explicit VulkanContext(bool allowCpu = true);
  ~VulkanContext();
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  // Whether a device fits, without keeping it.
  static DeviceProbe probe(bool allowCpu = true);

  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  const std::string& name() const { return name_; }
  bool isCpu() const { return isCpu_; }
  // Nanoseconds a timestamp tick; 0 when the queue has no timestamps.
  double timestampPeriod() const { return timestampPeriod_; }

  // A buffer of `size` bytes (at least 1) for `usage`, in memory with
  // `properties` (device-local for the kernel's data, host-visible for
  // staging and readback), and with `preferred` too where a memory type
  // has both (host-cached for the readback, which the CPU reads whole:
  // reads of uncached, write-combined memory are not cached).
  Buffer createBuffer(VkDeviceSize size, VkBufferUsageFlags usage, VkMemoryPropertyFlags properties,
                      VkMemoryPropertyFlags preferred = 0) const;
  void destroy(Buffer& buffer) const;

  // A command buffer to record into, then submitted and waited for by
  // submitAndWait (which frees it).
  VkCommandBuffer beginCommands() const;
  void submitAndWait(VkCommandBuffer commands) const;

 private:
  std::uint32_t memoryType(std::uint32_t allowed, VkMemoryPropertyFlags properties,
                           VkMemoryPropertyFlags preferred) const;

  VkInstance instance_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  std::uint32_t queueFamily_ = 0;
  double timestampPeriod_ = 0.0;
  std::string name_;
  bool isCpu_ = false;
};

// Throws VulkanError naming `what` unless `result` is VK_SUCCESS.
void check(VkResult result, const char* what);

}  // namespace render::gpu
