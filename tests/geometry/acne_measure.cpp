#include "tests/geometry/acne_measure.h"

#include <cstdio>
#include <string>

#include "renderer/render.h"
#include "renderer/render_scene.h"

namespace acne {

Measurement measureRenderer(const Layout& layout, render::RenderDevice device,
                            std::vector<float>* rendered) {
  scene::Scene s = buildScene(layout);
  render::RenderSettings settings;
  settings.width = kWidth;
  settings.height = kHeight;
  settings.verticalFovDegrees = kFovDegrees;
  settings.samplesPerPixel = 1;
  settings.device = device;
  render::RenderScene renderScene(s);
  render::Image image = render::renderImage(renderScene, settings);
  if (rendered) *rendered = image.rgb;
  std::vector<std::int32_t> ids = render::renderObjectIds(renderScene, settings);

  std::vector<PixelTruth> truth = referencePixels(s, sceneSize(layout));
  Measurement m;
  m.layout = layout;
  m.pixels = static_cast<int>(truth.size());
  // Float storage: a channel at ambient level is within a few float
  // roundings of it.
  m.counts = evaluate(truth, image.rgb, 1e-5, 0.0);
  for (std::size_t k = 0; k < truth.size(); ++k) {
    if (objectByColour(s, &image.rgb[3 * k], 0.0) != truth[k].object) {
      ++m.colourDisagree;
      if (!truth[k].nearSilhouette) ++m.colourDisagreeOffEdge;
    }
    if (ids[k] == truth[k].object) continue;
    ++m.disagree;
    if (!truth[k].nearSilhouette) ++m.disagreeOffEdge;
  }
  return m;
}

std::string fraction(int part, int whole) {
  if (part == 0) return "0/" + std::to_string(whole);
  char text[64];
  std::snprintf(text, sizeof text, "%d/%d (%.1f%%)", part, whole, 100.0 * part / whole);
  return text;
}

}  // namespace acne
