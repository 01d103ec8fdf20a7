// How a scene file's LIGHT colour and a KHR_lights_punctual light stand for
// each other (docs/GLTF.md, "Lights"). A scene file's light does not fall off
// and its colour multiplies display values (the specification's
// RENDERING.md); a glTF point light falls off with the square of the
// distance, in candela of linear light. The two are made to agree at a
// reference distance (gltf_reference_point.h) for a reference surface.
#pragma once

#include <glm/vec3.hpp>
#include <limits>
#include <numbers>

namespace scene::gltf {

// The illuminance that a viewer shows as a linear value of 1 on a white
// diffuse surface: Blender's glTF add-on converts with 683 lm/W both ways,
// and Cycles shows a white diffuse surface under E W/m^2 at E / pi.
inline constexpr double kLuxPerUnit = 683.0 * std::numbers::pi;

// The surface at which a scene light and its glTF light are matched: a
// COLOUR (and baseColorFactor) of 0.8, Blender's default base colour and the
// grey of the examples' floors. Matching for white instead leaves every
// darker surface brighter in a PBR viewer than in the renderer, which multiplies
// display values where the viewer multiplies linear ones.
inline constexpr double kReferenceSurface = 0.8;

// The illuminance (lux, per channel) at which a surface of the reference
// colour facing the light shows in a PBR viewer the display value that
// the renderer gives it under a scene light of colour `colour`:
// srgbToLinear(s * c) / s * kLuxPerUnit for each channel c, s the surface.
glm::dvec3 illuminanceFromColour(const glm::dvec3& colour);
// The inverse: the scene light colour that gives that illuminance.
glm::dvec3 colourFromIlluminance(const glm::dvec3& lux);

// A KHR_lights_punctual colour (each channel in [0, 1]) and intensity.
struct PointLight {
  glm::dvec3 color{1.0};
  double intensity = 1.0;
  // The intensity was clamped to the range of a float, where glTF readers
  // hold it (a light of 1e300, a light 1e30 from the reference point).
  bool clamped = false;
};

// Intensities within floats: what any glTF reader can hold.
inline constexpr double kLargestIntensity = std::numeric_limits<float>::max();
inline constexpr double kSmallestIntensity = std::numeric_limits<float>::min();

// The point light that gives illuminanceFromColour(colour) at `distance`
// (above 0): intensity = the largest channel's lux times distance^2, colour
// the channels over the largest. Black is colour 1 1 1, intensity 0.
PointLight pointLightFromColour(const glm::dvec3& colour, double distance);
// The light with its intensity clamped to the floats' range (marked
// `clamped`), where glTF readers hold it.
PointLight withinFloats(PointLight light);
// The scene light colour of a point light matched at `distance` (above 0);
// not finite when the light is too strong for a double there.
glm::dvec3 colourFromPointLight(const PointLight& light, double distance);
// A directional light's colour: its intensity is already lux, and neither
// it nor a far LIGHT falls off.
glm::dvec3 colourFromDirectionalLight(const PointLight& light);

// The mapping of files written before the reference distance (their extras
// hold no "referenceDistance"): intensity = the largest channel, colour the
// channels over it. Only the check of such files' extras uses it.
PointLight unscaledPointLightFromColour(const glm::dvec3& colour);

}  // namespace scene::gltf
