#include "tools/sfconvert/conversion_options.h"

#include <algorithm>

#include "scenefile/validation.h"

namespace tools {

scene::ConversionOptions conversionOptionsFor(const SfconvertOptions& o, bool toStdout,
                                              const std::string& bufferFile) {
  scene::ConversionOptions options;
  options.noLoss = o.noLoss;
  options.instructions.approximate = o.approximate;
  if (!toStdout) {
    options.instructions.outputFile = scene::outputFileNameFor(o.output);
  }
  options.gltf.yfovDegrees = o.fov;
  options.gltf.width = o.width;
  options.gltf.height = o.height;
  options.gltf.segments = o.tessellation;
  options.gltf.externalBuffer = bufferFile;
  options.gltf.lights = !o.noLights;
  options.gltf.extras = !o.noExtras;
  options.gltf.lightFalloff = o.lightFalloff == "none" ? scene::GltfLightFalloff::None
                                                       : scene::GltfLightFalloff::InverseSquare;
  options.gltf.generator = std::string("sfconvert ") + SCENEFILE_VERSION;
  options.obj.segments = o.tessellation;
  options.obj.materialLibrary = bufferFile;
  options.pov.verticalFovDegrees = o.fov;
  if (o.width > 0 && o.height > 0) {
    options.pov.width = o.width;
    options.pov.height = o.height;
  } else if (o.width > 0 || o.height > 0) {
    // One side given: the other keeps sfrender's 4:3.
    options.pov.width =
        o.width > 0 ? o.width : std::clamp(o.height * 4 / 3, 1, scene::kMaxImageSide);
    options.pov.height = o.height > 0 ? o.height : std::max(1, o.width * 3 / 4);
  }
  options.pov.flat = o.flat;
  return options;
}

}  // namespace tools
