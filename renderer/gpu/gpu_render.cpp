#include "renderer/gpu/gpu_render.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>

#include "renderer/camera.h"
#include "renderer/device.h"
#include "renderer/gpu/gpu_scene.h"
#include "renderer/gpu/vulkan_context.h"
// Generated at build time (renderer/CMakeLists.txt): render_comp_spv[].
#include "renderer/gpu/render_comp_spv.h"

namespace render::gpu {

namespace {

constexpr int kBindings = 7;
constexpr std::uint32_t kGroupSize = 8;  // render.comp's local_size_x and _y

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The compute pipeline of render.comp and its one descriptor set.
class Pipeline {
 public:
  explicit Pipeline(const VulkanContext& context) : device_(context.device()) {
    try {
      create();
    } catch (...) {
      release();
      throw;
    }
  }
  ~Pipeline() { release(); }
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  // Points binding k at buffers[k].
  void bind(const std::array<VkBuffer, kBindings>& buffers) {
    std::array<VkDescriptorBufferInfo, kBindings> infos{};
    std::array<VkWriteDescriptorSet, kBindings> writes{};
    for (int k = 0; k < kBindings; ++k) {
      infos[k] = VkDescriptorBufferInfo{buffers[k], 0, VK_WHOLE_SIZE};
      writes[k].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
      writes[k].dstSet = set_;
      writes[k].dstBinding = static_cast<std::uint32_t>(k);
      writes[k].descriptorCount = 1;
      writes[k].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      writes[k].pBufferInfo = &infos[k];
    }
    vkUpdateDescriptorSets(device_, kBindings, writes.data(), 0, nullptr);
  }
  void record(VkCommandBuffer commands) const {
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set_, 0,
                            nullptr);
  }

 private:
  void create() {
    std::array<VkDescriptorSetLayoutBinding, kBindings> bindings{};
    for (int k = 0; k < kBindings; ++k) {
      bindings[k].binding = static_cast<std::uint32_t>(k);
      bindings[k].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      bindings[k].descriptorCount = 1;
      bindings[k].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    }
    VkDescriptorSetLayoutCreateInfo setInfo{};
    setInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    setInfo.bindingCount = kBindings;
    setInfo.pBindings = bindings.data();
    check(vkCreateDescriptorSetLayout(device_, &setInfo, nullptr, &setLayout_),
          "creating the descriptor set layout");
    VkPipelineLayoutCreateInfo layoutInfo{};
    layoutInfo.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &setLayout_;
    check(vkCreatePipelineLayout(device_, &layoutInfo, nullptr, &layout_),
          "creating the pipeline layout");
    VkShaderModuleCreateInfo moduleInfo{};
    moduleInfo.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    moduleInfo.codeSize = sizeof render_comp_spv;
    moduleInfo.pCode = render_comp_spv;
    check(vkCreateShaderModule(device_, &moduleInfo, nullptr, &module_),
          "creating the shader module");
    VkComputePipelineCreateInfo pipelineInfo{};
    pipelineInfo.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
    pipelineInfo.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipelineInfo.stage.module = module_;
    pipelineInfo.stage.pName = "main";
    pipelineInfo.layout = layout_;
    check(vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr, &pipeline_),
          "compiling the compute pipeline");
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kBindings};
    VkDescriptorPoolCreateInfo poolInfo{};
    poolInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &size;
    check(vkCreateDescriptorPool(device_, &poolInfo, nullptr, &pool_),
          "creating the descriptor pool");
    VkDescriptorSetAllocateInfo allocation{};
    allocation.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    allocation.descriptorPool = pool_;
    allocation.descriptorSetCount = 1;
    allocation.pSetLayouts = &setLayout_;
    check(vkAllocateDescriptorSets(device_, &allocation, &set_), "allocating the descriptor set");
  }
  void release() {
    if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);
    if (pipeline_) vkDestroyPipeline(device_, pipeline_, nullptr);
    if (module_) vkDestroyShaderModule(device_, module_, nullptr);
    if (layout_) vkDestroyPipelineLayout(device_, layout_, nullptr);
    if (setLayout_) vkDestroyDescriptorSetLayout(device_, setLayout_, nullptr);
  }

  VkDevice device_;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkShaderModule module_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
};

