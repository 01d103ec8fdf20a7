// Prints the acne table of docs/ACCURACY.md: per layout of the acne scene
// and per primitive, the share of lit pixels drawn at ambient level, and
// the geometry agreement with the reference.
//
//   acne_report                 the renderer alone
//   acne_report --povray DIR    also POV-Ray 3.7 on the same scene, written
//                               by hand to DIR/acne_N.pov and rendered with
//                               povray -D +FP -A +W160 +H120 File_Gamma=1.0
//   acne_report --images DIR    also writes the renderer's images (PPM)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <glm/geometric.hpp>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "renderer/render.h"
#include "renderer/render_scene.h"
#include "tests/geometry/acne_measure.h"

namespace {

// World space is right-handed and POV-Ray's left-handed: mirroring z maps
// one onto the other, so every vector and matrix is written with z negated
// (S v, and S M S for a matrix, with S = diag(1, 1, -1)).
std::string povVector(const glm::dvec3& v) {
  char text[128];
  std::snprintf(text, sizeof text, "<%.17g, %.17g, %.17g>", v.x, v.y, -v.z);
  return text;
}

std::string povMatrix(const glm::dmat4& m) {
  // POV-Ray's matrix is 4 rows of 3 under row vectors: the images of x, y, z
  // and the translation, i.e. our columns.
  std::ostringstream out;
  out.precision(17);
  out << "matrix <";
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 3; ++r) {
      double sign = ((c == 2) != (r == 2)) ? -1.0 : 1.0;
      out << sign * m[c][r] << (c == 3 && r == 2 ? ">" : ", ");
    }
  }
  return out.str();
}

std::string povScene(const scene::Scene& s) {
  std::ostringstream out;
  out.precision(17);
  out << "#version 3.7;\n"
      << "global_settings { assumed_gamma 1.0 ambient_light rgb <1, 1, 1> }\n";
  // The camera of RENDERING.md: direction + x right + y up with x, y in
  // [-1/2, 1/2], so right and up span the whole image.
  const glm::dmat4& c = s.camera.matrix;
  glm::dvec3 forward = glm::normalize(-glm::dvec3(c[2]));
  glm::dvec3 up(c[1]);
  up = glm::normalize(up - glm::dot(up, forward) * forward);
  glm::dvec3 right = glm::cross(forward, up);
  double height = 2.0 * std::tan(acne::kFovDegrees * std::acos(-1.0) / 360.0);
  double width = height * acne::kWidth / acne::kHeight;
  out << "camera { perspective location " << povVector(glm::dvec3(c[3])) << " direction "
      << povVector(forward) << " up " << povVector(height * up) << " right "
      << povVector(width * right) << " }\n";
  for (const scene::Light& light : s.lights) {
    out << "light_source { " << povVector(light.position()) << " color rgb <" << light.colour.x
        << ", " << light.colour.y << ", " << light.colour.z << "> }\n";
  }
  for (const scene::Object& o : s.objects) {
    switch (o.kind) {
      case scene::ObjectKind::Plane:
        out << "plane { <0, 1, 0>, 0 ";
        break;
      case scene::ObjectKind::Sphere:
        out << "sphere { <0, 0, 0>, 1 ";
        break;
      case scene::ObjectKind::Cube:
        out << "box { <-1, -1, -1>, <1, 1, 1> ";
        break;
      case scene::ObjectKind::Cylinder:
        out << "cylinder { <0, -1, 0>, <0, 1, 0>, 1 ";
        break;
    }
    const scene::Material& m = o.material;
    out << povMatrix(o.matrix) << " pigment { color rgb <" << m.colour.x << ", " << m.colour.y
        << ", " << m.colour.z << "> } finish { ambient " << m.ambient << " diffuse " << m.diffuse
        << " phong " << m.specular << " phong_size " << m.shininess << " } }\n";
  }
  return out.str();
}

// A binary PPM (P6, maxval 255) as linear values in [0, 1].
std::optional<std::vector<float>> readPpm(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int width = 0, height = 0, maxval = 0;
  auto skipComments = [&] {
    in >> std::ws;
    while (in.peek() == '#') {
      std::string line;
      std::getline(in, line);
      in >> std::ws;
    }
  };
  in >> magic;
  skipComments();
  in >> width;
  skipComments();
  in >> height;
  skipComments();
  in >> maxval;
  in.get();
  if (!in || magic != "P6" || width != acne::kWidth || height != acne::kHeight || maxval != 255) {
    return std::nullopt;
  }
  std::vector<unsigned char> bytes(static_cast<std::size_t>(width) * height * 3);
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!in) return std::nullopt;
  std::vector<float> rgb(bytes.size());
  for (std::size_t i = 0; i < bytes.size(); ++i) rgb[i] = bytes[i] / 255.0f;
  return rgb;
}

