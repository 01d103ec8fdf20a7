#include "libscene/formats/gltf/gltf_cameras_lights.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <string>

#include "libscene/core/default_camera.h"
#include "libscene/formats/gltf/gltf_reference_point.h"
#include "libscene/text/number.h"
#include "scenefile/transform.h"
#include "scenefile/validation.h"

namespace scene::gltf {

bool CamerasAndLights::cameraFromExtras(int node, const glm::dmat4& world,
                                        const RecordExtras& extras) {
  const tinygltf::Node& n = c_.model.nodes[node];
  if (n.camera < 0 || haveCamera_ ||
      matrixDistance(withinFloatRange(cameraNodeMatrix(extras.matrix)), world) > kExtrasAgreement) {
    return false;
  }
  haveCamera_ = true;
  c_.scene.camera.matrix = extras.matrix;
  c_.scene.camera.colour = extras.colour;
  c_.scene.camera.lookAt = extras.lookAt;
  reportFov(n.camera);
  if (extras.noView) c_.scene.view.reset();
  return true;
}

bool CamerasAndLights::lightFromExtras(int node, const glm::dmat4& world,
                                       const RecordExtras& extras) {
  int light = nodeLight(c_.model, node);
  if (light < 0 ||
      matrixDistance(withinFloatRange(lightNodeMatrix(extras.matrix)), world) > kExtrasAgreement) {
    return false;
  }
  // Files written before the reference distance hold none, and their
  // intensity is the colour's largest channel.
  PointLight want = extras.referenceDistance
                        ? pointLightFromColour(extras.colour, *extras.referenceDistance)
                        : unscaledPointLightFromColour(extras.colour);
  PointLight have = pointLight(c_.model.lights[light]);
  double d =
      std::max(glm::length(want.color - have.color),
               std::abs(want.intensity - have.intensity) / std::max(1.0, std::abs(want.intensity)));
  if (!(d <= kExtrasAgreement) || c_.model.lights[light].type != "point") return false;
  c_.scene.lights.push_back(Light{extras.matrix, extras.colour, {}});
  return true;
}

void CamerasAndLights::reportFov(int camera) {
  const tinygltf::Camera& c = c_.model.cameras[camera];
  if (c.type != "perspective" || !(c.perspective.yfov > 0.0)) return;
  double degrees = std::round(c.perspective.yfov * 180.0 / std::numbers::pi * 1e6) / 1e6;
  // A View's range (checkView); a yfov from pi is reported with the file's
  // other values (gltf_document.h).
  if (!(degrees >= kMinFovDegrees && degrees <= kMaxFovDegrees)) {
    if (c.perspective.yfov < std::numbers::pi) {
      c_.out.report(c_.loss, DiagnosticCode::GltfIgnored, {},
                    "the camera's vertical field of view of " + formatNumber(c.perspective.yfov) +
                        " radians is outside what the renderer renders (" +
                        formatNumber(kMinFovDegrees) + " to " + formatNumber(kMaxFovDegrees) +
                        " degrees), and is dropped");
    }
    return;
  }
  View& view = c_.scene.view.emplace();
  view.verticalFovDegrees = degrees;
  // The document's check reports every aspect ratio as dropped from a scene
  // file; one out of a View's range is not kept for the renderer either.
  double aspect = c.perspective.aspectRatio;
  if (aspect >= kMinAspectRatio && aspect <= kMaxAspectRatio) view.aspectRatio = aspect;
  Diagnostic& d = c_.out.note(DiagnosticCode::CameraFov, {},
                              "the camera's vertical field of view is " + formatNumber(degrees) +
                                  " degrees, which a scene file cannot hold");
  d.hint = "render with {0}";
  d.remedies = {{Setting::FieldOfView, formatNumber(degrees)}};
}

void CamerasAndLights::addCamera(int node, const glm::dmat4& world) {
  const tinygltf::Camera& camera = c_.model.cameras[c_.model.nodes[node].camera];
  if (haveCamera_) {
    c_.out.report(c_.loss, DiagnosticCode::GltfExtraCamera, {},
                  "camera" + quoted(camera.name) + " on " + nodeLabel(c_.model, node) +
                      " is ignored: a scene file has one CAMERA, the first one found");
    return;
  }
  haveCamera_ = true;
  if (camera.type != "perspective") {
    c_.out.report(c_.loss, DiagnosticCode::GltfIgnored, {},
                  "camera" + quoted(camera.name) + " is " + camera.type +
                      "; it becomes a pinhole camera at the same place");
  }
  glm::dvec3 eye(world[3]);
  glm::dvec3 forward = -glm::dvec3(world[2]);
  glm::dvec3 up(world[1]);
  double fl = glm::length(forward);
  if (fl > 0.0) forward /= fl;
  up -= glm::dot(up, forward) * forward;
  double ul = glm::length(up);
  if (ul > 0.0) up /= ul;
  glm::dvec3 right = glm::cross(forward, up);
  c_.scene.camera.matrix = glm::dmat4(glm::dvec4(right, 0.0), glm::dvec4(up, 0.0),
                                      glm::dvec4(-forward, 0.0), glm::dvec4(eye, 1.0));
  reportFov(c_.model.nodes[node].camera);
}

PointLight CamerasAndLights::pointLight(const tinygltf::Light& light) {
  PointLight out;
  if (light.color.size() == 3) out.color = {light.color[0], light.color[1], light.color[2]};
  out.intensity = light.intensity;
  return out;
}

void CamerasAndLights::addLight(int node, int lightIndex, const glm::dmat4& world) {
  const tinygltf::Light& light = c_.model.lights[lightIndex];
  std::string label = "light" + quoted(light.name) + " on " + nodeLabel(c_.model, node);
  PointLight point = pointLight(light);
  glm::dmat4 m(1.0);
  m[3] = glm::dvec4(glm::dvec3(world[3]), 1.0);
  if (light.type == "directional") {
    // Illuminance, which falls off no more than a scene file's light.
    glm::dvec3 colour = colourFromDirectionalLight(point);
    if (!std::isfinite(colour.x + colour.y + colour.z)) colour = glm::dvec3(0.0);
    glm::dvec3 direction = -glm::dvec3(world[2]);
    pendingDirectional_.push_back({c_.scene.lights.size(), direction});
    c_.out.report(c_.loss, DiagnosticCode::GltfLightApproximated, {},
                  "directional " + label +
                      " becomes a point light far away against its direction: a scene file has "
                      "point lights only");
    c_.scene.lights.push_back(Light{m, colour, {}});
    return;
  }
  if (light.type == "spot") {
    c_.out.report(c_.loss, DiagnosticCode::GltfLightApproximated, {},
                  "spot " + label + " becomes a point light: its cone is dropped");
  } else if (light.type != "point") {
    c_.out.report(
        c_.loss, DiagnosticCode::GltfLightApproximated, {},
        label + " has the unknown type '" + light.type + "'; it is read as a point light");
  }
  pendingPoint_.push_back({c_.scene.lights.size(), point, label});
  c_.scene.lights.push_back(Light{m, glm::dvec3(0.0), {}});
}

void CamerasAndLights::finish() {
  placeDirectionalLights();
  if (!haveCamera_) makeDefaultCamera();
  colourPointLights();
}

void CamerasAndLights::colourPointLights() {
  if (pendingPoint_.empty()) return;
  ReferencePoint reference = referencePoint(c_.scene);
  std::string where = describeReferencePoint(reference);
  for (const PendingPoint& pending : pendingPoint_) {
    Light& light = c_.scene.lights[pending.light];
    double distance = referenceDistance(light.position(), reference);
    glm::dvec3 colour = colourFromPointLight(pending.point, distance);
    if (!std::isfinite(colour.x + colour.y + colour.z)) {
      c_.out.error(DiagnosticCode::ValueNotFinite, {},
                   pending.label + " at its reference distance " + approximateNumber(distance) +
                       " gives a LIGHT colour beyond the largest number");
      continue;
    }
    light.colour = colour;
    c_.out.note(DiagnosticCode::LightFalloff, {},
                pending.label +
                    " falls off with the square of the distance where a scene file's LIGHT does "
                    "not: LIGHT colour " +
                    approximateNumber(colour.x) + " " + approximateNumber(colour.y) + " " +
                    approximateNumber(colour.z) + " matches it at the reference distance " +
                    approximateNumber(distance) + ", from the light to " + where);
  }
}

void CamerasAndLights::placeDirectionalLights() {
  if (pendingDirectional_.empty()) return;
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  auto add = [&](const glm::dvec3& p) {
    if (std::isfinite(p.x + p.y + p.z)) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  };
  for (const Object& o : c_.scene.objects) add(glm::dvec3(o.matrix[3]));
  if (haveCamera_) add(glm::dvec3(c_.scene.camera.matrix[3]));
  glm::dvec3 centre = lo.x <= hi.x ? 0.5 * (lo + hi) : glm::dvec3(0.0);
  double radius = lo.x <= hi.x ? glm::length(hi - lo) : 1.0;
  for (const auto& [light, direction] : pendingDirectional_) {
    double length = glm::length(direction);
    glm::dvec3 d = length > 0.0 ? direction / length : glm::dvec3(0, -1, 0);
    glm::dvec3 position = centre - d * (100.0 * std::max(radius, 1.0));
    if (!std::isfinite(position.x + position.y + position.z)) {
      c_.out.error(DiagnosticCode::ValueNotFinite, {},
                   "a directional light becomes a point light 100 scene sizes away, which is "
                   "not finite for a scene this large");
      continue;
    }
    c_.scene.lights[light].matrix[3] = glm::dvec4(position, 1.0);
  }
}

void CamerasAndLights::makeDefaultCamera() {
  std::optional<glm::dmat4> camera = cameraSeeingObjects(c_.scene.objects);
  if (!camera) {
    c_.out.error(DiagnosticCode::ValueNotFinite, {},
                 "the file has no camera, and one on +Z that sees every object would stand "
                 "beyond the largest number");
    return;
  }
  c_.scene.camera.matrix = *camera;
  c_.out.report(c_.loss, DiagnosticCode::GltfNoCamera, {},
                "the file has no camera: CAMERA looks at the scene from +Z");
}

}  // namespace scene::gltf