// The region as renderImage cuts it (regionToRender).
GpuParams paramsFor(const RenderScene& scene, const RenderSettings& settings,
                    const PixelRegion& region, bool idsOnly) {
  PinholeCamera camera(scene.camera(), settings);
  GpuParams p{};
  for (int c = 0; c < 3; ++c) {
    p.eye[c] = camera.eye()[c];
    p.forward[c] = camera.forward()[c];
    p.up[c] = camera.up()[c];
    p.right[c] = camera.right()[c];
  }
  p.tanHalfWidth = camera.tanHalfWidth();
  p.tanHalfHeight = camera.tanHalfHeight();
  p.imageWidth = settings.width;
  p.imageHeight = settings.height;
  p.seed = settings.seed;
  p.regionX0 = region.x0;
  p.regionY0 = region.y0;
  p.regionWidth = region.width();
  p.regionHeight = region.height();
  p.samplesPerPixel = std::max(1, settings.samplesPerPixel);
  p.maxDepth = settings.maxDepth;
  p.planeCount = static_cast<std::int32_t>(scene.planeObjects().size());
  p.lightCount = static_cast<std::int32_t>(scene.lights().size());
  p.nodeCount = static_cast<std::int32_t>(scene.bvh().nodes().size());
  p.hasTransparency = scene.hasTransparency() ? 1 : 0;
  p.idsOnly = idsOnly ? 1 : 0;
  if (scene.hasTransparency()) {
    // The media the camera starts in, outermost first (PixelTracer); past
    // the shader's capacity the innermost are left out, as MediumStack::push
    // leaves them out past its own.
    for (std::uint32_t object : scene.mediaContaining(camera.eye())) {
      if (p.eyeMediaCount < kGpuMediaCapacity) p.eyeMedia[p.eyeMediaCount++] = object;
    }
  }
  return p;
}

// What one run of the kernel over a region gives back, per pixel.
struct KernelOutput {
  std::vector<float> colours;         // 4 a pixel: rgb, coverage
  std::vector<std::uint32_t> counts;  // 4 a pixel: secondary, shadow, cut, object
  double startSeconds = 0.0, uploadSeconds = 0.0, kernelSeconds = 0.0, readbackSeconds = 0.0;
  std::string device;
};

void barrier(VkCommandBuffer commands, VkPipelineStageFlags from, VkAccessFlags fromAccess,
             VkPipelineStageFlags to, VkAccessFlags toAccess) {
  VkMemoryBarrier b{};
  b.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  b.srcAccessMask = fromAccess;
  b.dstAccessMask = toAccess;
  vkCmdPipelineBarrier(commands, from, to, 0, 1, &b, 0, nullptr, 0, nullptr);
}

// Rows a dispatch draws: about 16 bands an image, whole work groups each.
int bandRows(int height) {
  int rows = (height + 15) / 16;
  rows = (rows + static_cast<int>(kGroupSize) - 1) / static_cast<int>(kGroupSize) *
         static_cast<int>(kGroupSize);
  return std::max(rows, static_cast<int>(kGroupSize));
}

// Draws one band of rows (p.rowBase on, `bandHeight` rows of `width`) and
// waits for it; gives the kernel's time, by the timestamp `queries` where
// the device has them (not null), else by the clock.
double dispatchBand(const VulkanContext& context, const Pipeline& pipeline, const Buffer& params,
                    const GpuParams& p, int width, int bandHeight, VkQueryPool queries) {
  const bool timed = queries != VK_NULL_HANDLE;
  VkCommandBuffer commands = context.beginCommands();
  vkCmdUpdateBuffer(commands, params.buffer, 0, sizeof p, &p);
  barrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
          VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
  if (timed) {
    vkCmdResetQueryPool(commands, queries, 0, 2);
    vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, queries, 0);
  }
  pipeline.record(commands);
  vkCmdDispatch(commands, (static_cast<std::uint32_t>(width) + kGroupSize - 1) / kGroupSize,
                (static_cast<std::uint32_t>(bandHeight) + kGroupSize - 1) / kGroupSize, 1);
  if (timed) vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries, 1);
  auto bandStart = std::chrono::steady_clock::now();
  context.submitAndWait(commands);
  if (!timed) return secondsSince(bandStart);
  std::uint64_t ticks[2] = {0, 0};
  check(vkGetQueryPoolResults(context.device(), queries, 0, 2, sizeof ticks, ticks,
                              sizeof(std::uint64_t),
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
        "reading the timestamps");
  return static_cast<double>(ticks[1] - ticks[0]) * context.timestampPeriod() * 1e-9;
}

