#include "renderer/render_scene_builder.h"

#include <utility>

namespace render {

RenderSceneBuilder::RenderSceneBuilder(int threads) : threads_(threads) {}

void RenderSceneBuilder::add(std::span<const scene::Object> objects) {
  for (const scene::Object& o : objects) {
    scene::Object& copy = objects_.emplace_back();
    copy.kind = o.kind;
    copy.material = o.material;
    copy.matrix = o.matrix;
  }
}

RenderScene RenderSceneBuilder::finish(const scene::Scene& header, bool lightGrids) && {
  scene::Scene scene;
  scene.camera = header.camera;
  scene.lights = header.lights;
  scene.objects = std::move(objects_);
  return RenderScene(scene, threads_, lightGrids);
}

}  // namespace render
