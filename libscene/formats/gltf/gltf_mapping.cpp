#include "libscene/formats/gltf/gltf_mapping.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scenefile/matrix.h"
#include "scenefile/srgb.h"
#include "scenefile/transform.h"

namespace scene::gltf {

double roughnessFromShininess(double shininess) {
  return std::pow(2.0 / (shininess + 2.0), 0.25);
}

double shininessFromRoughness(double roughness) {
  double r2 = roughness * roughness;
  double n = r2 > 0.0 ? 2.0 / (r2 * r2) - 2.0 : kMaxShininess;
  if (!std::isfinite(n)) n = kMaxShininess;
  return std::clamp(n, kMinShininess, kMaxShininess);
}

namespace {

// The weight of the mirrored or refracted colour in the base colour. The
// renderer adds REFLECTIVITY times a display value, a PBR viewer multiplies
// linear ones: a mirror's is REFLECTIVITY decoded. TRANSPARENCY is taken as
// it is, which Cycles showed closer on the whole picture (docs/GLTF.md,
// "Materials").
double sharpWeight(const Material& material) {
  if (material.transparency > 0.0) return std::clamp(material.transparency, 0.0, 1.0);
  return srgbToLinear(std::clamp(material.reflectivity, 0.0, 1.0));
}

}  // namespace

PbrMaterial pbrFromMaterial(const Material& material, ObjectKind kind) {
  PbrMaterial pbr;
  // The renderer adds the diffuse colour and the sharp share; glTF blends
  // one base colour between a diffuse and a sharp lobe by a factor f. So
  // base = diffuse + g and f = g / (max(diffuse) + g): f times the base is
  // g, (1 - f) times the base the diffuse colour (of its largest channel).
  double lit = std::clamp(material.ambient + material.diffuse, 0.0, 1.0);
  double g = sharpWeight(material);
  double largest = 0.0;
  for (int i = 0; i < 3; ++i) {
    double diffuse = std::clamp(material.colour[i], 0.0, 1.0) * lit;
    largest = std::max(largest, diffuse);
    pbr.baseColor[i] = std::min(diffuse + g, 1.0);
  }
  pbr.baseColor[3] = 1.0;
  double sharp = largest + g > 0.0 ? g / (largest + g) : 0.0;
  // Glass reflects by its IOR's Fresnel term, as the renderer weighs
  // REFLECTIVITY by Schlick's: it is not metallic.
  pbr.metallic = material.transparency > 0.0 ? 0.0 : sharp;
  if (material.transparency > 0.0) pbr.transmission = sharp;
  // The renderer's reflections and refractions are sharp whatever SHININESS
  // (which shapes the highlight alone).
  pbr.roughness = std::clamp((1.0 - sharp) * roughnessFromShininess(material.shininess), 0.0, 1.0);
  // glTF's default IOR (1.5) gives every dielectric its usual highlight; an
  // IOR is written where the scene says something else or refracts.
  if (material.ri != 1.0 || material.transparency > 0.0) pbr.ior = std::max(material.ri, 1.0);
  if (material.specular != Material{}.specular) pbr.specular = material.specular;
  pbr.doubleSided = kind == ObjectKind::Plane;
  return pbr;
}

Material materialFromPbr(const PbrMaterial& pbr) {
  Material m;
  double metallic = std::clamp(pbr.metallic, 0.0, 1.0);
  double transmission = pbr.transmission ? std::clamp(*pbr.transmission, 0.0, 1.0) : 0.0;
  double sharp = std::max(metallic, transmission);
  double largest = std::max({pbr.baseColor.r, pbr.baseColor.g, pbr.baseColor.b, 0.0});
  double g = sharp * largest;
  for (int i = 0; i < 3; ++i) m.colour[i] = std::max(pbr.baseColor[i] - g, 0.0);
  if (transmission > 0.0) {
    m.transparency = std::min(g, 1.0);
  } else {
    m.reflectivity = linearToSrgb(std::min(g, 1.0));
  }
  if (pbr.ior && *pbr.ior >= 1.0) m.ri = *pbr.ior;
  if (pbr.specular) m.specular = std::clamp(*pbr.specular, 0.0, 1.0);
  double roughness = std::clamp(pbr.roughness, 0.0, 1.0);
  if (sharp < 1.0) roughness = std::min(roughness / (1.0 - sharp), 1.0);
  m.shininess = shininessFromRoughness(roughness);
  return m;
}

glm::dmat4 cameraNodeMatrix(const glm::dmat4& camera) {
  glm::dvec3 right(camera[0]), up(camera[1]), back(camera[2]);
  auto unit = [](const glm::dvec3& v) { return std::abs(glm::length(v) - 1.0) <= 1e-9; };
  bool rigid = unit(right) && unit(up) && unit(back) && std::abs(glm::dot(right, up)) <= 1e-9 &&
               std::abs(glm::dot(up, back)) <= 1e-9 && std::abs(glm::dot(right, back)) <= 1e-9 &&
               glm::determinant(glm::dmat3(camera)) > 0.0;
  if (rigid) return camera;
  // Axes of length 1e-300 or 1e300 are valid: unitDirection scales them.
  back = unitDirection(back);
  if (!isModerate(up)) up = unitDirection(up);
  right = unitDirection(glm::cross(up, back));
  up = glm::cross(back, right);
  return glm::dmat4(glm::dvec4(right, 0.0), glm::dvec4(up, 0.0), glm::dvec4(back, 0.0), camera[3]);
}

glm::dmat4 lightNodeMatrix(const glm::dmat4& light) {
  glm::dmat4 m(1.0);
  m[3] = glm::dvec4(glm::dvec3(light[3]), 1.0);
  return m;
}

bool isTrsMatrix(const glm::dmat4& m) {
  for (int i = 0; i < 3; ++i) {
    for (int j = i + 1; j < 3; ++j) {
      glm::dvec3 a(m[i]), b(m[j]);
      double scale = glm::length(a) * glm::length(b);
      if (!(std::abs(glm::dot(a, b)) <= 1e-9 * scale)) return false;
    }
  }
  return true;
}

glm::dmat4 withinFloatRange(const glm::dmat4& m) {
  constexpr double kLargest = std::numeric_limits<float>::max();
  glm::dmat4 out = m;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) out[c][r] = std::clamp(m[c][r], -kLargest, kLargest);
  }
  return out;
}

