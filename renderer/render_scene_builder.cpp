#include "renderer/render_scene_builder.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "renderer/huge_pages.h"
#include "renderer/parallel_parts.h"
#include "renderer/permute_in_place.h"

namespace render {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A material's properties but its colour, bit for bit.
std::array<std::uint64_t, 7> propertyBits(const scene::Material& m) {
  return {std::bit_cast<std::uint64_t>(m.ambient),
          std::bit_cast<std::uint64_t>(m.diffuse),
          std::bit_cast<std::uint64_t>(m.specular),
          std::bit_cast<std::uint64_t>(m.shininess),
          std::bit_cast<std::uint64_t>(m.reflectivity),
          std::bit_cast<std::uint64_t>(m.transparency),
          std::bit_cast<std::uint64_t>(m.ri)};
}

}  // namespace

// Here rather than in render_scene.cpp, which the builder's header would
// otherwise include back: a whole scene is one batch.
RenderScene::RenderScene(const scene::Scene& scene, int threads, bool lightGrids,
                         std::optional<std::uint64_t> imageSamples) {
  RenderSceneBuilder builder(threads);
  builder.reserve(scene.objects.size());
  builder.add(scene.objects);
  *this = std::move(builder).finish(scene, lightGrids, imageSamples);
}

RenderSceneBuilder::RenderSceneBuilder(int threads)
    : threads_(std::min(resolveThreads(threads), Bvh::kMaxBuildThreads)) {}

void RenderSceneBuilder::reserve(std::uint64_t objects) {
  objects = std::min(objects, kMaxObjects);
  objects_.reserve(objects);
  colours_.reserve(objects);
  adviseHugePages(objects_.data(), objects_.data() + objects_.capacity());
  adviseHugePages(colours_.data(), colours_.data() + colours_.capacity());
}

std::uint32_t RenderSceneBuilder::materialNumber(const scene::Material& material) {
  std::array<std::uint64_t, 7> bits = propertyBits(material);
  if (!materials_.empty() && propertyBits(materials_[lastMaterial_]) == bits) return lastMaterial_;
  auto [found, added] =
      materialNumbers_.try_emplace(bits, static_cast<std::uint32_t>(materials_.size()));
  if (added) {
    materials_.push_back(material);
    materials_.back().colour = glm::dvec3(0.0);
  }
  lastMaterial_ = found->second;
  return lastMaterial_;
}

void RenderSceneBuilder::add(std::span<const scene::Object> batch) {
  const std::size_t first = objects_.size();
  const std::size_t count = batch.size();
  if (count > kMaxObjects - first) {
    throw std::length_error("a scene holds at most 4294967294 objects");
  }
  if (count == 0) return;
  const std::size_t parts = count < RenderScene::kMinParallelObjects ? 1 : threads_;
  // The new records and colours are left unset (UnsetVector), to be written
  // once, on the threads, a part each.
  objects_.resize(first + count);
  colours_.resize(first + count);
  // Materials are numbered by their first use, in order, whatever the
  // threads: the first one here, then each part checks that its objects
  // share the last one found, which nearly every batch does. Where any
  // object does not, this thread numbers the batch afresh after the parts.
  if (materials_.empty()) materialNumber(batch[0].material);
  const std::uint32_t shared = lastMaterial_;
  const std::array<std::uint64_t, 7> sharedBits = propertyBits(materials_[shared]);
  std::vector<MaterialMaxima> maxima(parts);
  std::vector<std::uint8_t> transparent(parts, 0);
  std::vector<std::uint8_t> allShared(parts, 1);
  std::vector<std::uint32_t> planes(parts, 0);
  runParts(parts, threads_, [&](std::size_t part) {
    // Gathered here and stored once: the parts' entries share a cache line.
    MaterialMaxima gathered;
    bool anyTransparent = false;
    bool sharesMaterial = true;
    std::uint32_t planeCount = 0;
    const std::size_t begin = count * part / parts;
    const std::size_t end = count * (part + 1) / parts;
    for (std::size_t i = begin; i < end; ++i) {
      const scene::Object& o = batch[i];
      RenderObject& record = objects_[first + i];
      record = renderObject(o.kind, o.matrix);
      record.material = shared;
      sharesMaterial &= propertyBits(o.material) == sharedBits;
      planeCount += o.kind == scene::ObjectKind::Plane ? 1 : 0;
      colours_[first + i] = o.material.colour;
      anyTransparent |= o.material.transparency > 0.0;
      gathered.add(o.kind, o.material);
    }
    transparent[part] = anyTransparent ? 1 : 0;
    allShared[part] = sharesMaterial ? 1 : 0;
    planes[part] = planeCount;
    maxima[part] = gathered;
  });
  if (std::find(allShared.begin(), allShared.end(), 0) != allShared.end()) {
    for (std::size_t i = 0; i < count; ++i) {
      objects_[first + i].material = materialNumber(batch[i].material);
    }
  }
  for (std::uint32_t n : planes) planes_ += n;
  for (const MaterialMaxima& part : maxima) materialMaxima_.merge(part);
  hasTransparency_ |= std::find(transparent.begin(), transparent.end(), 1) != transparent.end();
}

