// Compiles a scene's objects into a RenderScene batch by batch, as a reader
// hands them over, so that no whole list of scene::Object need be held: each
// batch becomes records at once, and finish() lays them out in the BVH's
// order in place.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <vector>

#include "renderer/material_maxima.h"
#include "renderer/render_scene.h"
#include "scenefile/scene.h"

namespace render {

class RenderSceneBuilder {
 public:
  /// `threads` threads make the records and the BVH (0: every core); the
  /// scene is the same whatever their number.
  explicit RenderSceneBuilder(int threads = 0);

  /// Room for `objects` objects in all, for a caller that knows the count:
  /// the records are then allocated once rather than grown.
  void reserve(std::uint64_t objects);

  /// Compiles `objects` into render records at once (on the builder's
  /// threads); they may be destroyed after the call. Objects are numbered in
  /// the order they are added (RenderScene::sceneObject). Throws
  /// std::length_error past kMaxObjects in all.
  void add(std::span<const scene::Object> objects);

  /// The finished scene: the BVH and the light grids over every object
  /// added; `header` gives the camera and the lights (its objects are
  /// ignored). `imageSamples`, where known, are the camera samples of the
  /// whole image to be rendered (fullImageSampleCount): few of them for the
  /// objects build a compact BVH (Bvh::nodeCostFor). Frees every build
  /// temporary before it returns.
  RenderScene finish(const scene::Scene& header, bool lightGrids = true,
                     std::optional<std::uint64_t> imageSamples = std::nullopt) &&;

  /// The distinct materials (colour aside) of the objects added.
  std::uint64_t materialCount() const { return materials_.size(); }

  /// The most objects a scene may have: objects are numbered in 32 bits,
  /// RaySource::kNone aside.
  static constexpr std::uint64_t kMaxObjects = 0xFFFFFFFE;

  /// Wall seconds of finish()'s stages, for benchmarks; zero before it.
  struct StageSeconds {
    double bvh = 0;    ///< the BVH's build
    double order = 0;  ///< the records laid out in its order
    double grids = 0;  ///< the lights' grids
  };
  /// finish()'s stage times: the one thing it leaves in the builder.
  const StageSeconds& stageSeconds() const { return stageSeconds_; }

 private:
  // The number of `material`'s properties but its colour in materials_,
  // added there if new.
  std::uint32_t materialNumber(const scene::Material& material);
  // Lays the records out as `order` says (record r becomes the one that
  // was at order[r]), in place.
  void permute(const std::vector<std::uint32_t>& order);

  int threads_;
  // In the order added, until finish() lays them out in the BVH's.
  // Left unset by resize: add() writes every new record and colour.
  UnsetVector<RenderObject> objects_;
  UnsetVector<glm::dvec3> colours_;
  std::uint32_t planes_ = 0;
  // The distinct materials, colour aside (it is zero), and their numbers by
  // their properties' bits; the last one found, which the next object
  // mostly shares.
  std::vector<scene::Material> materials_;
  std::map<std::array<std::uint64_t, 7>, std::uint32_t> materialNumbers_;
  std::uint32_t lastMaterial_ = 0;
  MaterialMaxima materialMaxima_;
  bool hasTransparency_ = false;
  StageSeconds stageSeconds_;
};

}  // namespace render