std::vector<glm::dmat4> nodeChain(const glm::dmat4& m) {
  glm::dmat3 a(m);
  double largest = 0.0;
  for (int c = 0; c < 3; ++c) {
    largest = std::max(largest, std::abs(a[c][0]) + std::abs(a[c][1]) + std::abs(a[c][2]));
  }
  bool trs = isTrsMatrix(m);
  if (trs && largest <= kLargestSingleNodeColumn) return {m};
  glm::dmat3 u(1.0);
  glm::dvec3 sigma(1.0);
  glm::dmat3 v(1.0);
  if (trs) {
    // The columns' directions and lengths; a mirror flips the last one.
    for (int c = 0; c < 3; ++c) {
      sigma[c] = glm::length(a[c]);
      u[c] = a[c] / sigma[c];
    }
    if (glm::determinant(u) < 0.0) {
      u[2] = -u[2];
      sigma[2] = -sigma[2];
    }
  } else {
    RotationScaleRotation usv = rotationScaleRotation(a);
    u = usv.u;
    sigma = usv.sigma;
    v = usv.v;
  }
  std::vector<glm::dmat4> chain;
  chain.emplace_back(u);
  chain.back()[3] = m[3];
  // A column of floats up to 3.4e38 can be longer than the largest float:
  // the scale is split into one within floats and a uniform power of two
  // (exact, and it commutes), so that no node holds a number that a reader
  // of floats makes infinite.
  constexpr double kLargestFloat = std::numeric_limits<float>::max();
  double power = 1.0;
  while (std::max({std::abs(sigma.x), std::abs(sigma.y), std::abs(sigma.z)}) / power >
         kLargestFloat) {
    power *= 2.0;
  }
  glm::dmat4 scale(1.0);
  for (int i = 0; i < 3; ++i) scale[i][i] = sigma[i] / power;
  chain.push_back(scale);
  if (power > 1.0) chain.emplace_back(glm::dmat3(power));
  if (!trs) chain.emplace_back(glm::transpose(v));
  return chain;
}

double matrixDistance(const glm::dmat4& a, const glm::dmat4& b) {
  double largest = 1.0;
  double distance = 0.0;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      largest = std::max(largest, std::abs(a[c][r]));
      double d = std::abs(a[c][r] - b[c][r]);
      if (std::isnan(d)) return std::numeric_limits<double>::infinity();
      distance = std::max(distance, d);
    }
  }
  return std::isfinite(distance) ? distance / largest : distance;
}

double instanceDistance(const glm::dmat4& a, const glm::dmat4& b) {
  double whole = 0.0;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 3; ++r) whole = std::max(whole, std::abs(a[c][r]));
  }
  double distance = 0.0;
  for (int c = 0; c < 4; ++c) {
    double largest = 0.0;
    double d = 0.0;
    for (int r = 0; r < 3; ++r) {
      largest = std::max(largest, std::abs(a[c][r]));
      d = std::max(d, std::abs(a[c][r] - b[c][r]));
    }
    if (c == 3) largest = whole;
    if (std::isnan(d) || (d > 0.0 && !(largest > 0.0)))
      return std::numeric_limits<double>::infinity();
    if (d > 0.0) distance = std::max(distance, d / largest);
  }
  return distance;
}

}  // namespace scene::gltf