void writePpm(const std::string& path, const render::Image& image) {
  std::ofstream out(path, std::ios::binary);
  out << "P6\n" << image.width << " " << image.height << "\n255\n";
  for (float v : image.rgb) {
    double c = std::clamp(static_cast<double>(v), 0.0, 1.0);
    out.put(static_cast<char>(static_cast<int>(std::lround(c * 255.0))));
  }
}

// The cells of one row: per primitive and in all, the lit pixels drawn
// dark; then the shadowed pixels drawn lit.
std::string cells(const acne::Counts& c) {
  std::string row;
  int dark = 0, black = 0, lit = 0, leaks = 0, shadowed = 0;
  for (int p = 0; p < acne::kPrimitives; ++p) {
    row += " | " + acne::fraction(c.darkLit[p], c.lit[p]);
    dark += c.darkLit[p];
    black += c.blackLit[p];
    lit += c.lit[p];
    leaks += c.leaks[p];
    shadowed += c.shadowed[p];
  }
  row += " | " + acne::fraction(dark, lit);
  if (black > 0) row += ", " + std::to_string(black) + " of them black";
  return row + " | " + acne::fraction(leaks, shadowed);
}

}  // namespace

int main(int argc, char** argv) {
  std::string povDir, imageDir;
  for (int i = 1; i + 1 < argc; i += 2) {
    std::string option = argv[i];
    if (option == "--povray") {
      povDir = argv[i + 1];
    } else if (option == "--images") {
      imageDir = argv[i + 1];
    } else {
      std::cerr << "usage: acne_report [--povray DIR] [--images DIR]\n";
      return 2;
    }
  }
  if (argc % 2 == 0) {
    std::cerr << "usage: acne_report [--povray DIR] [--images DIR]\n";
    return 2;
  }

  std::string header = "| scale";
  std::string rule = "|---";
  for (const char* name : acne::kPrimitiveNames) {
    header += std::string(" | ") + name;
    rule += "|---";
  }
  header += " | all | shadowed pixels drawn lit | geometry agreement |\n";
  rule += "|---|---|---|\n";

  // Both tables are printed at the end, one after the other.
  std::ostringstream ours, theirs;
  std::vector<acne::Layout> layouts = acne::layouts();
  for (std::size_t n = 0; n < layouts.size(); ++n) {
    const acne::Layout& layout = layouts[n];
    acne::Measurement m = acne::measureRenderer(layout);
    ours << "| " << layout.label << cells(m.counts) << " | "
         << acne::fraction(m.pixels - m.disagree, m.pixels) << " |\n";

    if (!imageDir.empty()) {
      render::RenderSettings settings;
      settings.width = acne::kWidth;
      settings.height = acne::kHeight;
      settings.verticalFovDegrees = acne::kFovDegrees;
      render::RenderScene renderScene(acne::buildScene(layout));
      writePpm(imageDir + "/sfrender_" + std::to_string(n) + ".ppm",
               render::renderImage(renderScene, settings));
    }
    if (povDir.empty()) continue;
    scene::Scene s = acne::buildScene(layout);
    std::string base = povDir + "/acne_" + std::to_string(n);
    std::ofstream(base + ".pov") << povScene(s);
    std::string command = "povray -D +FP -A +W" + std::to_string(acne::kWidth) + " +H" +
                          std::to_string(acne::kHeight) + " File_Gamma=1.0 +I" + base + ".pov +O" +
                          base + ".ppm >" + base + ".log 2>&1";
    std::optional<std::vector<float>> pov;
    if (std::system(command.c_str()) == 0) pov = readPpm(base + ".ppm");
    if (!pov) {
      theirs << "| " << layout.label << " | failed: see " << base << ".log |\n";
      continue;
    }
    std::vector<acne::PixelTruth> truth = acne::referencePixels(s, acne::sceneSize(layout));
    int agree = 0;
    for (std::size_t k = 0; k < truth.size(); ++k) {
      if (acne::objectByColour(s, &(*pov)[3 * k], 1.5 / 255) == truth[k].object) ++agree;
    }
    // 8-bit storage: a channel at ambient level is within 1.5 levels of it.
    acne::Counts c = acne::evaluate(truth, *pov, 0.0, 1.5 / 255);
    theirs << "| " << layout.label << cells(c) << " | "
           << acne::fraction(agree, static_cast<int>(truth.size())) << " |\n";
  }
  std::cout << "sfrender (render::renderImage and render::renderObjectIds):\n\n"
            << header << rule << ours.str();
  if (!povDir.empty()) {
    std::cout << "\nPOV-Ray (geometry told by colour):\n\n" << header << rule << theirs.str();
  }
  return 0;
}
