// The values of POV-Ray's expressions that the importer evaluates: floats,
// vectors of 2 to 5 components, and colours (red, green, blue, filter,
// transmit), with POV-Ray's promotions between them.
#pragma once

#include <array>
#include <glm/vec3.hpp>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace scene {

// A degree in radians: POV-Ray writes angles in degrees.
inline constexpr double kPovDegree = std::numbers::pi / 180.0;

struct PovValue {
  enum class Type { Float, Vector, Colour };
  Type type = Type::Float;
  int size = 1;  // components in use: 1 for a float, 2..5 for a vector, 5 for a colour
  std::array<double, 5> v{};

  static PovValue number(double x);
  static PovValue vector(std::span<const double> components);
  static PovValue vector(const glm::dvec3& xyz);
  static PovValue colour(double r, double g, double b, double f = 0.0, double t = 0.0);

  bool isFloat() const { return type == Type::Float; }
  // A float stands for a vector of equal components, a 2-vector gets z = 0.
  glm::dvec3 toVector() const;
  // A float sets every component, filter and transmit included (POV-Ray's
  // rule); a vector of 3, 4 or 5 reads as rgb, rgbf or rgbft.
  PovValue toColour() const;
  // What the type is called in a message: "a float", "a vector", "a colour".
  std::string_view typeName() const;
};

enum class PovOperator { Add, Subtract, Multiply, Divide };

// a op b with POV-Ray's promotions: a float with a vector or a colour acts on
// each component; two vectors of different sizes meet at the larger size;
// a vector with a colour gives a colour.
PovValue applyOperator(const PovValue& a, const PovValue& b, PovOperator op);

// A component by POV-Ray's dot name (x, y, z, t, u, v, red, green, blue,
// filter, transmit, gray), or nothing when the value has no such part.
std::optional<double> povComponent(const PovValue& value, std::string_view name);

// The built-in functions of POV-Ray's float and vector expressions that the
// importer evaluates (sin, sqrt, vlength, vcross, ...). Nothing when `name`
// is none of them; otherwise the value or, in `error`, why the arguments do
// not fit.
bool isPovFunction(std::string_view name);
std::optional<PovValue> callPovFunction(std::string_view name, std::span<const PovValue> args,
                                        std::string& error);

// POV-Ray's srgb colours: the sRGB transfer curve undone.
double povSrgbToLinear(double channel);

}  // namespace scene
