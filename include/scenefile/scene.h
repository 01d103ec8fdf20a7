/// @file
/// The scene model: exactly what a scene file or an instruction file carries.
///
/// Equality compares values, not origins: source spans are ignored by the
/// operator== of every type here, so a scene equals itself read back from
/// another file.
///
/// Matrices are glm::dmat4, which GLM stores column by column: `m[c][r]` is the
/// entry in row r, column c. Every matrix maps local space to world space with
/// column vectors (p_world = M * p_local), so the translation is `m[3]`. The
/// file formats write the same matrix row by row; the readers and writers are
/// the only places that convert between the two orders.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "scenefile/diagnostic.h"

namespace scene {

/// The four primitives of FORMATS.md, each in its local space
/// (scenefile/object_kinds.def lists them).
enum class ObjectKind : std::uint8_t {
#define SCENEFILE_OBJECT_KIND(enumerator, record, pov) enumerator,
#include "scenefile/object_kinds.def"
#undef SCENEFILE_OBJECT_KIND
};

/// Every ObjectKind, in the order of scenefile/object_kinds.def.
inline constexpr ObjectKind kObjectKinds[] = {
#define SCENEFILE_OBJECT_KIND(enumerator, record, pov) ObjectKind::enumerator,
#include "scenefile/object_kinds.def"
#undef SCENEFILE_OBJECT_KIND
};

/// The record name as both formats spell it: "PLANE", "SPHERE", ...
std::string_view objectKindName(ObjectKind kind);
/// The kind whose record name is exactly `name`, if any.
std::optional<ObjectKind> objectKindFromName(std::string_view name);
/// The record names as a message offers them: "PLANE, SPHERE, CYLINDER or CUBE".
std::string objectKindChoices();

/// The Phong material of FORMATS.md. Scene files carry only `colour`; the
/// other values then keep these defaults.
struct Material {
  glm::dvec3 colour{1.0, 1.0, 1.0};  ///< red, green, blue; non-negative
  double ambient = 0.1;              ///< AMBIENT, in [0, 1]
  double diffuse = 0.9;              ///< DIFFUSE, in [0, 1]
  double specular = 0.9;             ///< SPECULAR, in [0, 1]
  double shininess = 200.0;          ///< SHININESS, above 0
  double reflectivity = 0.0;         ///< REFLECTIVITY, in [0, 1]
  double transparency = 0.0;         ///< TRANSPARENCY, in [0, 1]
  double ri = 1.0;                   ///< RI, the refractive index, above 0

  friend bool operator==(const Material&, const Material&) = default;
};

/// The properties of a material other than the colour, in the order the
/// instruction writer prints them. Used by the writers and the loss report.
enum class MaterialProperty : std::uint8_t {
  Ambient,
  Diffuse,
  Specular,
  Shininess,
  Reflectivity,
  Transparency,
  Ri
};
/// Every MaterialProperty, in that order.
inline constexpr MaterialProperty kMaterialProperties[] = {
    MaterialProperty::Ambient,      MaterialProperty::Diffuse,      MaterialProperty::Specular,
    MaterialProperty::Shininess,    MaterialProperty::Reflectivity, MaterialProperty::Transparency,
    MaterialProperty::Ri};
std::string_view materialPropertyName(MaterialProperty property);  ///< "AMBIENT", ...
/// The member of `material` that holds `property`.
double& materialValue(Material& material, MaterialProperty property);
/// The value of `property` in `material`.
double materialValue(const Material& material, MaterialProperty property);
/// The value of `property` in a default Material.
double defaultMaterialValue(MaterialProperty property);

/// One operation of an instruction file's TRANSFORMATION section.
enum class TransformKind : std::uint8_t { Scale, Translate, RotateX, RotateY, RotateZ };
std::string_view transformKindName(TransformKind kind);  ///< "SCALE", ...

/// One operation as an instruction file writes it, with its place there.
struct TransformOp {
  TransformKind kind = TransformKind::Translate;
  /// SCALE and TRANSLATE use x, y, z; a rotation uses x alone (radians).
  glm::dvec3 value{0.0};
  SourceSpan span;

  friend bool operator==(const TransformOp& a, const TransformOp& b);
};

/// The camera: where it stands and where it looks.
struct Camera {
  /// Camera to world: the eye is m[3], forward is -m[2], up is m[1].
  glm::dmat4 matrix{1.0};
  /// A scene file's CAMERA carries a colour that nothing uses; kept so that a
  /// scene file converts to itself bit for bit.
  glm::dvec3 colour{0.0};
  /// Set when the camera came from an instruction file: its LOOK_AT point, so
  /// that writing the file again gives back the same numbers. The eye is m[3].
  std::optional<glm::dvec3> lookAt;
  SourceSpan span;

  friend bool operator==(const Camera& a, const Camera& b);
};

/// What the file's camera shows beyond the camera matrix: a POV-Ray or glTF
/// camera's field of view and, where the file gives one, its aspect ratio.
/// Scene files and instruction files hold none; a renderer given no view of
/// its own renders at this one.
struct View {
  /// The vertical field of view in degrees, in [kMinFovDegrees, kMaxFovDegrees]
  /// (validation.h, checkView).
  double verticalFovDegrees = 60.0;
  /// The image's width over its height, where the file says.
  std::optional<double> aspectRatio;
  SourceSpan span;

  friend bool operator==(const View& a, const View& b);
};

/// A point light.
struct Light {
  /// The light sits at m[3]; the rest of the matrix has no meaning but is kept
  /// so that a scene file converts to itself bit for bit.
  glm::dmat4 matrix{1.0};
  glm::dvec3 colour{1.0};  ///< red, green, blue; non-negative
  SourceSpan span;         ///< the record in its file

  /// Where the light is: m[3].
  glm::dvec3 position() const { return glm::dvec3(matrix[3]); }
  friend bool operator==(const Light& a, const Light& b);
};

/// One primitive, placed by its local-to-world matrix.
struct Object {
  ObjectKind kind = ObjectKind::Sphere;  ///< which primitive
  Material material;                     ///< its material
  glm::dmat4 matrix{1.0};                ///< local to world
  /// Set when the object came from an instruction file: its operations, with
  /// `matrix == composeTransform(*transforms)`. Whoever changes `matrix`
  /// resets this, and the instruction writer then decomposes the matrix.
  std::optional<std::vector<TransformOp>> transforms;
  SourceSpan span;

  friend bool operator==(const Object& a, const Object& b);
};

/// A whole scene. Lights and objects each keep the order of their file; the
/// writers put the camera first, then the lights, then the objects.
struct Scene {
  Camera camera;
  std::vector<Light> lights;
  std::vector<Object> objects;
  /// An instruction file's OUTPUT_FILE, exactly as written, with its span.
  std::optional<std::string> outputFile;
  SourceSpan outputFileSpan;
  /// The view of a POV-Ray or glTF camera.
  std::optional<View> view;

  friend bool operator==(const Scene& a, const Scene& b);
};

}  // namespace scene
