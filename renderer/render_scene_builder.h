// Compiles a scene's objects into a RenderScene batch by batch, as a reader
// hands them over, so that no whole list of scene::Object need be held.
#pragma once

#include <span>
#include <vector>

#include "renderer/render_scene.h"
#include "scenefile/scene.h"

namespace render {

class RenderSceneBuilder {
 public:
  /// `threads` threads make the records and the BVH (0: every core); the
  /// scene is the same whatever their number.
  explicit RenderSceneBuilder(int threads = 0);

  /// Compiles `objects` into render records at once; they may be destroyed
  /// after the call. Objects are numbered in the order they are added
  /// (RenderScene::sceneObject).
  void add(std::span<const scene::Object> objects);

  /// The finished scene: the BVH and the light grids over every object
  /// added; `header` gives the camera and the lights (its objects are
  /// ignored). Frees every build temporary before it returns.
  RenderScene finish(const scene::Scene& header, bool lightGrids = true) &&;

 private:
  int threads_;
  std::vector<scene::Object> objects_;
};

}  // namespace render
