#include "renderer/camera_trace.h"

#include <algorithm>

#include "renderer/parallel_parts.h"
#include "renderer/render_tiles.h"

namespace render {

namespace {

// The side of a cell of the eye's direction grid, in pixels, and where
// objects are dense.
constexpr int kEyeCellPixels = 4;
constexpr int kDenseEyeCellPixels = 2;
constexpr std::uint64_t kMaxEyeCells = std::uint64_t{1} << 22;

}  // namespace

CameraTrace::CameraTrace(const RenderScene& scene, const RenderSettings& settings)
    : scene_(scene), camera_(scene.camera(), settings) {
  if (settings.eyeGrid && settings.packets) buildEyeGrid(settings);
}

// The eye's direction grid, where it pays: for a render of at least 4
// samples a bounded object. Its build costs about a camera ray's search per
// object, and at 1,000,000 objects in 1080p (2 samples an object) it made
// the render slower, not faster.
void CameraTrace::buildEyeGrid(const RenderSettings& settings) {
  std::uint64_t objects = scene_.boundedObjects().size();
  if (objects < RenderScene::kMinEyeGridObjects || uniformSampleCount(settings) < 4 * objects) {
    return;
  }
  // Cells of 4 pixels a side, or of 2 where there is more than an object in
  // 64 pixels: about one listed object a ray either way (the floor scenes of
  // 1,000 and 100,000 objects at 1080p list 0.70 and 1.34; with cells of 4
  // the second lists 2.43).
  double pixelsPerObject =
      static_cast<double>(settings.width) * settings.height / static_cast<double>(objects);
  int cell = pixelsPerObject < 64.0 ? kDenseEyeCellPixels : kEyeCellPixels;
  // At most kMaxEyeCells cells (about 50 MB), whatever the image's size.
  auto cellsAcross = [&](int pixels, int side) {
    return static_cast<int>((static_cast<std::int64_t>(pixels) + side - 1) / side);
  };
  while (static_cast<std::uint64_t>(cellsAcross(settings.width, cell)) *
             static_cast<std::uint64_t>(cellsAcross(settings.height, cell)) >
         kMaxEyeCells) {
    cell *= 2;
  }
  GridWindow window =
      camera_.imageWindow(cellsAcross(settings.width, cell), cellsAcross(settings.height, cell));
  EyeGrid grid = scene_.eyeGrid(camera_.eye(), window);
  if (grid.grid.built()) eyeGrid_ = std::move(grid);
}

void CameraTrace::closestHits(const Ray* rays, int count, std::optional<Hit>* out) const {
  if (eyeGrid_) {
    scene_.closestHitsFromEye(*eyeGrid_, rays, count, out);
    return;
  }
  constexpr int kPacket = Bvh::kPacketSize;
  const RaySource fromCamera[kPacket] = {};
  for (int first = 0; first < count; first += kPacket) {
    scene_.closestHits(rays + first, fromCamera, std::min(kPacket, count - first), out + first);
  }
}

void traceCameraRays(const RenderScene& scene, const RenderSettings& settings,
                     const CameraRowCallback& onRow) {
  CameraTrace camera(scene, settings);
  int spp = std::max(1, settings.samplesPerPixel);
  forEachTile(PixelRegion{0, 0, settings.width, settings.height}, resolveThreads(settings.threads),
              [&](int, const PixelRegion& tile) {
                Ray rays[kRenderTileSize];
                std::optional<Hit> hits[kRenderTileSize];
                int n = tile.width();
                for (int j = tile.y0; j < tile.y1; ++j) {
                  for (int k = 0; k < n; ++k) {
                    camera.makeRay(samplePosition(tile.x0 + k, j, 0, spp, settings.seed), rays[k]);
                  }
                  camera.closestHits(rays, n, hits);
                  onRow(j, tile.x0, n, rays, hits);
                }
              },
              {});
}

}  // namespace render
