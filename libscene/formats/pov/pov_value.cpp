#include "libscene/formats/pov/pov_value.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace scene {

namespace {

// POV-Ray's vrotate: about x, then y, then z, in degrees (rotate's matrices).
glm::dvec3 rotateDegrees(const glm::dvec3& p, const glm::dvec3& angles) {
  glm::dvec3 r = p;
  double c = std::cos(angles.x * kPovDegree), s = std::sin(angles.x * kPovDegree);
  r = {r.x, c * r.y - s * r.z, s * r.y + c * r.z};
  c = std::cos(angles.y * kPovDegree), s = std::sin(angles.y * kPovDegree);
  r = {c * r.x + s * r.z, r.y, -s * r.x + c * r.z};
  c = std::cos(angles.z * kPovDegree), s = std::sin(angles.z * kPovDegree);
  r = {c * r.x - s * r.y, s * r.x + c * r.y, r.z};
  return r;
}

// Rodrigues' rotation of p about `axis` by `degrees`.
glm::dvec3 rotateAbout(const glm::dvec3& p, const glm::dvec3& axis, double degrees) {
  glm::dvec3 k = glm::normalize(axis);
  double c = std::cos(degrees * kPovDegree), s = std::sin(degrees * kPovDegree);
  return p * c + glm::cross(k, p) * s + k * glm::dot(k, p) * (1.0 - c);
}

struct FloatFunction {
  std::string_view name;
  double (*f)(double);
};

double degrees(double x) {
  return x / kPovDegree;
}
double radians(double x) {
  return x * kPovDegree;
}
double truncate(double x) {
  return std::trunc(x);
}
double lnOf(double x) {
  return std::log(x);
}
double log10Of(double x) {
  return std::log10(x);
}

constexpr FloatFunction kUnary[] = {
    {"abs", [](double x) { return std::abs(x); }},
    {"acos", [](double x) { return std::acos(x); }},
    {"acosh", [](double x) { return std::acosh(x); }},
    {"asin", [](double x) { return std::asin(x); }},
    {"asinh", [](double x) { return std::asinh(x); }},
    {"atan", [](double x) { return std::atan(x); }},
    {"atanh", [](double x) { return std::atanh(x); }},
    {"ceil", [](double x) { return std::ceil(x); }},
    {"cos", [](double x) { return std::cos(x); }},
    {"cosh", [](double x) { return std::cosh(x); }},
    {"degrees", degrees},
    {"exp", [](double x) { return std::exp(x); }},
    {"floor", [](double x) { return std::floor(x); }},
    {"int", truncate},
    {"ln", lnOf},
    {"log", log10Of},
    {"radians", radians},
    {"sin", [](double x) { return std::sin(x); }},
    {"sinh", [](double x) { return std::sinh(x); }},
    {"sqrt", [](double x) { return std::sqrt(x); }},
    {"tan", [](double x) { return std::tan(x); }},
    {"tanh", [](double x) { return std::tanh(x); }},
};

// clang-format off
constexpr std::string_view kOthers[] = {
    "atan2", "div", "max", "min", "mod", "pow", "select", "vaxis_rotate", "vcross", "vdot",
    "vlength", "vnormalize", "vrotate",
};
// clang-format on

bool needFloats(std::span<const PovValue> args, std::size_t count, std::string_view name,
                std::string& error) {
  if (args.size() != count) {
    error = std::string(name) + " takes " + std::to_string(count) + " argument" +
            (count == 1 ? "" : "s");
    return false;
  }
  for (const PovValue& a : args) {
    if (!a.isFloat()) {
      error = std::string(name) + " takes floats, not " + std::string(a.typeName());
      return false;
    }
  }
  return true;
}

}  // namespace

PovValue PovValue::number(double x) {
  PovValue value;
  value.v[0] = x;
  return value;
}

PovValue PovValue::vector(std::span<const double> components) {
  PovValue value;
  value.type = Type::Vector;
  value.size = static_cast<int>(std::min<std::size_t>(components.size(), 5));
  for (int i = 0; i < value.size; ++i) value.v[i] = components[i];
  return value;
}

PovValue PovValue::vector(const glm::dvec3& xyz) {
  double c[3] = {xyz.x, xyz.y, xyz.z};
  return vector(c);
}

PovValue PovValue::colour(double r, double g, double b, double f, double t) {
  PovValue value;
  value.type = Type::Colour;
  value.size = 5;
  value.v = {r, g, b, f, t};
  return value;
}

glm::dvec3 PovValue::toVector() const {
  if (type == Type::Float) return glm::dvec3(v[0]);
  return {v[0], v[1], size >= 3 || type == Type::Colour ? v[2] : 0.0};
}

PovValue PovValue::toColour() const {
  switch (type) {
    case Type::Float:
      return colour(v[0], v[0], v[0], v[0], v[0]);
    case Type::Vector:
      return colour(v[0], v[1], size >= 3 ? v[2] : 0.0, size >= 4 ? v[3] : 0.0,
                    size >= 5 ? v[4] : 0.0);
    case Type::Colour:
      break;
  }
  return *this;
}

std::string_view PovValue::typeName() const {
  switch (type) {
    case Type::Float:
      return "a float";
    case Type::Vector:
      return "a vector";
    case Type::Colour:
      break;
  }
  return "a colour";
}

