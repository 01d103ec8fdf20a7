#include "renderer/gpu/vulkan_context.h"

#include <vector>

namespace render::gpu {

void check(VkResult result, const char* what) {
  if (result != VK_SUCCESS) {
    throw VulkanError(std::string(what) + " failed (VkResult " + std::to_string(result) + ")");
  }
}

namespace {

VkInstance createInstance() {
  VkApplicationInfo app{};
  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.pApplicationName = "sfrender";
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  info.pApplicationInfo = &app;
  VkInstance instance = VK_NULL_HANDLE;
  VkResult result = vkCreateInstance(&info, nullptr, &instance);
  if (result != VK_SUCCESS) {
    throw VulkanError("no Vulkan driver could be loaded (VkResult " + std::to_string(result) + ")");
  }
  return instance;
}

// A queue family with compute, or -1.
int computeFamily(VkPhysicalDevice device) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  for (std::uint32_t i = 0; i < count; ++i) {
    if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) return static_cast<int>(i);
  }
  return -1;
}

struct Choice {
  VkPhysicalDevice device = VK_NULL_HANDLE;
  int family = -1;
  bool isCpu = false;
  std::string name;
  std::string reason;
};

// The first device with doubles, 64-bit integers and compute: a GPU before
// a CPU implementation.
Choice chooseDevice(VkInstance instance, bool allowCpu) {
  std::uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  Choice best;
  best.reason = count == 0 ? "no Vulkan device is present" : "";
  for (VkPhysicalDevice device : devices) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(device, &properties);
    VkPhysicalDeviceFeatures features;
    vkGetPhysicalDeviceFeatures(device, &features);
    std::string name = properties.deviceName;
    bool isCpu = properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    int family = computeFamily(device);
    if (!features.shaderFloat64 || !features.shaderInt64 || family < 0) {
      if (best.reason.empty()) best.reason = name + " lacks shaderFloat64 or shaderInt64";
      continue;
    }
    if (isCpu && !allowCpu) {
      if (best.reason.empty()) best.reason = name + " is a CPU implementation";
      continue;
    }
    if (best.device == VK_NULL_HANDLE || (best.isCpu && !isCpu)) {
      best = Choice{device, family, isCpu, name, ""};
    }
  }
  return best;
}

}  // namespace

DeviceProbe VulkanContext::probe(bool allowCpu) {
  DeviceProbe result;
  VkInstance instance = VK_NULL_HANDLE;
  try {
    instance = createInstance();
  } catch (const VulkanError& e) {
    result.reason = e.what();
    return result;
  }
  Choice choice = chooseDevice(instance, allowCpu);
  vkDestroyInstance(instance, nullptr);
  result.found = choice.device != VK_NULL_HANDLE;
  result.isCpu = choice.isCpu;
  result.name = choice.name;
  result.reason = choice.reason;
  return result;
}

VulkanContext::VulkanContext(bool allowCpu) {
  instance_ = createInstance();
  try {
    Choice choice = chooseDevice(instance_, allowCpu);
    if (choice.device == VK_NULL_HANDLE) throw VulkanError(choice.reason);
    physical_ = choice.device;
    queueFamily_ = static_cast<std::uint32_t>(choice.family);
    name_ = choice.name;
    isCpu_ = choice.isCpu;

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{};
    queueInfo.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queueInfo.queueFamilyIndex = queueFamily_;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkPhysicalDeviceFeatures features{};
    features.shaderFloat64 = VK_TRUE;
    features.shaderInt64 = VK_TRUE;
    VkDeviceCreateInfo deviceInfo{};
    deviceInfo.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    deviceInfo.pEnabledFeatures = &features;
    check(vkCreateDevice(physical_, &deviceInfo, nullptr, &device_), "creating the device");
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);

    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(physical_, &properties);
    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical_, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(physical_, &count, families.data());
    if (families[queueFamily_].timestampValidBits > 0) {
      timestampPeriod_ = properties.limits.timestampPeriod;
    }

    VkCommandPoolCreateInfo poolInfo{};
    poolInfo.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    poolInfo.queueFamilyIndex = queueFamily_;
    check(vkCreateCommandPool(device_, &poolInfo, nullptr, &pool_), "creating a command pool");
    VkFenceCreateInfo fenceInfo{};
    fenceInfo.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    check(vkCreateFence(device_, &fenceInfo, nullptr, &fence_), "creating a fence");
  } catch (...) {
    if (pool_) vkDestroyCommandPool(device_, pool_, nullptr);
    if (device_) vkDestroyDevice(device_, nullptr);
    vkDestroyInstance(instance_, nullptr);
    throw;
  }
}