// The kernel's colours and counts of `pixels` pixels (`outputBytes` each),
// copied through the host-visible `readback`, one after the other, into
// `out`.
void readBack(const VulkanContext& context, const Buffer& colours, const Buffer& counts,
              const Buffer& readback, VkDeviceSize outputBytes, std::size_t pixels,
              KernelOutput& out) {
  VkCommandBuffer commands = context.beginCommands();
  barrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
          VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
  VkBufferCopy first{0, 0, outputBytes};
  VkBufferCopy second{0, outputBytes, outputBytes};
  vkCmdCopyBuffer(commands, colours.buffer, readback.buffer, 1, &first);
  vkCmdCopyBuffer(commands, counts.buffer, readback.buffer, 1, &second);
  barrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
          VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
  context.submitAndWait(commands);
  void* mapped = nullptr;
  check(vkMapMemory(context.device(), readback.memory, 0, readback.size, 0, &mapped),
        "mapping the readback buffer");
  out.colours.resize(pixels * 4);
  out.counts.resize(pixels * 4);
  std::memcpy(out.colours.data(), mapped, pixels * 16);
  std::memcpy(out.counts.data(), static_cast<char*>(mapped) + outputBytes, pixels * 16);
  vkUnmapMemory(context.device(), readback.memory);
}

// Runs render.comp over `region` of the image in bands; the device's
// resources are freed on every path out.
KernelOutput runKernel(const RenderScene& scene, const RenderSettings& settings,
                       const PixelRegion& region, bool idsOnly, const ProgressCallback& progress,
                       const CancelFlag* cancel) {
  KernelOutput out;
  auto start = std::chrono::steady_clock::now();
  // The caller's device where it keeps one open, else one for this render.
  std::optional<VulkanContext> own;
  const VulkanContext& context = settings.gpu ? settings.gpu->vulkan() : own.emplace();
  Pipeline pipeline(context);
  out.device = context.name();
  out.startSeconds = secondsSince(start);

  auto uploadStart = std::chrono::steady_clock::now();
  GpuScene gpuScene = uploadScene(context, scene, settings.threads);
  out.uploadSeconds = secondsSince(uploadStart);

  const std::size_t pixels = static_cast<std::size_t>(region.width()) * region.height();
  const VkDeviceSize outputBytes = std::max<VkDeviceSize>(16, pixels * 16);
  const VkMemoryPropertyFlags local = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  const VkMemoryPropertyFlags host =
      VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  Buffer params, colours, counts, readback;
  VkQueryPool queries = VK_NULL_HANDLE;
  auto release = [&] {
    if (queries) vkDestroyQueryPool(context.device(), queries, nullptr);
    for (Buffer* b : {&params, &colours, &counts, &readback}) context.destroy(*b);
    destroyScene(context, gpuScene);
  };
  try {
    params =
        context.createBuffer(sizeof(GpuParams), storage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, local);
    colours = context.createBuffer(outputBytes, storage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, local);
    counts = context.createBuffer(outputBytes, storage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, local);
    readback = context.createBuffer(2 * outputBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, host,
                                    VK_MEMORY_PROPERTY_HOST_CACHED_BIT);
    pipeline.bind({params.buffer, gpuScene.objects.buffer, gpuScene.nodes.buffer,
                   gpuScene.planes.buffer, gpuScene.lights.buffer, colours.buffer, counts.buffer});
    bool timed = context.timestampPeriod() > 0.0;
    if (timed) {
      VkQueryPoolCreateInfo queryInfo{};
      queryInfo.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
      queryInfo.queryType = VK_QUERY_TYPE_TIMESTAMP;
      queryInfo.queryCount = 2;
      check(vkCreateQueryPool(context.device(), &queryInfo, nullptr, &queries),
            "creating the timestamp queries");
    }

    GpuParams p = paramsFor(scene, settings, region, idsOnly);
    int rows = bandRows(region.height());
    int bands = region.height() == 0 ? 0 : (region.height() + rows - 1) / rows;
    for (int band = 0; band < bands; ++band) {
      if (cancel && cancel->requested()) throw RenderCancelled();
      p.rowBase = band * rows;
      int bandHeight = std::min(rows, region.height() - p.rowBase);
      out.kernelSeconds +=
          dispatchBand(context, pipeline, params, p, region.width(), bandHeight, queries);
      if (progress) progress(band + 1, bands);
    }

    auto readStart = std::chrono::steady_clock::now();
    readBack(context, colours, counts, readback, outputBytes, pixels, out);
    out.readbackSeconds = secondsSince(readStart);
  } catch (...) {
    release();
    throw;
  }
  release();
  return out;
}