PovValue applyOperator(const PovValue& a, const PovValue& b, PovOperator op) {
  auto apply = [op](double x, double y) {
    switch (op) {
      case PovOperator::Add:
        return x + y;
      case PovOperator::Subtract:
        return x - y;
      case PovOperator::Multiply:
        return x * y;
      case PovOperator::Divide:
        break;
    }
    return x / y;
  };
  if (a.isFloat() && b.isFloat()) return PovValue::number(apply(a.v[0], b.v[0]));
  PovValue result;
  if (a.type == PovValue::Type::Colour || b.type == PovValue::Type::Colour) {
    result.type = PovValue::Type::Colour;
    result.size = 5;
  } else {
    result.type = PovValue::Type::Vector;
    result.size = std::max(a.isFloat() ? 0 : a.size, b.isFloat() ? 0 : b.size);
  }
  for (int i = 0; i < result.size; ++i) {
    double x = a.isFloat() ? a.v[0] : (i < a.size ? a.v[i] : 0.0);
    double y = b.isFloat() ? b.v[0] : (i < b.size ? b.v[i] : 0.0);
    result.v[i] = apply(x, y);
  }
  return result;
}

std::optional<double> povComponent(const PovValue& value, std::string_view name) {
  if (value.isFloat()) return std::nullopt;
  static constexpr std::string_view kVectorNames[] = {"x", "y", "z", "t"};
  static constexpr std::string_view kColourNames[] = {"red", "green", "blue", "filter", "transmit"};
  for (int i = 0; i < 4; ++i) {
    if (name == kVectorNames[i] && i < value.size) return value.v[i];
  }
  if (name == "u" && value.size >= 1) return value.v[0];
  if (name == "v" && value.size >= 2) return value.v[1];
  for (int i = 0; i < 5; ++i) {
    if (name == kColourNames[i] && i < value.size) return value.v[i];
  }
  if (name == "gray" || name == "grey") {
    return 0.297 * value.v[0] + 0.589 * value.v[1] + 0.114 * value.v[2];
  }
  return std::nullopt;
}

bool isPovFunction(std::string_view name) {
  for (const FloatFunction& f : kUnary) {
    if (f.name == name) return true;
  }
  return std::find(std::begin(kOthers), std::end(kOthers), name) != std::end(kOthers);
}

std::optional<PovValue> callPovFunction(std::string_view name, std::span<const PovValue> args,
                                        std::string& error) {
  for (const FloatFunction& f : kUnary) {
    if (f.name != name) continue;
    if (!needFloats(args, 1, name, error)) return std::nullopt;
    return PovValue::number(f.f(args[0].v[0]));
  }
  if (name == "atan2" || name == "pow" || name == "mod" || name == "div") {
    if (!needFloats(args, 2, name, error)) return std::nullopt;
    double x = args[0].v[0], y = args[1].v[0];
    if (name == "atan2") return PovValue::number(std::atan2(x, y));
    if (name == "pow") return PovValue::number(std::pow(x, y));
    if (name == "mod") return PovValue::number(std::fmod(x, y));
    return PovValue::number(std::trunc(x / y));
  }
  if (name == "max" || name == "min") {
    if (args.empty()) {
      error = std::string(name) + " takes at least one argument";
      return std::nullopt;
    }
    if (!needFloats(args, args.size(), name, error)) return std::nullopt;
    double r = args[0].v[0];
    for (const PovValue& a : args) r = name == "max" ? std::max(r, a.v[0]) : std::min(r, a.v[0]);
    return PovValue::number(r);
  }
  if (name == "select") {
    if (args.size() != 3 && args.size() != 4) {
      error = "select takes 3 or 4 arguments";
      return std::nullopt;
    }
    if (!args[0].isFloat()) {
      error = "select's first argument is a float";
      return std::nullopt;
    }
    double x = args[0].v[0];
    if (args.size() == 3) return x < 0 ? args[1] : args[2];
    return x < 0 ? args[1] : (x == 0 ? args[2] : args[3]);
  }
  // The vector functions take vectors (a float stands for <f, f, f>).
  if (name == "vlength" || name == "vnormalize") {
    if (args.size() != 1) {
      error = std::string(name) + " takes 1 argument";
      return std::nullopt;
    }
    glm::dvec3 a = args[0].toVector();
    if (name == "vlength") return PovValue::number(glm::length(a));
    double length = glm::length(a);
    return PovValue::vector(length > 0.0 ? a / length : glm::dvec3(0.0));
  }
  if (name == "vdot" || name == "vcross" || name == "vrotate") {
    if (args.size() != 2) {
      error = std::string(name) + " takes 2 arguments";
      return std::nullopt;
    }
    glm::dvec3 a = args[0].toVector(), b = args[1].toVector();
    if (name == "vdot") return PovValue::number(glm::dot(a, b));
    if (name == "vcross") return PovValue::vector(glm::cross(a, b));
    return PovValue::vector(rotateDegrees(a, b));
  }
  if (name == "vaxis_rotate") {
    if (args.size() != 3 || !args[2].isFloat()) {
      error = "vaxis_rotate takes a vector, an axis and an angle in degrees";
      return std::nullopt;
    }
    glm::dvec3 axis = args[1].toVector();
    if (glm::length(axis) == 0.0) {
      error = "vaxis_rotate's axis has zero length";
      return std::nullopt;
    }
    return PovValue::vector(rotateAbout(args[0].toVector(), axis, args[2].v[0]));
  }
  error = "unknown function '" + std::string(name) + "'";
  return std::nullopt;
}

double povSrgbToLinear(double channel) {
  return channel <= 0.04045 ? channel / 12.92 : std::pow((channel + 0.055) / 1.055, 2.4);
}

}  // namespace scene