VulkanContext::~VulkanContext() {
  vkDeviceWaitIdle(device_);
  vkDestroyFence(device_, fence_, nullptr);
  vkDestroyCommandPool(device_, pool_, nullptr);
  vkDestroyDevice(device_, nullptr);
  vkDestroyInstance(instance_, nullptr);
}

std::uint32_t VulkanContext::memoryType(std::uint32_t allowed, VkMemoryPropertyFlags properties,
                                        VkMemoryPropertyFlags preferred) const {
  VkPhysicalDeviceMemoryProperties memory;
  vkGetPhysicalDeviceMemoryProperties(physical_, &memory);
  for (VkMemoryPropertyFlags wanted : {properties | preferred, properties}) {
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
      if ((allowed & (1u << i)) && (memory.memoryTypes[i].propertyFlags & wanted) == wanted) {
        return i;
      }
    }
  }
  throw VulkanError("no memory type fits a buffer");
}

Buffer VulkanContext::createBuffer(VkDeviceSize size, VkBufferUsageFlags usage,
                                   VkMemoryPropertyFlags properties,
                                   VkMemoryPropertyFlags preferred) const {
  Buffer b;
  b.size = size > 0 ? size : 16;
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = b.size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  check(vkCreateBuffer(device_, &info, nullptr, &b.buffer), "creating a buffer");
  VkMemoryRequirements requirements;
  vkGetBufferMemoryRequirements(device_, b.buffer, &requirements);
  VkMemoryAllocateInfo allocation{};
  allocation.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  allocation.allocationSize = requirements.size;
  try {
    allocation.memoryTypeIndex = memoryType(requirements.memoryTypeBits, properties, preferred);
    check(vkAllocateMemory(device_, &allocation, nullptr, &b.memory), "allocating device memory");
  } catch (...) {
    vkDestroyBuffer(device_, b.buffer, nullptr);
    throw;
  }
  vkBindBufferMemory(device_, b.buffer, b.memory, 0);
  return b;
}

void VulkanContext::destroy(Buffer& buffer) const {
  if (buffer.buffer) vkDestroyBuffer(device_, buffer.buffer, nullptr);
  if (buffer.memory) vkFreeMemory(device_, buffer.memory, nullptr);
  buffer = Buffer{};
}

VkCommandBuffer VulkanContext::beginCommands() const {
  VkCommandBufferAllocateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  info.commandPool = pool_;
  info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  info.commandBufferCount = 1;
  VkCommandBuffer commands = VK_NULL_HANDLE;
  check(vkAllocateCommandBuffers(device_, &info, &commands), "allocating a command buffer");
  VkCommandBufferBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkBeginCommandBuffer(commands, &begin);
  return commands;
}

void VulkanContext::submitAndWait(VkCommandBuffer commands) const {
  vkEndCommandBuffer(commands);
  VkSubmitInfo submit{};
  submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands;
  VkResult result = vkQueueSubmit(queue_, 1, &submit, fence_);
  if (result == VK_SUCCESS) result = vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX);
  vkResetFences(device_, 1, &fence_);
  vkFreeCommandBuffers(device_, pool_, 1, &commands);
  check(result, "running commands on the device");
}

}  // namespace render::gpu
