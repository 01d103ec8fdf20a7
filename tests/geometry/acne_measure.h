// One row of the acne table: the acne scene at one layout, drawn by the
// renderer at one sample per pixel and judged by the reference.
#pragma once

#include <string>
#include <vector>

#include "renderer/render.h"
#include "tests/geometry/acne_scene.h"

namespace acne {

struct Measurement {
  Layout layout;
  Counts counts;
  int pixels = 0;
  int disagree = 0;         // object ids that differ from the reference
  int disagreeOffEdge = 0;  // ... away from every silhouette
  // The same for the object the image shows, told by its colour.
  int colourDisagree = 0;
  int colourDisagreeOffEdge = 0;
};

// `device`: where renderImage and renderObjectIds trace (the GPU path runs
// the same checks, tests/geometry/acne_test.cpp). With `image`, the rendered
// colours are kept there.
Measurement measureRenderer(const Layout& layout,
                            render::RenderDevice device = render::RenderDevice::Cpu,
                            std::vector<float>* image = nullptr);

// "3/1234" with a percentage, for the table.
std::string fraction(int part, int whole);

}  // namespace acne
