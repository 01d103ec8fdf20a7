#include "tests/geometry/acne_scene.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "scenefile/transform.h"
#include "tests/geometry/reference_caster.h"

namespace acne {

namespace {

// Shadow segments are also cast to the light moved by this fraction of the
// scene's size along each axis: a pixel whose verdict changes is on a shadow
// outline, where RENDERING.md owes no particular answer.
constexpr double kShadowMargin = 1e-6;
constexpr double kSilhouetteAngle = 1e-6;

scene::Object makeObject(scene::ObjectKind kind, const glm::dvec3& colour, const glm::dmat4& m) {
  scene::Object o;
  o.kind = kind;
  o.material.colour = colour;
  // No highlights: every pixel is then a multiple of its object's colour,
  // which lets acne_report tell objects apart in another renderer's image.
  o.material.specular = 0.0;
  o.matrix = m;
  return o;
}

}  // namespace

std::vector<Layout> layouts() {
  glm::dvec3 far(1e6, 1e6, 1e6);
  return {
      {"1e-6", 1e-6, glm::dvec3(0.0)},
      {"1e-3", 1e-3, glm::dvec3(0.0)},
      {"1", 1.0, glm::dvec3(0.0)},
      {"1e3", 1e3, glm::dvec3(0.0)},
      {"1e6", 1e6, glm::dvec3(0.0)},
      {"1, moved (1e6, 1e6, 1e6)", 1.0, far},
      {"1e-3, moved (1e6, 1e6, 1e6)", 1e-3, far},
  };
}

scene::Scene buildScene(const Layout& layout) {
  // Scale about the origin, then move: the same picture at every layout.
  glm::dmat4 place = glm::translate(glm::dmat4(1.0), layout.offset) *
                     glm::scale(glm::dmat4(1.0), glm::dvec3(layout.scale));
  auto at = [&](const glm::dvec3& p) { return glm::dvec3(place * glm::dvec4(p, 1.0)); };
  glm::dmat4 identity(1.0);
  auto translate = [&](double x, double y, double z) {
    return glm::translate(identity, glm::dvec3(x, y, z));
  };

  scene::Scene s;
  s.camera.matrix = scene::cameraFromLookAt(at({0.8, 4.0, 8.0}), at({0.0, 1.0, 0.0}));
  scene::Light light;
  light.matrix[3] = glm::dvec4(at({-4.0, 9.0, 6.0}), 1.0);
  light.colour = glm::dvec3(1.0);
  s.lights.push_back(light);

  using K = scene::ObjectKind;
  s.objects.push_back(makeObject(K::Plane, {0.6, 0.6, 0.6}, place));
  s.objects.push_back(makeObject(K::Sphere, {0.9, 0.3, 0.3}, place * translate(-3.0, 1.0, 0.0)));
  s.objects.push_back(makeObject(
      K::Cube, {0.3, 0.9, 0.3},
      place * translate(0.0, 1.0, 0.0) * glm::rotate(identity, 0.6, glm::dvec3(0, 1, 0))));
  s.objects.push_back(makeObject(K::Cylinder, {0.3, 0.3, 0.9}, place * translate(3.0, 1.0, 0.0)));
  s.objects.push_back(makeObject(K::Cylinder, {0.9, 0.9, 0.3},
                                 place * translate(-1.3, 4.3, 2.0) *
                                     glm::rotate(identity, 1.1, glm::dvec3(0.3, 0.2, 1.0)) *
                                     glm::scale(identity, glm::dvec3(0.5, 1.2, 0.5))));
  return s;
}

std::vector<PixelTruth> referencePixels(const scene::Scene& s, double sceneSize) {
  geomref::Scene reference(s);
  geomref::Camera camera(s.camera, kWidth, kHeight, kFovDegrees);
  geomref::Vec3 light = reference.lights().at(0);
  glm::dvec3 lightColour = s.lights[0].colour;

  std::vector<PixelTruth> pixels(static_cast<std::size_t>(kWidth) * kHeight);
  for (int j = 0; j < kHeight; ++j) {
    for (int i = 0; i < kWidth; ++i) {
      PixelTruth& p = pixels[static_cast<std::size_t>(j) * kWidth + i];
      geomref::Ray ray = camera.rayThrough(i + geomref::Real(0.5), j + geomref::Real(0.5));
      std::optional<geomref::Hit> hit = reference.closestHit(ray);
      if (!hit) continue;
      p.object = hit->object;
      p.nearSilhouette = geomref::nearSilhouette(reference, camera, i, j, kSilhouetteAngle);
      geomref::Vec3 n = hit->normal;
      if (geomref::dot(n, ray.direction) > 0) n = -n;
      p.cosine = static_cast<double>(geomref::dot(geomref::normalize(light - hit->point), n));

      int blocked = 0;
      int segments = 0;
      for (int k = -1; k < 6; ++k) {
        geomref::Vec3 target = light;
        if (k >= 0) target[k / 2] += (k % 2 == 0 ? 1 : -1) * kShadowMargin * sceneSize;
        ++segments;
        if (reference.segmentBlocked(hit->point, target, hit->object)) ++blocked;
      }
      p.clearPath = blocked == 0;
      p.blockedPath = blocked == segments;

      const scene::Material& m = s.objects[hit->object].material;
      p.ambient = m.colour * lightColour * m.ambient;
      p.lit = m.colour * lightColour * (m.ambient + m.diffuse * std::max(0.0, p.cosine));
    }
  }
  return pixels;
}

Counts evaluate(const std::vector<PixelTruth>& truth, const std::vector<float>& rgb,
                double relative, double absolute) {
  // The diffuse floor allows for the renderer's own hit point and normal,
  // which differ from the reference's by rounding.
  constexpr double kFloorTolerance = 1e-3;
  Counts counts;
  for (std::size_t k = 0; k < truth.size(); ++k) {
    const PixelTruth& p = truth[k];
    bool finite = true;
    bool atAmbient = true;
    bool underLit = false;
    bool black = true;
    for (int c = 0; c < 3; ++c) {
      double v = rgb[3 * k + c];
      finite = finite && std::isfinite(v);
      atAmbient = atAmbient && v <= p.ambient[c] * (1.0 + relative) + absolute;
      black = black && v <= absolute;
      underLit = underLit || v < p.lit[c] * (1.0 - kFloorTolerance) - absolute;
    }
    if (!finite) ++counts.nonFinite;
    if (p.object < 0) continue;
    if (p.mustBeLit()) {
      ++counts.lit[p.object];
      if (atAmbient || !finite) ++counts.darkLit[p.object];
      if (black) ++counts.blackLit[p.object];
      if (underLit || !finite) ++counts.underLit[p.object];
    }
    if (p.mustBeDark()) {
      ++counts.shadowed[p.object];
      if (!atAmbient) ++counts.leaks[p.object];
    }
  }
  return counts;
}

std::int32_t objectByColour(const scene::Scene& s, const float* rgb, double black) {
  glm::dvec3 p(rgb[0], rgb[1], rgb[2]);
  if (std::max({p.x, p.y, p.z}) <= black) return -1;
  std::int32_t best = -1;
  double bestCosine = -1.0;
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    double cosine = glm::dot(glm::normalize(p), glm::normalize(s.objects[i].material.colour));
    if (cosine > bestCosine) {
      bestCosine = cosine;
      best = static_cast<std::int32_t>(i);
    }
  }
  return best;
}

}  // namespace acne
