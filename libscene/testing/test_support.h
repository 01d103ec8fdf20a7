// Helpers shared by the unit tests: finding diagnostics by code and place.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "scenefile/convert.h"
#include "scenefile/diagnostic.h"
#include "scenefile/scene.h"
#include "scenefile/transform.h"

namespace scene::testing {

// Seconds of wall time since `start`, for the tests that bound a read's time.
inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The bytes of a file, for a test that reads one of the repository's.
inline std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A file of `text` named `name` in the tests' temporary folder: its path.
inline std::filesystem::path writeTempFile(const std::string& name, const std::string& text) {
  std::filesystem::path path = std::filesystem::path(::testing::TempDir()) / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// Every diagnostic of `list` with `code`.
inline std::vector<Diagnostic> withCode(const DiagnosticList& list, DiagnosticCode code) {
  std::vector<Diagnostic> out;
  for (const Diagnostic& d : list.items()) {
    if (d.code == code) out.push_back(d);
  }
  return out;
}

// Asserts that `list` holds exactly one diagnostic with `code`, at line and
// column, with the given severity, and returns it.
inline Diagnostic expectOne(const DiagnosticList& list, DiagnosticCode code, std::uint32_t line,
                            std::uint32_t column, Severity severity = Severity::Error) {
  std::vector<Diagnostic> found = withCode(list, code);
  std::string all;
  for (const Diagnostic& d : list.items()) {
    all += std::to_string(d.span.line) + ":" + std::to_string(d.span.column) + " [" +
           std::string(codeName(d.code)) + "] " + d.message + "\n";
  }
  EXPECT_EQ(found.size(), 1u) << "code " << codeName(code) << " in:\n" << all;
  if (found.empty()) return {};
  EXPECT_EQ(found[0].span.line, line) << all;
  EXPECT_EQ(found[0].span.column, column) << all;
  EXPECT_EQ(found[0].severity, severity) << all;
  return found[0];
}

// A valid scene file's first record, to prefix records under test.
inline const std::string kCameraRecord = "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 5\n0 0 0 1\n";
inline const std::string kLightRecord = "LIGHT\n1 1 1\n1 0 0 3\n0 1 0 3\n0 0 1 3\n0 0 0 1\n";

// A camera, one light and a red sphere whose translation holds -0 and
// 1e-300: numbers a writer must keep exactly.
inline Scene smallScene() {
  Scene s;
  s.camera.matrix = cameraFromLookAt({0, 0, 5}, {0, 0, 0});
  Light light;
  light.matrix[3] = glm::dvec4(3, 3, 3, 1);
  light.colour = glm::dvec3(1, 0.5, 0.25);
  s.lights.push_back(light);
  Object sphere;
  sphere.kind = ObjectKind::Sphere;
  sphere.material.colour = glm::dvec3(1, 0, 0);
  sphere.matrix[3] = glm::dvec4(0.1, -0.0, 1e-300, 1);
  s.objects.push_back(sphere);
  return s;
}

// Conversion options with one format's settings, or with noLoss.
inline ConversionOptions conversionWith(const GltfWriteOptions& gltf) {
  ConversionOptions options;
  options.gltf = gltf;
  return options;
}
inline ConversionOptions conversionWith(const PovWriteOptions& pov) {
  ConversionOptions options;
  options.pov = pov;
  return options;
}
inline ConversionOptions noLossConversion() {
  ConversionOptions options;
  options.noLoss = true;
  return options;
}

}  // namespace scene::testing
