#include "renderer/default_scene.h"

#include "scenefile/transform.h"

namespace render {

namespace {

scene::Object makeObject(scene::ObjectKind kind, const glm::dvec3& colour,
                         std::vector<scene::TransformOp> ops) {
  scene::Object object;
  object.kind = kind;
  object.material.colour = colour;
  object.matrix = scene::composeTransform(ops);
  object.transforms = std::move(ops);
  return object;
}

scene::TransformOp scale(double x, double y, double z) {
  return {scene::TransformKind::Scale, {x, y, z}, {}};
}
scene::TransformOp translate(double x, double y, double z) {
  return {scene::TransformKind::Translate, {x, y, z}, {}};
}
scene::TransformOp rotateY(double a) {
  return {scene::TransformKind::RotateY, {a, 0, 0}, {}};
}

}  // namespace

scene::Scene defaultScene() {
  scene::Scene s;
  glm::dvec3 eye(0.0, 2.6, 9.0);
  glm::dvec3 target(0.0, 0.9, 0.0);
  s.camera.matrix = scene::cameraFromLookAt(eye, target);
  s.camera.lookAt = target;

  scene::Light key;
  key.matrix[3] = glm::dvec4(5.0, 8.0, 6.0, 1.0);
  key.colour = glm::dvec3(0.8);
  scene::Light fill;
  fill.matrix[3] = glm::dvec4(-6.0, 5.0, 5.0, 1.0);
  fill.colour = glm::dvec3(0.35, 0.35, 0.4);
  s.lights = {key, fill};

  using scene::ObjectKind;
  scene::Object floor = makeObject(ObjectKind::Plane, {0.75, 0.72, 0.65}, {});
  floor.material.specular = 0.1;
  floor.material.reflectivity = 0.1;

  scene::Object mirror = makeObject(ObjectKind::Cube, {0.05, 0.05, 0.05},
                                    {scale(3.2, 1.8, 0.05), translate(0, 1.8, -3.5)});
  mirror.material.reflectivity = 0.9;
  mirror.material.diffuse = 0.2;

  scene::Object glass = makeObject(ObjectKind::Sphere, {0.9, 0.95, 1.0},
                                   {scale(0.9, 0.9, 0.9), translate(0.2, 0.9, 1.8)});
  glass.material.ambient = 0.0;
  glass.material.diffuse = 0.05;
  glass.material.reflectivity = 0.2;
  glass.material.transparency = 0.9;
  glass.material.ri = 1.5;

  scene::Object ball = makeObject(ObjectKind::Sphere, {0.85, 0.15, 0.12},
                                  {scale(0.8, 0.8, 0.8), translate(-2.4, 0.8, 0.0)});
  scene::Object box =
      makeObject(ObjectKind::Cube, {0.15, 0.3, 0.85},
                 {scale(0.65, 0.65, 0.65), rotateY(0.6), translate(2.5, 0.65, -0.2)});
  box.material.shininess = 60.0;
  scene::Object can = makeObject(ObjectKind::Cylinder, {0.2, 0.7, 0.25},
                                 {scale(0.5, 0.75, 0.5), translate(-0.6, 0.75, -1.6)});

  s.objects = {floor, mirror, glass, ball, box, can};
  s.outputFile = "default-scene.png";
  return s;
}

}  // namespace render