void RenderSceneBuilder::permute(const std::vector<std::uint32_t>& order) {
  // In place: a copy in the new order would hold the records twice.
  const int threads = order.size() < RenderScene::kMinParallelObjects ? 1 : threads_;
  permuteInPlace(std::span<const std::uint32_t>(order), threads, std::span<RenderObject>(objects_),
                 std::span<glm::dvec3>(colours_));
}

RenderScene RenderSceneBuilder::finish(const scene::Scene& header, bool lightGrids,
                                       std::optional<std::uint64_t> imageSamples) && {
  const auto count = static_cast<std::uint32_t>(objects_.size());
  const std::uint32_t planeCount = planes_;
  const std::uint32_t boundedCount = count - planeCount;
  RenderScene scene;
  scene.camera_ = header.camera;
  // Step 1: the records' order: the planes first, in the order added, then
  // the bounded objects in the BVH's, where neighbours in space lie together
  // in memory (in a file's order, which may be random, the render of
  // 1,000,000 objects took a third longer). The BVH is built over their
  // boxes as it reads them, item k the k-th bounded object added.
  auto start = std::chrono::steady_clock::now();
  std::vector<std::uint32_t> order;
  allocateHere(order, count);
  order.resize(count);
  std::uint32_t plane = 0;
  std::uint32_t bounded = planeCount;
  for (std::uint32_t i = 0; i < count; ++i) {
    order[objects_[i].kind == scene::ObjectKind::Plane ? plane++ : bounded++] = i;
  }
  scene.bvh_ = Bvh(
      boundedCount,
      [&](std::uint32_t item) { return *worldBounds(objects_[order[planeCount + item]]); },
      threads_,
      imageSamples ? Bvh::nodeCostFor(boundedCount, *imageSamples)
                   : Bvh::nodeCostFor(boundedCount));
  {
    std::vector<std::uint32_t> byPlace = scene.bvh_.takeOrder();
    for (std::uint32_t& item : byPlace) item = order[planeCount + item];
    std::copy(byPlace.begin(), byPlace.end(), order.begin() + planeCount);
  }
  stageSeconds_.bvh = secondsSince(start);
  start = std::chrono::steady_clock::now();
  // Step 2: the records laid out so, in place.
  permute(order);
  stageSeconds_.order = secondsSince(start);
  scene.objects_ = std::move(objects_);
  scene.colours_ = std::move(colours_);
  scene.materials_ = std::move(materials_);
  if (scene.materials_.empty()) scene.materials_.emplace_back();
  scene.materials_.shrink_to_fit();
  materialNumbers_.clear();
  scene.sceneObjects_ = std::move(order);
  scene.bounded_ = ObjectRange{planeCount, boundedCount};
  scene.planes_.resize(planeCount);
  std::iota(scene.planes_.begin(), scene.planes_.end(), 0u);
  scene.planeNormals_.reserve(planeCount);
  for (std::uint32_t p = 0; p < planeCount; ++p) {
    scene.planeNormals_.push_back(
        glm::normalize(scene.objects_[p].normalToWorld(glm::dvec3(0.0, 1.0, 0.0))));
  }
  scene.hasTransparency_ = hasTransparency_;
  scene.materialMaxima_ = materialMaxima_;
  scene.lights_.reserve(header.lights.size());
  for (const scene::Light& light : header.lights) {
    scene.lights_.push_back(RenderLight{light.position(), light.colour});
  }
  // Step 3: a grid per light, for its shadow rays (docs/TRACING.md,
  // "Direction grids"); not for a scene of planes alone, which has nothing
  // to list.
  if (lightGrids && boundedCount >= RenderScene::kMinLightGridObjects) {
    start = std::chrono::steady_clock::now();
    scene.buildLightGrids(threads_);
    stageSeconds_.grids = secondsSince(start);
  }
  return scene;
}

}  // namespace render
