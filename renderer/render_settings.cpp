#include "renderer/render_settings.h"

#include <algorithm>
#include <cstddef>

#include "renderer/huge_pages.h"

namespace render {

PixelRegion regionToRender(const RenderSettings& settings) {
  PixelRegion full{0, 0, std::max(0, settings.width), std::max(0, settings.height)};
  if (settings.region.empty()) return full;
  PixelRegion cut{std::max(settings.region.x0, 0), std::max(settings.region.y0, 0),
                  std::min(settings.region.x1, full.x1), std::min(settings.region.y1, full.y1)};
  return cut.empty() ? PixelRegion{} : cut;
}

bool samplesAdaptively(const RenderSettings& settings) {
  return settings.adaptiveThreshold > 0.0 && settings.samplesPerPixel > 1;
}

std::uint64_t uniformSampleCount(const RenderSettings& settings) {
  PixelRegion region = regionToRender(settings);
  return static_cast<std::uint64_t>(region.width()) * static_cast<std::uint64_t>(region.height()) *
         static_cast<std::uint64_t>(std::max(1, settings.samplesPerPixel));
}

std::uint64_t fullImageSampleCount(const RenderSettings& settings) {
  return static_cast<std::uint64_t>(std::max(0, settings.width)) *
         static_cast<std::uint64_t>(std::max(0, settings.height)) *
         static_cast<std::uint64_t>(std::max(1, settings.samplesPerPixel));
}

Image blankImageFor(const RenderSettings& settings) {
  PixelRegion region = regionToRender(settings);
  Image image;
  image.width = region.width();
  image.height = region.height();
  image.originX = region.x0;
  image.originY = region.y0;
  image.fullWidth = std::max(0, settings.width);
  image.fullHeight = std::max(0, settings.height);
  std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  // Advised before it is first written: the whole huge pages within it
  // fault in 2 MiB at a time. Faulted in 4 KiB at a time, its 11 MB at
  // 1280x720 were a tenth of the CPU time of the default scene at
  // --adaptive 0.15 (docs/PERFORMANCE.md, "Equal error").
  image.rgb.reserve(pixels * Image::kChannels);
  adviseHugePages(image.rgb.data(), image.rgb.data() + image.rgb.capacity());
  image.rgb.assign(pixels * Image::kChannels, 0.0f);
  if (settings.coverage) image.coverage.assign(pixels, 0.0f);
  return image;
}

}  // namespace render