Image renderImageVulkan(const RenderScene& scene, const RenderSettings& settings,
                        RenderStatistics* statistics, const ProgressCallback& progress,
                        const CancelFlag* cancel) {
  auto start = std::chrono::steady_clock::now();
  PixelRegion region = regionToRender(settings);
  Image image = blankImageFor(settings);
  std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  KernelOutput out = runKernel(scene, settings, region, false, progress, cancel);
  RayCounts rays;
  for (std::size_t k = 0; k < pixels; ++k) {
    for (std::size_t c = 0; c < 3; ++c) image.rgb[3 * k + c] = out.colours[4 * k + c];
    if (settings.coverage) image.coverage[k] = out.colours[4 * k + 3];
    rays.secondary += out.counts[4 * k];
    rays.shadow += out.counts[4 * k + 1];
    rays.cut += out.counts[4 * k + 2];
  }
  if (statistics) {
    std::uint64_t spp = static_cast<std::uint64_t>(std::max(1, settings.samplesPerPixel));
    *statistics = RenderStatistics{};
    rays.primary = pixels * spp;
    statistics->rays = rays;
    statistics->pixels = pixels;
    statistics->samples = pixels * spp;
    statistics->device = out.device;
    statistics->deviceStartSeconds = out.startSeconds;
    statistics->uploadSeconds = out.uploadSeconds;
    statistics->kernelSeconds = out.kernelSeconds;
    statistics->readbackSeconds = out.readbackSeconds;
    statistics->seconds = secondsSince(start);
  }
  return image;
}

std::vector<std::int32_t> renderObjectIdsVulkan(const RenderScene& scene,
                                                const RenderSettings& settings) {
  PixelRegion full{0, 0, std::max(0, settings.width), std::max(0, settings.height)};
  KernelOutput out = runKernel(scene, settings, full, true, {}, nullptr);
  std::vector<std::int32_t> ids(static_cast<std::size_t>(full.width()) * full.height());
  // The kernel numbers objects as the scene's records do; kNone is -1.
  for (std::size_t k = 0; k < ids.size(); ++k) {
    std::uint32_t object = out.counts[4 * k + 3];
    ids[k] = object == RaySource::kNone ? -1 : static_cast<std::int32_t>(scene.sceneObject(object));
  }
  return ids;
}

}  // namespace

// What fails in Vulkan (a device lost, memory short) is to the caller the
// device's being unavailable, as a missing device is.
Image renderImageGpu(const RenderScene& scene, const RenderSettings& settings,
                     RenderStatistics* statistics, const ProgressCallback& progress,
                     const CancelFlag* cancel) {
  try {
    return renderImageVulkan(scene, settings, statistics, progress, cancel);
  } catch (const VulkanError& e) {
    throw DeviceUnavailable(e.what());
  }
}

std::vector<std::int32_t> renderObjectIdsGpu(const RenderScene& scene,
                                             const RenderSettings& settings) {
  try {
    return renderObjectIdsVulkan(scene, settings);
  } catch (const VulkanError& e) {
    throw DeviceUnavailable(e.what());
  }
}

}  // namespace render::gpu
