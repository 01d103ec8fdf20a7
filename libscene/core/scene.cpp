#include "scenefile/scene.h"

#include <array>
#include <iterator>

namespace scene {

namespace {
constexpr std::string_view kObjectKindNames[] = {
#define SCENEFILE_OBJECT_KIND(enumerator, record, pov) #record,
#include "scenefile/object_kinds.def"
#undef SCENEFILE_OBJECT_KIND
};
constexpr std::array<std::string_view, 7> kMaterialNames = {
    "AMBIENT", "DIFFUSE", "SPECULAR", "SHININESS", "REFLECTIVITY", "TRANSPARENCY", "RI"};
constexpr std::array<std::string_view, 5> kTransformNames = {"SCALE", "TRANSLATE", "ROTATE_X",
                                                             "ROTATE_Y", "ROTATE_Z"};
}  // namespace

std::string_view objectKindName(ObjectKind kind) {
  return kObjectKindNames[static_cast<std::size_t>(kind)];
}

std::optional<ObjectKind> objectKindFromName(std::string_view name) {
  for (ObjectKind kind : kObjectKinds) {
    if (objectKindName(kind) == name) return kind;
  }
  return std::nullopt;
}

std::string objectKindChoices() {
  std::string text;
  for (std::size_t i = 0; i < std::size(kObjectKinds); ++i) {
    if (i > 0) text += i + 1 == std::size(kObjectKinds) ? " or " : ", ";
    text += objectKindName(kObjectKinds[i]);
  }
  return text;
}

std::string_view materialPropertyName(MaterialProperty property) {
  return kMaterialNames[static_cast<std::size_t>(property)];
}

double& materialValue(Material& material, MaterialProperty property) {
  switch (property) {
    case MaterialProperty::Ambient:
      return material.ambient;
    case MaterialProperty::Diffuse:
      return material.diffuse;
    case MaterialProperty::Specular:
      return material.specular;
    case MaterialProperty::Shininess:
      return material.shininess;
    case MaterialProperty::Reflectivity:
      return material.reflectivity;
    case MaterialProperty::Transparency:
      return material.transparency;
    case MaterialProperty::Ri:
      return material.ri;
  }
  return material.ri;
}

double materialValue(const Material& material, MaterialProperty property) {
  return materialValue(const_cast<Material&>(material), property);
}

double defaultMaterialValue(MaterialProperty property) {
  return materialValue(Material{}, property);
}

std::string_view transformKindName(TransformKind kind) {
  return kTransformNames[static_cast<std::size_t>(kind)];
}

bool operator==(const TransformOp& a, const TransformOp& b) {
  return a.kind == b.kind && a.value == b.value;
}

bool operator==(const Camera& a, const Camera& b) {
  return a.matrix == b.matrix && a.colour == b.colour && a.lookAt == b.lookAt;
}

bool operator==(const View& a, const View& b) {
  return a.verticalFovDegrees == b.verticalFovDegrees && a.aspectRatio == b.aspectRatio;
}

bool operator==(const Light& a, const Light& b) {
  return a.matrix == b.matrix && a.colour == b.colour;
}

bool operator==(const Object& a, const Object& b) {
  return a.kind == b.kind && a.material == b.material && a.matrix == b.matrix &&
         a.transforms == b.transforms;
}

bool operator==(const Scene& a, const Scene& b) {
  return a.camera == b.camera && a.lights == b.lights && a.objects == b.objects &&
         a.outputFile == b.outputFile && a.view == b.view;
}

}  // namespace scene
