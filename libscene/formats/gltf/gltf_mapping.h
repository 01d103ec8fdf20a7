// How the scene model maps onto glTF 2.0 and back: the rules that the glTF
// writer and reader share, so that each is the other's inverse
// (docs/GLTF.md gives the reasons).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <optional>
#include <vector>

#include "scenefile/scene.h"

namespace scene::gltf {

// The key under which the exact values ride in `extras`: {"sf": {...}}.
inline constexpr const char* kExtrasKey = "sf";

inline constexpr double kDefaultYfovDegrees = 60.0;
// The near plane of every exported camera; glTF's perspective camera needs
// one, and the far plane is left out (an infinite projection).
inline constexpr double kZnear = 0.01;

// A Phong material in glTF's metallic-roughness model with the
// KHR_materials_ior, _transmission and _specular extensions. Each optional
// is written only when set.
struct PbrMaterial {
  glm::dvec4 baseColor{1.0};
  double metallic = 0.0;
  double roughness = 1.0;
  std::optional<double> ior;
  std::optional<double> transmission;
  std::optional<double> specular;
  bool doubleSided = false;
};

// SHININESS n and roughness r: the Blinn-Phong exponent of a GGX lobe of
// width alpha = r^2 is n = 2 / alpha^2 - 2, so r = (2 / (n + 2))^(1/4).
// Reading back clamps n to [kMinShininess, kMaxShininess].
inline constexpr double kMinShininess = 1.0;
inline constexpr double kMaxShininess = 1e6;
double roughnessFromShininess(double shininess);
double shininessFromRoughness(double roughness);

// The glTF material of a scene material (docs/GLTF.md, "Materials"). The
// renderer adds COLOUR * (AMBIENT + DIFFUSE) and REFLECTIVITY (or
// TRANSPARENCY) times the mirrored (or refracted) colour; glTF blends one
// base colour between a diffuse lobe and a sharp one (metallic, or
// KHR_materials_transmission for a material with TRANSPARENCY), so the base
// colour is the diffuse colour plus the sharp share's weight g (REFLECTIVITY
// decoded from sRGB, TRANSPARENCY as it is), and
// the blend factor is g over the base colour's largest channel. Roughness is
// SHININESS's, scaled down by the sharp lobe's factor, since the renderer's
// reflections and refractions are sharp. Planes are double-sided. Values
// glTF cannot hold are clamped (a colour above 1, RI below 1).
PbrMaterial pbrFromMaterial(const Material& material, ObjectKind kind);
// The inverse for what glTF holds: COLOUR, SHININESS, SPECULAR,
// REFLECTIVITY (metallic), TRANSPARENCY, RI. AMBIENT and DIFFUSE keep their
// defaults, which add up to 1; a metal's tint is lost.
Material materialFromPbr(const PbrMaterial& pbr);

// The matrix of the node that carries a camera: the camera matrix itself
// when it is a rotation and a translation, else the rigid camera that the
// renderer uses (right, up, back orthonormalised from forward and up).
glm::dmat4 cameraNodeMatrix(const glm::dmat4& camera);
// A light's node: its position alone (the rest of a light matrix means
// nothing, and stays in extras).
glm::dmat4 lightNodeMatrix(const glm::dmat4& light);

// Whether a glTF node can hold the matrix as it is: glTF asks for a matrix
// that decomposes into translation, rotation and scale, which is one whose
// 3x3 columns are orthogonal (within 1e-9 of their norms).
bool isTrsMatrix(const glm::dmat4& m);

// Readers check a node's matrix in single precision, to an absolute 5e-5
// (the Khronos validator does): a block whose columns sum above this in
// absolute value is written as a chain instead of one matrix.
inline constexpr double kLargestSingleNodeColumn = 64.0;

// The matrix with every entry clamped to the range of a float (+-3.4e38):
// glTF readers hold node matrices in single precision, and a larger value
// would become infinite there. The exact matrix rides in extras.
glm::dmat4 withinFloatRange(const glm::dmat4& m);

// The matrices of the nodes that stand for `m`, parent first, whose product
// is m (to rounding). One node holds m when it is TRS with moderate columns;
// otherwise the chain is translation and rotation, then a diagonal scale,
// then (only for shear) a rotation: each of which any reader checks exactly.
std::vector<glm::dmat4> nodeChain(const glm::dmat4& m);

// The largest |a - b| over the entries, relative to the largest entry of a
// (at least 1): how the reader tells whether a node still sits where its
// extras say.
double matrixDistance(const glm::dmat4& a, const glm::dmat4& b);

// The largest |a - b| of each axis column relative to that column's largest
// entry in a, and of the translation relative to the largest entry of a:
// how far an instance (EXT_mesh_gpu_instancing, whose translation, rotation
// and scale are floats) lies from the object it stands for, each axis held
// to its own rounding however the axes' lengths differ.
double instanceDistance(const glm::dmat4& a, const glm::dmat4& b);

}  // namespace scene::gltf
