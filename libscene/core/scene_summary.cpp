#include "scenefile/scene_summary.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <tuple>
#include <vector>

namespace scene {

namespace {

// How far the unit shape reaches from its centre along the world axis whose
// row of the linear part is `a`: the largest a . p over the shape's points p.
double reach(ObjectKind kind, const glm::dvec3& a) {
  switch (kind) {
    case ObjectKind::Sphere:
      return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
    case ObjectKind::Cube:
      return std::abs(a.x) + std::abs(a.y) + std::abs(a.z);
    case ObjectKind::Cylinder:
      // A disc of radius 1 in x-z at each y in [-1, 1].
      return std::abs(a.y) + std::hypot(a.x, a.z);
    case ObjectKind::Plane:
      break;
  }
  return 0.0;
}

bool finite(const Bounds& b) {
  for (int k = 0; k < 3; ++k) {
    if (!std::isfinite(b.low[k]) || !std::isfinite(b.high[k])) return false;
  }
  return true;
}

// The values of a material in one order, to sort and compare them.
auto materialKey(const Material& m) {
  return std::make_tuple(m.colour.r, m.colour.g, m.colour.b, m.ambient, m.diffuse, m.specular,
                         m.shininess, m.reflectivity, m.transparency, m.ri);
}

std::size_t distinctMaterials(const std::vector<Object>& objects) {
  // Pointers sorted, not copies: a scene may hold millions of objects.
  std::vector<const Material*> all;
  all.reserve(objects.size());
  for (const Object& object : objects) all.push_back(&object.material);
  std::sort(all.begin(), all.end(),
            [](const Material* a, const Material* b) { return materialKey(*a) < materialKey(*b); });
  auto same = [](const Material* a, const Material* b) { return *a == *b; };
  return static_cast<std::size_t>(std::unique(all.begin(), all.end(), same) - all.begin());
}

}  // namespace

std::optional<Bounds> objectBounds(ObjectKind kind, const glm::dmat4& matrix) {
  if (kind == ObjectKind::Plane) return std::nullopt;
  Bounds b;
  for (int axis = 0; axis < 3; ++axis) {
    double r = reach(kind, {matrix[0][axis], matrix[1][axis], matrix[2][axis]});
    b.low[axis] = matrix[3][axis] - r;
    b.high[axis] = matrix[3][axis] + r;
  }
  return b;
}

SceneSummary summarizeScene(const Scene& scene) {
  SceneSummary summary;
  summary.lights = scene.lights.size();
  for (const Object& object : scene.objects) {
    ++summary.objects[static_cast<std::size_t>(object.kind)];
    std::optional<Bounds> b = objectBounds(object.kind, object.matrix);
    if (!b || !finite(*b)) {
      ++summary.unbounded;
    } else if (!summary.bounds) {
      summary.bounds = b;
    } else {
      summary.bounds->low = glm::min(summary.bounds->low, b->low);
      summary.bounds->high = glm::max(summary.bounds->high, b->high);
    }
  }
  summary.materials = distinctMaterials(scene.objects);
  return summary;
}

}  // namespace scene
